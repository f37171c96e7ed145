set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'contact_mode3.svg'
set title 'Mode 3: frequency against the normal penalty factor FKN'
set xlabel 'FKN (kn = FKN E / h)'
set ylabel 'frequency [Hz]'
set logscale x
set grid
set key outside right
plot 'contact_mode3.dat' index 0 using 1:2 with linespoints pt 7 ps 0.5 title 'interference 1e-06 m', \
     'contact_mode3.dat' index 1 using 1:2 with linespoints pt 7 ps 0.5 title 'interference 1e-05 m', \
     'contact_mode3.dat' index 2 using 1:2 with linespoints pt 7 ps 0.5 title 'interference 0.0001 m', \
     937.117039458 with lines dt 2 lc rgb 'black' title 'glued'
