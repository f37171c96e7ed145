set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_per_newton_A.x.svg'
set title 'Response A.x per newton at each force level, with the linear limits'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude / Fe [m/N]'
set grid
set key outside right
plot , \
     'frf_per_newton_A.x.dat' index 0 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' title 'free (no damper)', \
     'frf_per_newton_A.x.dat' index 0 using 1:3 with lines lw 2 dt 3 lc rgb '#000000' title 'stuck (eq 3.51)'
