set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'campbell.svg'
set title 'Campbell diagram: rotating modes (lines) and engine-order lines (dashed)'
set xlabel 'speed [rad/s]'
set ylabel 'frequency [Hz]'
set grid
set key outside right
set xrange [0:6]
set yrange [0:5.06304704331]
set datafile missing 'nan'
plot 'campbell.dat' index 0 using 1:2 with linespoints pt 7 ps 0.4 title 'mode 1', \
     'campbell.dat' index 1 using 1:2 with linespoints pt 7 ps 0.4 title 'mode 2', \
     'campbell.dat' index 2 using 1:2 with linespoints pt 7 ps 0.4 title 'mode 3', \
     'campbell.dat' index 3 using 1:2 with linespoints pt 7 ps 0.4 title 'mode 4', \
     'campbell.dat' index 4 using 1:2 with points pt 6 ps 1.2 lc rgb 'black' title 'crossings', \
     1 * x / (2 * pi) with lines dt 2 lc rgb '#7f7f7f' notitle, \
     2 * x / (2 * pi) with lines dt 2 lc rgb '#7f7f7f' notitle, \
     3 * x / (2 * pi) with lines dt 2 lc rgb '#7f7f7f' notitle
