set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_T2.x.svg'
set title 'Response T2.x (amplitude)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
set xrange [170:190]
set arrow from 174.63829348077118,graph 0 to 174.63829348077118,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.64823938904536,graph 0 to 174.64823938904536,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T2.x.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T2.x.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom'
