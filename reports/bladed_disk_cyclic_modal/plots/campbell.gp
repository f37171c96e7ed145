set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'campbell.svg'
set title 'Campbell diagram by nodal diameter (the ones the engine orders excite) and engine-order lines'
set xlabel 'speed [rpm]'
set ylabel 'frequency [Hz]'
set grid
set key outside right
set xrange [0:15000]
set yrange [0:1515.65207438]
set datafile missing 'nan'
plot 'campbell.dat' index 0 using 1:2 with linespoints pt 7 ps 0.4 lc 1 title 'ND 0', \
     'campbell.dat' index 1 using 1:2 with linespoints pt 7 ps 0.4 lc 1 notitle, \
     'campbell.dat' index 2 using 1:2 with linespoints pt 7 ps 0.4 lc 1 notitle, \
     'campbell.dat' index 3 using 1:2 with linespoints pt 7 ps 0.4 lc 1 notitle, \
     'campbell.dat' index 4 using 1:2 with linespoints pt 7 ps 0.4 lc 1 notitle, \
     'campbell.dat' index 5 using 1:2 with linespoints pt 7 ps 0.4 lc 1 notitle, \
     'campbell.dat' index 6 using 1:2 with linespoints pt 7 ps 0.4 lc 2 title 'ND 1', \
     'campbell.dat' index 7 using 1:2 with linespoints pt 7 ps 0.4 lc 2 notitle, \
     'campbell.dat' index 8 using 1:2 with linespoints pt 7 ps 0.4 lc 2 notitle, \
     'campbell.dat' index 9 using 1:2 with linespoints pt 7 ps 0.4 lc 2 notitle, \
     'campbell.dat' index 10 using 1:2 with linespoints pt 7 ps 0.4 lc 2 notitle, \
     'campbell.dat' index 11 using 1:2 with linespoints pt 7 ps 0.4 lc 2 notitle, \
     'campbell.dat' index 12 using 1:2 with linespoints pt 7 ps 0.4 lc 3 title 'ND 2', \
     'campbell.dat' index 13 using 1:2 with linespoints pt 7 ps 0.4 lc 3 notitle, \
     'campbell.dat' index 14 using 1:2 with linespoints pt 7 ps 0.4 lc 3 notitle, \
     'campbell.dat' index 15 using 1:2 with linespoints pt 7 ps 0.4 lc 3 notitle, \
     'campbell.dat' index 16 using 1:2 with linespoints pt 7 ps 0.4 lc 3 notitle, \
     'campbell.dat' index 17 using 1:2 with linespoints pt 7 ps 0.4 lc 3 notitle, \
     'campbell.dat' index 18 using 1:2 with linespoints pt 7 ps 0.4 lc 4 title 'ND 3', \
     'campbell.dat' index 19 using 1:2 with linespoints pt 7 ps 0.4 lc 4 notitle, \
     'campbell.dat' index 20 using 1:2 with linespoints pt 7 ps 0.4 lc 4 notitle, \
     'campbell.dat' index 21 using 1:2 with linespoints pt 7 ps 0.4 lc 4 notitle, \
     'campbell.dat' index 22 using 1:2 with linespoints pt 7 ps 0.4 lc 4 notitle, \
     'campbell.dat' index 23 using 1:2 with linespoints pt 7 ps 0.4 lc 4 notitle, \
     'campbell.dat' index 24 using 1:2 with linespoints pt 7 ps 0.4 lc 5 title 'ND 4', \
     'campbell.dat' index 25 using 1:2 with linespoints pt 7 ps 0.4 lc 5 notitle, \
     'campbell.dat' index 26 using 1:2 with linespoints pt 7 ps 0.4 lc 5 notitle, \
     'campbell.dat' index 27 using 1:2 with linespoints pt 7 ps 0.4 lc 5 notitle, \
     'campbell.dat' index 28 using 1:2 with linespoints pt 7 ps 0.4 lc 5 notitle, \
     'campbell.dat' index 29 using 1:2 with linespoints pt 7 ps 0.4 lc 5 notitle, \
     'campbell.dat' index 30 using 1:2 with linespoints pt 7 ps 0.4 lc 6 title 'ND 6', \
     'campbell.dat' index 31 using 1:2 with linespoints pt 7 ps 0.4 lc 6 notitle, \
     'campbell.dat' index 32 using 1:2 with linespoints pt 7 ps 0.4 lc 6 notitle, \
     'campbell.dat' index 33 using 1:2 with linespoints pt 7 ps 0.4 lc 6 notitle, \
     'campbell.dat' index 34 using 1:2 with linespoints pt 7 ps 0.4 lc 6 notitle, \
     'campbell.dat' index 35 using 1:2 with linespoints pt 7 ps 0.4 lc 6 notitle, \
     'campbell.dat' index 36 using 1:2 with linespoints pt 7 ps 0.4 lc 7 title 'ND 8', \
     'campbell.dat' index 37 using 1:2 with linespoints pt 7 ps 0.4 lc 7 notitle, \
     'campbell.dat' index 38 using 1:2 with linespoints pt 7 ps 0.4 lc 7 notitle, \
     'campbell.dat' index 39 using 1:2 with linespoints pt 7 ps 0.4 lc 7 notitle, \
     'campbell.dat' index 40 using 1:2 with linespoints pt 7 ps 0.4 lc 7 notitle, \
     'campbell.dat' index 41 using 1:2 with linespoints pt 7 ps 0.4 lc 7 notitle, \
     'campbell.dat' index 42 using 1:2 with linespoints pt 7 ps 0.4 lc 8 title 'ND 12', \
     'campbell.dat' index 43 using 1:2 with linespoints pt 7 ps 0.4 lc 8 notitle, \
     'campbell.dat' index 44 using 1:2 with linespoints pt 7 ps 0.4 lc 8 notitle, \
     'campbell.dat' index 45 using 1:2 with linespoints pt 7 ps 0.4 lc 8 notitle, \
     'campbell.dat' index 46 using 1:2 with linespoints pt 7 ps 0.4 lc 8 notitle, \
     'campbell.dat' index 47 using 1:2 with linespoints pt 7 ps 0.4 lc 8 notitle, \
     'campbell.dat' index 48 using 1:2 with points pt 6 ps 1.2 lc rgb 'black' title 'crossings', \
     x * 1 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 1', \
     x * 2 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 2', \
     x * 3 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 3', \
     x * 4 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 4', \
     x * 6 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 6', \
     x * 8 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 8', \
     x * 12 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 12', \
     x * 24 / 60.0 with lines dt 2 lc rgb 'gray40' title 'EO 24'
