set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_A.x.svg'
set title 'Response A.x: time integration (points), harmonic balance and linear model (lines)'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
set datafile missing 'nan'
plot 'frf_A.x.dat' index 0 using 1:2 with points pt 7 ps 0.5 lc rgb '#1f5fbf' title 'Fe = 30 N, time domain', \
     'frf_A.x.dat' index 0 using 1:3 with lines dt 2 lc rgb '#1f5fbf' title 'Fe = 30 N, linear (contacts as springs)', \
     'frf_A.x.dat' index 2 using 1:2 with points pt 7 ps 0.5 lc rgb '#bf1f1f' title 'Fe = 10 N, time domain', \
     'frf_A.x.dat' index 2 using 1:3 with lines dt 2 lc rgb '#bf1f1f' title 'Fe = 10 N, linear (contacts as springs)', \
     'frf_A.x.dat' index 4 using 1:2 with points pt 7 ps 0.5 lc rgb '#2f9f2f' title 'Fe = 6 N, time domain', \
     'frf_A.x.dat' index 4 using 1:3 with lines dt 2 lc rgb '#2f9f2f' title 'Fe = 6 N, linear (contacts as springs)', \
     'frf_A.x.dat' index 6 using 1:2 with points pt 7 ps 0.5 lc rgb '#9f2fbf' title 'Fe = 4.28571 N, time domain', \
     'frf_A.x.dat' index 6 using 1:3 with lines dt 2 lc rgb '#9f2fbf' title 'Fe = 4.28571 N, linear (contacts as springs)', \
     'frf_A.x.dat' index 8 using 1:2 with points pt 7 ps 0.5 lc rgb '#bf8f1f' title 'Fe = 3.33333 N, time domain', \
     'frf_A.x.dat' index 8 using 1:3 with lines dt 2 lc rgb '#bf8f1f' title 'Fe = 3.33333 N, linear (contacts as springs)'
