set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_T1.z.svg'
set title 'Response T1.z (amplitude)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
set xrange [1:4999]
set arrow from 174.63829362840886,graph 0 to 174.63829362840886,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.6482395366741,graph 0 to 174.6482395366741,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.8478020399982,graph 0 to 921.8478020399982,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.3890338810155,graph 0 to 922.3890338810155,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.3131633830951,graph 0 to 1088.3131633830951,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821018007573,graph 0 to 1102.0821018007573,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114576934,graph 0 to 1155.3590114576934,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.4209235664275,graph 0 to 1155.4209235664275,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.0446718016954,graph 0 to 1849.0446718016954,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.6531086589907,graph 0 to 1851.6531086589907,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.297375170922,graph 0 to 3560.297375170922,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.886302233662,graph 0 to 3560.886302233662,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.9017543270807,graph 0 to 3616.9017543270807,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.5026891082457,graph 0 to 3619.5026891082457,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.97910409324,graph 0 to 4213.97910409324,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.423106167493,graph 0 to 4369.423106167493,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T1.z.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T1.z.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T1.z.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
