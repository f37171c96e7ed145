set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'contact_states_peak.svg'
set title 'Contact states at the peak peaks (slip = the rest of the period)'
set logscale x
set xlabel 'Fe [N]'
set ylabel 'fraction of the period'
set yrange [-0.02:1.02]
set grid
set key outside right
plot 'contact_states_peak.dat' using 1:2 with linespoints pt 7 lc rgb '#1f5fbf' title 'joint.1 stick', \
     'contact_states_peak.dat' using 1:3 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'joint.1 lift-off', \
     'contact_states_peak.dat' using 1:4 with linespoints pt 7 lc rgb '#bf1f1f' title 'joint.2 stick', \
     'contact_states_peak.dat' using 1:5 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'joint.2 lift-off', \
     'contact_states_peak.dat' using 1:6 with linespoints pt 7 lc rgb '#2f9f2f' title 'joint.3 stick', \
     'contact_states_peak.dat' using 1:7 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'joint.3 lift-off', \
     'contact_states_peak.dat' using 1:8 with linespoints pt 7 lc rgb '#9f2fbf' title 'joint.4 stick', \
     'contact_states_peak.dat' using 1:9 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'joint.4 lift-off', \
     'contact_states_peak.dat' using 1:10 with linespoints pt 7 lc rgb '#bf8f1f' title 'joint.5 stick', \
     'contact_states_peak.dat' using 1:11 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'joint.5 lift-off', \
     'contact_states_peak.dat' using 1:12 with linespoints pt 7 lc rgb '#1f9fbf' title 'joint.6 stick', \
     'contact_states_peak.dat' using 1:13 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'joint.6 lift-off', \
     'contact_states_peak.dat' using 1:14 with linespoints pt 7 lc rgb '#7f7f7f' title 'joint.7 stick', \
     'contact_states_peak.dat' using 1:15 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'joint.7 lift-off', \
     'contact_states_peak.dat' using 1:16 with linespoints pt 7 lc rgb '#000000' title 'joint.8 stick', \
     'contact_states_peak.dat' using 1:17 with linespoints pt 4 dt 2 lc rgb '#000000' title 'joint.8 lift-off', \
     'contact_states_peak.dat' using 1:18 with linespoints pt 7 lc rgb '#1f5fbf' title 'joint.9 stick', \
     'contact_states_peak.dat' using 1:19 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'joint.9 lift-off', \
     'contact_states_peak.dat' using 1:20 with linespoints pt 7 lc rgb '#bf1f1f' title 'joint.10 stick', \
     'contact_states_peak.dat' using 1:21 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'joint.10 lift-off', \
     'contact_states_peak.dat' using 1:22 with linespoints pt 7 lc rgb '#2f9f2f' title 'joint.11 stick', \
     'contact_states_peak.dat' using 1:23 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'joint.11 lift-off', \
     'contact_states_peak.dat' using 1:24 with linespoints pt 7 lc rgb '#9f2fbf' title 'joint.12 stick', \
     'contact_states_peak.dat' using 1:25 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'joint.12 lift-off', \
     'contact_states_peak.dat' using 1:26 with linespoints pt 7 lc rgb '#bf8f1f' title 'joint.13 stick', \
     'contact_states_peak.dat' using 1:27 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'joint.13 lift-off', \
     'contact_states_peak.dat' using 1:28 with linespoints pt 7 lc rgb '#1f9fbf' title 'joint.14 stick', \
     'contact_states_peak.dat' using 1:29 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'joint.14 lift-off', \
     'contact_states_peak.dat' using 1:30 with linespoints pt 7 lc rgb '#7f7f7f' title 'joint.15 stick', \
     'contact_states_peak.dat' using 1:31 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'joint.15 lift-off', \
     'contact_states_peak.dat' using 1:32 with linespoints pt 7 lc rgb '#000000' title 'joint.16 stick', \
     'contact_states_peak.dat' using 1:33 with linespoints pt 4 dt 2 lc rgb '#000000' title 'joint.16 lift-off', \
     'contact_states_peak.dat' using 1:34 with linespoints pt 7 lc rgb '#1f5fbf' title 'joint.17 stick', \
     'contact_states_peak.dat' using 1:35 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'joint.17 lift-off', \
     'contact_states_peak.dat' using 1:36 with linespoints pt 7 lc rgb '#bf1f1f' title 'joint.18 stick', \
     'contact_states_peak.dat' using 1:37 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'joint.18 lift-off', \
     'contact_states_peak.dat' using 1:38 with linespoints pt 7 lc rgb '#2f9f2f' title 'joint.19 stick', \
     'contact_states_peak.dat' using 1:39 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'joint.19 lift-off', \
     'contact_states_peak.dat' using 1:40 with linespoints pt 7 lc rgb '#9f2fbf' title 'joint.20 stick', \
     'contact_states_peak.dat' using 1:41 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'joint.20 lift-off', \
     'contact_states_peak.dat' using 1:42 with linespoints pt 7 lc rgb '#bf8f1f' title 'joint.21 stick', \
     'contact_states_peak.dat' using 1:43 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'joint.21 lift-off', \
     'contact_states_peak.dat' using 1:44 with linespoints pt 7 lc rgb '#1f9fbf' title 'joint.22 stick', \
     'contact_states_peak.dat' using 1:45 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'joint.22 lift-off', \
     'contact_states_peak.dat' using 1:46 with linespoints pt 7 lc rgb '#7f7f7f' title 'joint.23 stick', \
     'contact_states_peak.dat' using 1:47 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'joint.23 lift-off', \
     'contact_states_peak.dat' using 1:48 with linespoints pt 7 lc rgb '#000000' title 'joint.24 stick', \
     'contact_states_peak.dat' using 1:49 with linespoints pt 4 dt 2 lc rgb '#000000' title 'joint.24 lift-off', \
     'contact_states_peak.dat' using 1:50 with linespoints pt 7 lc rgb '#1f5fbf' title 'joint.25 stick', \
     'contact_states_peak.dat' using 1:51 with linespoints pt 4 dt 2 lc rgb '#1f5fbf' title 'joint.25 lift-off', \
     'contact_states_peak.dat' using 1:52 with linespoints pt 7 lc rgb '#bf1f1f' title 'joint.26 stick', \
     'contact_states_peak.dat' using 1:53 with linespoints pt 4 dt 2 lc rgb '#bf1f1f' title 'joint.26 lift-off', \
     'contact_states_peak.dat' using 1:54 with linespoints pt 7 lc rgb '#2f9f2f' title 'joint.27 stick', \
     'contact_states_peak.dat' using 1:55 with linespoints pt 4 dt 2 lc rgb '#2f9f2f' title 'joint.27 lift-off', \
     'contact_states_peak.dat' using 1:56 with linespoints pt 7 lc rgb '#9f2fbf' title 'joint.28 stick', \
     'contact_states_peak.dat' using 1:57 with linespoints pt 4 dt 2 lc rgb '#9f2fbf' title 'joint.28 lift-off', \
     'contact_states_peak.dat' using 1:58 with linespoints pt 7 lc rgb '#bf8f1f' title 'joint.29 stick', \
     'contact_states_peak.dat' using 1:59 with linespoints pt 4 dt 2 lc rgb '#bf8f1f' title 'joint.29 lift-off', \
     'contact_states_peak.dat' using 1:60 with linespoints pt 7 lc rgb '#1f9fbf' title 'joint.30 stick', \
     'contact_states_peak.dat' using 1:61 with linespoints pt 4 dt 2 lc rgb '#1f9fbf' title 'joint.30 lift-off', \
     'contact_states_peak.dat' using 1:62 with linespoints pt 7 lc rgb '#7f7f7f' title 'joint.31 stick', \
     'contact_states_peak.dat' using 1:63 with linespoints pt 4 dt 2 lc rgb '#7f7f7f' title 'joint.31 lift-off', \
     'contact_states_peak.dat' using 1:64 with linespoints pt 7 lc rgb '#000000' title 'joint.32 stick', \
     'contact_states_peak.dat' using 1:65 with linespoints pt 4 dt 2 lc rgb '#000000' title 'joint.32 lift-off'
