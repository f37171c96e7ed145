set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'mode1.svg'
set multiplot layout 1,2 title 'Mode 1: 0.0000 Hz (displacements x 655)'
set size ratio -1
set key off
set title 'front (x-y)'
set xlabel 'x [m]'
set ylabel 'y [m]'
plot 'mode1.dat' index 0 with lines lc rgb '#bbbbbb', 'mode1.dat' index 1 with lines lc rgb '#1f5fbf'
set title 'side (z-y)'
set xlabel 'z [m]'
set xtics rotate by 90 right
plot 'mode1.dat' index 2 with lines lc rgb '#bbbbbb', 'mode1.dat' index 3 with lines lc rgb '#1f5fbf'
unset multiplot
