set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'hysteresis.svg'
set title 'Hysteresis loops at 174.85 Hz, Fe = 100 N'
set xlabel 'relative tangential displacement u [m]'
set ylabel 'tangential force T [N]'
set grid
set key outside right
plot 'hysteresis.dat' index 0 using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'L1', \
     'hysteresis.dat' index 1 using 1:2 with lines lw 2 lc rgb '#bf1f1f' title 'L2', \
     'hysteresis.dat' index 2 using 1:2 with lines lw 2 lc rgb '#2f9f2f' title 'R'
