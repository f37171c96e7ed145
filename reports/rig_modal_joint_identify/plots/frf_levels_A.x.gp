set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_levels_A.x.svg'
set title 'Response A.x at each force level (first harmonic)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 
