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
set arrow from 174.63829371894496,graph 0 to 174.63829371894496,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 174.6482396272064,graph 0 to 174.6482396272064,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 921.8478020535008,graph 0 to 921.8478020535008,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 922.389033894547,graph 0 to 922.389033894547,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1088.313163380661,graph 0 to 1088.313163380661,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1102.0821017984254,graph 0 to 1102.0821017984254,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.3590114739422,graph 0 to 1155.3590114739422,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1155.4209235826931,graph 0 to 1155.4209235826931,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1849.044671802799,graph 0 to 1849.044671802799,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 1851.6531086601103,graph 0 to 1851.6531086601103,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.2973751775835,graph 0 to 3560.2973751775835,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3560.8863022403257,graph 0 to 3560.8863022403257,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3616.901754329323,graph 0 to 3616.901754329323,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 3619.502689110498,graph 0 to 3619.502689110498,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4213.979104093086,graph 0 to 4213.979104093086,graph 1 nohead dt 3 lc rgb '#bbbbbb'
set arrow from 4369.423106167329,graph 0 to 4369.423106167329,graph 1 nohead dt 3 lc rgb '#bbbbbb'
plot 'frf_T1.z.dat' using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'full', \
     'frf_T1.z.dat' using 1:3 with lines lw 1 lc rgb '#bf1f1f' title 'rom', \
     'frf_T1.z.dat' using 1:4 with lines lw 1 lc rgb '#2f9f2f' title 'rom_corner'
