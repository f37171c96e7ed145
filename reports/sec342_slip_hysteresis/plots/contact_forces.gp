set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'contact_forces.svg'
set title 'Contact forces at 174.85 Hz, Fe = 100 N (N solid, T dashed)'
set xlabel 'time [s]'
set ylabel 'force [N]'
set grid
set key outside right
plot 'contact_forces.dat' index 0 using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'L1 N', 'contact_forces.dat' index 0 using 1:3 with lines dt 2 lc rgb '#1f5fbf' title 'L1 T', \
     'contact_forces.dat' index 1 using 1:2 with lines lw 2 lc rgb '#bf1f1f' title 'L2 N', 'contact_forces.dat' index 1 using 1:3 with lines dt 2 lc rgb '#bf1f1f' title 'L2 T', \
     'contact_forces.dat' index 2 using 1:2 with lines lw 2 lc rgb '#2f9f2f' title 'R N', 'contact_forces.dat' index 2 using 1:3 with lines dt 2 lc rgb '#2f9f2f' title 'R T'
