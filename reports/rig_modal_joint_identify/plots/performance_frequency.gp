set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'performance_frequency.svg'
set title 'Damper performance: resonance frequency against Fe [N]'
set logscale x
set xlabel 'Fe [N]'
set ylabel 'frequency [Hz]'
set grid
set key outside right
set datafile missing 'nan'
plot 'performance_frequency.dat' using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'peak (bladebench)'
