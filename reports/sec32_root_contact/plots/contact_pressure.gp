set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'contact_pressure.svg'
set title 'Contact pressure at the Gauss points of every pair (state point)'
set xlabel 'x [m]'
set ylabel 'pressure [Pa]'
set grid
set key outside right
set datafile missing 'nan'
plot 'contact_pressure.dat' index 0 using 1:2 with points pt 7 ps 0.4 title 'root1_arms', \
     'contact_pressure.dat' index 1 using 1:2 with points pt 7 ps 0.4 title 'root2_arms', \
     'contact_pressure.dat' index 2 using 1:2 with points pt 7 ps 0.4 title 'wedge1_root', \
     'contact_pressure.dat' index 3 using 1:2 with points pt 7 ps 0.4 title 'wedge2_root'
