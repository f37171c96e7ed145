set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_harmonics.svg'
set title 'Harmonic balance: peak amplitude error against the largest H vs cost'
set logscale xy
set format y '10^{%L}'
set xlabel 'sweep time [s]'
set ylabel '|relative amplitude error|'
set grid
set key outside right
plot 'study_harmonics.dat' index 0 using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'Fe = 300 N, ip', 'study_harmonics.dat' index 0 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 1 using 1:2 with linespoints pt 7 lc rgb '#bf1f1f' title 'Fe = 300 N, oop', 'study_harmonics.dat' index 1 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 2 using 1:2 with linespoints pt 7 lc rgb '#2f9f2f' title 'Fe = 60 N, ip', 'study_harmonics.dat' index 2 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 3 using 1:2 with linespoints pt 7 lc rgb '#9f2fbf' title 'Fe = 60 N, oop', 'study_harmonics.dat' index 3 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 4 using 1:2 with linespoints pt 7 lc rgb '#bf8f1f' title 'Fe = 30 N, ip', 'study_harmonics.dat' index 4 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 5 using 1:2 with linespoints pt 7 lc rgb '#1f9fbf' title 'Fe = 30 N, oop', 'study_harmonics.dat' index 5 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 6 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'Fe = 5 N, ip', 'study_harmonics.dat' index 6 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle, \
     'study_harmonics.dat' index 7 using 1:2 with linespoints pt 7 lc rgb '#000000' title 'Fe = 5 N, oop', 'study_harmonics.dat' index 7 using 1:2:(sprintf('H=%d', $3)) with labels offset 0,1 notitle
