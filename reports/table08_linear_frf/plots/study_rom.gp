set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_rom.svg'
set title 'Reduced model error vs fixed-interface modes'
set logscale y
set format y '10^{%L}'
set xlabel 'fixed-interface modes'
set ylabel 'relative error'
set grid
set key outside right
plot 'study_rom.dat' index 0 using 1:2 with linespoints pt 7 title 'corner: max error, first frequencies', 'study_rom.dat' index 0 using 1:3 with linespoints pt 5 dt 2 title 'corner: FRF peak frequency', \
     'study_rom.dat' index 1 using 1:2 with linespoints pt 7 title 'thesis: max error, first frequencies', 'study_rom.dat' index 1 using 1:3 with linespoints pt 5 dt 2 title 'thesis: FRF peak frequency', \
     'study_rom.dat' index 2 using 1:2 with linespoints pt 7 title 'tips_only: max error, first frequencies', 'study_rom.dat' index 2 using 1:3 with linespoints pt 5 dt 2 title 'tips_only: FRF peak frequency'
