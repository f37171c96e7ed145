set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_levels_damper_right.y.svg'
set title 'Response damper_right.y at each force level (first harmonic)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 'frf_levels_damper_right.y.dat' index 0 using 1:2 with lines lc rgb '#1f5fbf' title 'Fe = 0.1 N', \
     'frf_levels_damper_right.y.dat' index 1 using 1:2 with lines lc rgb '#bf1f1f' title 'Fe = 0.5 N', \
     'frf_levels_damper_right.y.dat' index 2 using 1:2 with lines lc rgb '#2f9f2f' title 'Fe = 1 N', \
     'frf_levels_damper_right.y.dat' index 3 using 1:2 with lines lc rgb '#9f2fbf' title 'Fe = 2 N', \
     'frf_levels_damper_right.y.dat' index 4 using 1:2 with lines lc rgb '#bf8f1f' title 'Fe = 3 N', \
     'frf_levels_damper_right.y.dat' index 5 using 1:2 with lines lc rgb '#1f9fbf' title 'Fe = 5 N', \
     'frf_levels_damper_right.y.dat' index 6 using 1:2 with lines lc rgb '#7f7f7f' title 'Fe = 10 N'
