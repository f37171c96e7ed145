set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'performance_amplitude.svg'
set title 'Damper performance: resonance amplitude per newton against Fe [N]'
set logscale x
set xlabel 'Fe [N]'
set ylabel 'amplitude / Fe [m/N]'
set grid
set key outside right
set logscale y
set format y '10^{%L}'
set datafile missing 'nan'
plot 'performance_amplitude.dat' using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'peak (bladebench)'
