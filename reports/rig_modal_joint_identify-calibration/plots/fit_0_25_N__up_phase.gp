set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'fit_0_25_N__up_phase.svg'
set title '0.25 N, up: phase measured (points, 1 sigma) and computed'
set xlabel 'frequency [Hz]'
set ylabel 'phase [deg]'
set grid
set key outside right
set datafile missing 'nan'
plot 'fit_0_25_N__up_phase.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 0.5 lc rgb 'black' title 'measured', \
     'fit_0_25_N__up_phase.dat' index 1 using 1:2 with lines dt 2 lc rgb '#1f77b4' title 'start values', \
     'fit_0_25_N__up_phase.dat' index 2 using 1:2 with lines lw 2 lc rgb '#d62728' title 'identified'
