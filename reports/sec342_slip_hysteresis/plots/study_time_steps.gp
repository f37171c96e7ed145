set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_time_steps.svg'
set title 'Time integration: largest FRF amplitude error against the finest variant vs cost'
set logscale xy
set format y '10^{%L}'
set xlabel 'sweep time [s]'
set ylabel 'max |relative amplitude error|'
set grid
set key outside right
plot 'study_time_steps.dat' index 0 using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'steady tolerance 0.001', 'study_time_steps.dat' index 0 using 1:2:(sprintf('%d', $3)) with labels offset 0,1 notitle, \
     'study_time_steps.dat' index 1 using 1:2 with linespoints pt 7 lc rgb '#bf1f1f' title 'steady tolerance 1e-05', 'study_time_steps.dat' index 1 using 1:2:(sprintf('%d', $3)) with labels offset 0,1 notitle
