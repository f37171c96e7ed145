set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'performance_frequency.svg'
set title 'Damper performance: resonance frequency against CF / Fe'
set logscale x
set xlabel 'CF / Fe'
set ylabel 'frequency [Hz]'
set grid
set key outside right
set datafile missing 'nan'
plot 'performance_frequency.dat' using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'IP (bladebench)', \
     'performance_frequency.dat' using 1:3 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'IP (reference)', \
     'performance_frequency.dat' using 1:4 with linespoints pt 7 lc rgb '#bf1f1f' title 'OOP (bladebench)', \
     'performance_frequency.dat' using 1:5 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'OOP (reference)'
