set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'nodal_diameter_map.svg'
set title 'Nodal-diameter map of the 12-sector structure'
set xlabel 'nodal diameter'
set ylabel 'frequency [Hz]'
set grid
set key outside right
set xrange [-0.5:6.5]
set xtics 1
set datafile missing 'nan'
plot 'nodal_diameter_map.dat' index 0 using 1:2 with linespoints pt 7 ps 0.6 title 'family 1', \
     'nodal_diameter_map.dat' index 1 using 1:2 with linespoints pt 7 ps 0.6 title 'family 2', \
     'nodal_diameter_map.dat' index 2 using 1:2 with linespoints pt 7 ps 0.6 title 'family 3', \
     'nodal_diameter_map.dat' index 3 using 1:2 with linespoints pt 7 ps 0.6 title 'family 4', \
     'nodal_diameter_map.dat' index 4 using 1:2 with linespoints pt 7 ps 0.6 title 'family 5', \
     'nodal_diameter_map.dat' index 5 using 1:2 with linespoints pt 7 ps 0.6 title 'family 6'
