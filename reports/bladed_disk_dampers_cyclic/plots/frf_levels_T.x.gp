set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_levels_T.x.svg'
set title 'Response T.x at each force level (first harmonic)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 'frf_levels_T.x.dat' index 0 using 1:2 with lines lc rgb '#1f5fbf' title 'Fe = 0.01 N', \
     'frf_levels_T.x.dat' index 1 using 1:2 with lines lc rgb '#bf1f1f' title 'Fe = 0.5 N', \
     'frf_levels_T.x.dat' index 2 using 1:2 with lines lc rgb '#2f9f2f' title 'Fe = 2 N', \
     'frf_levels_T.x.dat' index 3 using 1:2 with lines lc rgb '#9f2fbf' title 'Fe = 8 N'
