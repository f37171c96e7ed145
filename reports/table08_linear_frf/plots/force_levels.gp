set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'force_levels.svg'
set title 'Response T1.x (full) at each force level'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 'force_levels.dat' using 1:2 with lines title 'Fe = 5 N', \
     'force_levels.dat' using 1:3 with lines title 'Fe = 50 N', \
     'force_levels.dat' using 1:4 with lines title 'Fe = 100 N', \
     'force_levels.dat' using 1:5 with lines title 'Fe = 200 N', \
     'force_levels.dat' using 1:6 with lines title 'Fe = 300 N'
