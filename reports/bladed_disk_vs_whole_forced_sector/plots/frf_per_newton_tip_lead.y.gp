set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'frf_per_newton_tip_lead.y.svg'
set title 'Response tip_lead.y per newton at each force level, with the linear limits'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude / Fe [m/N]'
set grid
set key outside right
plot 'frf_per_newton_tip_lead.y.dat' index 0 using 1:2 with lines lc rgb '#1f5fbf' title 'Fe = 0.1 N', \
     'frf_per_newton_tip_lead.y.dat' index 1 using 1:2 with lines lc rgb '#bf1f1f' title 'Fe = 0.5 N', \
     'frf_per_newton_tip_lead.y.dat' index 2 using 1:2 with lines lc rgb '#2f9f2f' title 'Fe = 1 N', \
     'frf_per_newton_tip_lead.y.dat' index 3 using 1:2 with lines lc rgb '#9f2fbf' title 'Fe = 2 N', \
     'frf_per_newton_tip_lead.y.dat' index 4 using 1:2 with lines lc rgb '#bf8f1f' title 'Fe = 3 N', \
     'frf_per_newton_tip_lead.y.dat' index 5 using 1:2 with lines lc rgb '#1f9fbf' title 'Fe = 5 N', \
     'frf_per_newton_tip_lead.y.dat' index 6 using 1:2 with lines lc rgb '#7f7f7f' title 'Fe = 10 N', \
     'frf_per_newton_tip_lead.y.dat' index 7 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' title 'free (no damper)', \
     'frf_per_newton_tip_lead.y.dat' index 7 using 1:3 with lines lw 2 dt 3 lc rgb '#000000' title 'stuck (eq 3.51)'
