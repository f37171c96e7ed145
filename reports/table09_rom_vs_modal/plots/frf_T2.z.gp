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
set arrow from 174.6382937392292,graph 0 to 174.6382937392292,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.64823964748967,graph 0 to 174.64823964748967,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.847802054741,graph 0 to 921.847802054741,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.3890338957608,graph 0 to 922.3890338957608,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.3131633815406,graph 0 to 1088.3131633815406,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821017992096,graph 0 to 1102.0821017992096,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114915758,graph 0 to 1155.3590114915758,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.4209236002896,graph 0 to 1155.4209236002896,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.0446718057483,graph 0 to 1849.0446718057483,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.6531086630846,graph 0 to 1851.6531086630846,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.297375178568,graph 0 to 3560.297375178568,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.8863022413198,graph 0 to 3560.8863022413198,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.90175433239,graph 0 to 3616.90175433239,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.5026891135985,graph 0 to 3619.5026891135985,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.979104093284,graph 0 to 4213.979104093284,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.423106167563,graph 0 to 4369.423106167563,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T2.z.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T2.z.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T2.z.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
