set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'check1.svg'
set title 'Check: Ff/F0 = 0.1: largest displacement and first harmonic vs the exact motion, Coulomb''s stick'
set xlabel 'entry (order of the report table)'
set ylabel 'value'
set key outside right
set grid
plot 'check1.dat' using 1:3:4 with yerrorbars lc rgb '#999999' title 'reference +- tolerance', \
     'check1.dat' using 1:2 with points pt 7 ps 0.6 lc rgb '#1f5fbf' title 'computed'
