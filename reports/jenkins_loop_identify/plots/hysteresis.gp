set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'hysteresis.svg'
set title 'Hysteresis loop: energy 0.003071 J per cycle, max |T| 88 N'
set xlabel 'relative tangential displacement u [m]'
set ylabel 'tangential force T [N]'
set grid
set key outside right
set datafile missing 'nan'
plot 'hysteresis.dat' index 0 using 1:2 with lines lw 1.5 lc rgb '#7f7f7f' title 'loop', \
     'hysteresis.dat' index 1 using 1:2 with points pt 7 ps 0.5 lc rgb '#1f5fbf' title 'stick', \
     'hysteresis.dat' index 2 using 1:2 with points pt 7 ps 0.5 lc rgb '#bf1f1f' title 'slip+', \
     'hysteresis.dat' index 3 using 1:2 with points pt 7 ps 0.5 lc rgb '#2f9f2f' title 'slip-', \
     'hysteresis.dat' index 4 using 1:2 with points pt 7 ps 0.5 lc rgb '#9f2fbf' title 'lift-off'
