set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'contact_states_OOP.svg'
set title 'Contact states at the OOP peaks (slip = the rest of the period)'
set logscale x
set xlabel 'CF / Fe'
set ylabel 'fraction of the period'
set yrange [-0.02:1.02]
set grid
set key outside right
plot 'contact_states_OOP.dat' using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'L1 stick', \
     'contact_states_OOP.dat' using 1:3 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'L1 lift-off', \
     'contact_states_OOP.dat' using 1:4 with linespoints pt 7 lc rgb '#bf1f1f' title 'L2 stick', \
     'contact_states_OOP.dat' using 1:5 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'L2 lift-off', \
     'contact_states_OOP.dat' using 1:6 with linespoints pt 7 lc rgb '#2f9f2f' title 'R stick', \
     'contact_states_OOP.dat' using 1:7 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'R lift-off'
