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
     'contact_states_peak.dat' using 1:5 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'next lift-off', \
     'contact_states_peak.dat' using 1:6 with linespoints pt 7 lc rgb '#2f9f2f' title 'own@1 stick', \
     'contact_states_peak.dat' using 1:7 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'own@1 lift-off', \
     'contact_states_peak.dat' using 1:8 with linespoints pt 7 lc rgb '#9f2fbf' title 'next@1 stick', \
     'contact_states_peak.dat' using 1:9 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'next@1 lift-off', \
     'contact_states_peak.dat' using 1:10 with linespoints pt 7 lc rgb '#bf8f1f' title 'own@2 stick', \
     'contact_states_peak.dat' using 1:11 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'own@2 lift-off', \
     'contact_states_peak.dat' using 1:12 with linespoints pt 7 lc rgb '#1f9fbf' title 'next@2 stick', \
     'contact_states_peak.dat' using 1:13 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'next@2 lift-off', \
     'contact_states_peak.dat' using 1:14 with linespoints pt 7 lc rgb '#7f7f7f' title 'own@3 stick', \
     'contact_states_peak.dat' using 1:15 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'own@3 lift-off', \
     'contact_states_peak.dat' using 1:16 with linespoints pt 7 lc rgb '#000000' title 'next@3 stick', \
     'contact_states_peak.dat' using 1:17 with linespoints pt 4 dt 2 lc rgb '#000000' title 'next@3 lift-off', \
     'contact_states_peak.dat' using 1:18 with linespoints pt 7 lc rgb '#1f5fbf' title 'own@4 stick', \
     'contact_states_peak.dat' using 1:19 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'own@4 lift-off', \
     'contact_states_peak.dat' using 1:20 with linespoints pt 7 lc rgb '#bf1f1f' title 'next@4 stick', \
     'contact_states_peak.dat' using 1:21 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'next@4 lift-off', \
     'contact_states_peak.dat' using 1:22 with linespoints pt 7 lc rgb '#2f9f2f' title 'own@5 stick', \
     'contact_states_peak.dat' using 1:23 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'own@5 lift-off', \
     'contact_states_peak.dat' using 1:24 with linespoints pt 7 lc rgb '#9f2fbf' title 'next@5 stick', \
     'contact_states_peak.dat' using 1:25 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'next@5 lift-off', \
     'contact_states_peak.dat' using 1:26 with linespoints pt 7 lc rgb '#bf8f1f' title 'own@6 stick', \
     'contact_states_peak.dat' using 1:27 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'own@6 lift-off', \
     'contact_states_peak.dat' using 1:28 with linespoints pt 7 lc rgb '#1f9fbf' title 'next@6 stick', \
     'contact_states_peak.dat' using 1:29 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'next@6 lift-off', \
     'contact_states_peak.dat' using 1:30 with linespoints pt 7 lc rgb '#7f7f7f' title 'own@7 stick', \
     'contact_states_peak.dat' using 1:31 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'own@7 lift-off', \
     'contact_states_peak.dat' using 1:32 with linespoints pt 7 lc rgb '#000000' title 'next@7 stick', \
     'contact_states_peak.dat' using 1:33 with linespoints pt 4 dt 2 lc rgb '#000000' title 'next@7 lift-off', \
     'contact_states_peak.dat' using 1:34 with linespoints pt 7 lc rgb '#1f5fbf' title 'own@8 stick', \
     'contact_states_peak.dat' using 1:35 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'own@8 lift-off', \
     'contact_states_peak.dat' using 1:36 with linespoints pt 7 lc rgb '#bf1f1f' title 'next@8 stick', \
     'contact_states_peak.dat' using 1:37 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'next@8 lift-off', \
     'contact_states_peak.dat' using 1:38 with linespoints pt 7 lc rgb '#2f9f2f' title 'own@9 stick', \
     'contact_states_peak.dat' using 1:39 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'own@9 lift-off', \
     'contact_states_peak.dat' using 1:40 with linespoints pt 7 lc rgb '#9f2fbf' title 'next@9 stick', \
     'contact_states_peak.dat' using 1:41 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'next@9 lift-off', \
     'contact_states_peak.dat' using 1:42 with linespoints pt 7 lc rgb '#bf8f1f' title 'own@10 stick', \
     'contact_states_peak.dat' using 1:43 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'own@10 lift-off', \
     'contact_states_peak.dat' using 1:44 with linespoints pt 7 lc rgb '#1f9fbf' title 'next@10 stick', \
     'contact_states_peak.dat' using 1:45 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'next@10 lift-off', \
     'contact_states_peak.dat' using 1:46 with linespoints pt 7 lc rgb '#7f7f7f' title 'own@11 stick', \
     'contact_states_peak.dat' using 1:47 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'own@11 lift-off', \
     'contact_states_peak.dat' using 1:48 with linespoints pt 7 lc rgb '#000000' title 'next@11 stick', \
     'contact_states_peak.dat' using 1:49 with linespoints pt 4 dt 2 lc rgb '#000000' title 'next@11 lift-off'
