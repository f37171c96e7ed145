set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_T2.x.svg'
set title 'Response T2.x (amplitude)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
set xrange [1:4999]
set arrow from 174.63829370283534,graph 0 to 174.63829370283534,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.64823961109465,graph 0 to 174.64823961109465,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.8478020532408,graph 0 to 921.8478020532408,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.3890338942604,graph 0 to 922.3890338942604,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.3131633808796,graph 0 to 1088.3131633808796,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821017985886,graph 0 to 1102.0821017985886,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114811866,graph 0 to 1155.3590114811866,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.420923589912,graph 0 to 1155.420923589912,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.044671806149,graph 0 to 1849.044671806149,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.65310866347,graph 0 to 1851.65310866347,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.2973751768,graph 0 to 3560.2973751768,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.8863022395585,graph 0 to 3560.8863022395585,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.901754329992,graph 0 to 3616.901754329992,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.50268911117,graph 0 to 3619.50268911117,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.979104093179,graph 0 to 4213.979104093179,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.423106167445,graph 0 to 4369.423106167445,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T2.x.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T2.x.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T2.x.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
