set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_levels_B.x.svg'
set title 'Response B.x at each force level (first harmonic)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 'frf_levels_B.x.dat' index 0 using 1:2 with lines lc rgb '#1f5fbf' title 'Fe = 2 N', \
     'frf_levels_B.x.dat' index 0 using 1:3 with lines dt 2 lc rgb '#1f5fbf' title 'unstable (Hill)'
