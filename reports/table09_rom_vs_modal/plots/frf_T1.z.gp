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
set arrow from 174.6382937189449,graph 0 to 174.6382937189449,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.64823962720638,graph 0 to 174.64823962720638,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.8478020535,graph 0 to 921.8478020535,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.3890338945466,graph 0 to 922.3890338945466,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.3131633806597,graph 0 to 1088.3131633806597,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821017984265,graph 0 to 1102.0821017984265,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114739427,graph 0 to 1155.3590114739427,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.4209235826913,graph 0 to 1155.4209235826913,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.04467180279,graph 0 to 1849.04467180279,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.6531086601099,graph 0 to 1851.6531086601099,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.29737517757,graph 0 to 3560.29737517757,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.8863022403175,graph 0 to 3560.8863022403175,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.901754329308,graph 0 to 3616.901754329308,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.502689110497,graph 0 to 3619.502689110497,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.979104093092,graph 0 to 4213.979104093092,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.423106167328,graph 0 to 4369.423106167328,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T1.z.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T1.z.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T1.z.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
