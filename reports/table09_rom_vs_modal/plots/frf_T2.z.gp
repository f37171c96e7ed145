set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_T2.z.svg'
set title 'Response T2.z (amplitude)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
set xrange [1:4999]
set arrow from 174.63829368352208,graph 0 to 174.63829368352208,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.64823959178213,graph 0 to 174.64823959178213,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.847802048697,graph 0 to 921.847802048697,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.3890338897278,graph 0 to 922.3890338897278,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.3131633822395,graph 0 to 1088.3131633822395,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821017999322,graph 0 to 1102.0821017999322,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114782714,graph 0 to 1155.3590114782714,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.420923587008,graph 0 to 1155.420923587008,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.044671804035,graph 0 to 1849.044671804035,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.6531086613513,graph 0 to 1851.6531086613513,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.297375174938,graph 0 to 3560.297375174938,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.8863022376872,graph 0 to 3560.8863022376872,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.9017543294563,graph 0 to 3616.9017543294563,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.502689110659,graph 0 to 3619.502689110659,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.979104093176,graph 0 to 4213.979104093176,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.42310616743,graph 0 to 4369.42310616743,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T2.z.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T2.z.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T2.z.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
