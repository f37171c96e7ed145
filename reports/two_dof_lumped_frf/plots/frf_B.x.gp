set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_B.x.svg'
set title 'Response B.x (amplitude)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
set xrange [100:400]
plot 'frf_B.x.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'inline', \
     'frf_B.x.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'inline_modal', \
     'frf_B.x.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'file'
