set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'mode4.svg'
set title 'Mode 4: 246.8073 Hz (displacements x 37.5)'
set size ratio -1
set xlabel 'x [m]'
set ylabel 'y [m]'
set key outside right
plot 'mode4.dat' index 0 with lines lc rgb '#999999' dt 2 title 'undeformed', \
     'mode4.dat' index 1 with lines lc rgb '#1f5fbf' lw 1.5 title 'deformed'
