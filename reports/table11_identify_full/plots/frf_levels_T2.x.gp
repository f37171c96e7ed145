set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_levels_T2.x.svg'
set title 'Response T2.x at each force level (first harmonic)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 'frf_levels_T2.x.dat' index 0 using 1:2 with lines lc rgb '#1f5fbf' title 'Fe = 300 N', \
     'frf_levels_T2.x.dat' index 1 using 1:2 with lines lc rgb '#bf1f1f' title 'Fe = 260 N', \
     'frf_levels_T2.x.dat' index 2 using 1:2 with lines lc rgb '#2f9f2f' title 'Fe = 220 N', \
     'frf_levels_T2.x.dat' index 3 using 1:2 with lines lc rgb '#9f2fbf' title 'Fe = 200 N', \
     'frf_levels_T2.x.dat' index 4 using 1:2 with lines lc rgb '#bf8f1f' title 'Fe = 150 N', \
     'frf_levels_T2.x.dat' index 5 using 1:2 with lines lc rgb '#1f9fbf' title 'Fe = 110 N', \
     'frf_levels_T2.x.dat' index 6 using 1:2 with lines lc rgb '#7f7f7f' title 'Fe = 100 N', \
     'frf_levels_T2.x.dat' index 7 using 1:2 with lines lc rgb '#000000' title 'Fe = 80 N', \
     'frf_levels_T2.x.dat' index 8 using 1:2 with lines lc rgb '#1f5fbf' title 'Fe = 60 N', \
     'frf_levels_T2.x.dat' index 9 using 1:2 with lines lc rgb '#bf1f1f' title 'Fe = 30 N', \
     'frf_levels_T2.x.dat' index 10 using 1:2 with lines lc rgb '#2f9f2f' title 'Fe = 20 N', \
     'frf_levels_T2.x.dat' index 11 using 1:2 with lines lc rgb '#9f2fbf' title 'Fe = 15 N', \
     'frf_levels_T2.x.dat' index 12 using 1:2 with lines lc rgb '#bf8f1f' title 'Fe = 12 N', \
     'frf_levels_T2.x.dat' index 13 using 1:2 with lines lc rgb '#1f9fbf' title 'Fe = 6 N', \
     'frf_levels_T2.x.dat' index 14 using 1:2 with lines lc rgb '#7f7f7f' title 'Fe = 5 N'
