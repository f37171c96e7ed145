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
set arrow from 174.63829348077118,graph 0 to 174.63829348077118,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.64823938904536,graph 0 to 174.64823938904536,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.8478020130298,graph 0 to 921.8478020130298,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.3890338540725,graph 0 to 922.3890338540725,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.3131633468336,graph 0 to 1088.3131633468336,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821017649248,graph 0 to 1102.0821017649248,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114197834,graph 0 to 1155.3590114197834,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.420923528525,graph 0 to 1155.420923528525,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.044671787821,graph 0 to 1849.044671787821,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.6531086451512,graph 0 to 1851.6531086451512,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.2973751596696,graph 0 to 3560.2973751596696,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.886302222413,graph 0 to 3560.886302222413,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.901754317173,graph 0 to 3616.901754317173,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.502689098377,graph 0 to 3619.502689098377,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.979104088148,graph 0 to 4213.979104088148,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.423106162271,graph 0 to 4369.423106162271,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T2.z.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T2.z.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T2.z.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
