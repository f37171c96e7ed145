set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'contact_states_peak.svg'
set title 'Contact states at the peak peaks (slip = the rest of the period)'
set logscale x
set xlabel 'Fe [N]'
set ylabel 'fraction of the period'
set yrange [-0.02:1.02]
set grid
set key outside right
plot 'contact_states_peak.dat' using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'own stick', \
     'contact_states_peak.dat' using 1:3 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'own lift-off', \
     'contact_states_peak.dat' using 1:4 with linespoints pt 7 lc rgb '#bf1f1f' title 'next stick', \
     'contact_states_peak.dat' using 1:5 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'next lift-off'
