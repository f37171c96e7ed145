set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'fit_OOP_peaks_amplitude.svg'
set title 'OOP peaks: amplitude measured (points, 1 sigma) and computed'
set xlabel 'force level [N]'
set ylabel 'amplitude per newton [m/N]'
set grid
set key outside right
set datafile missing 'nan'
set logscale x
plot 'fit_OOP_peaks_amplitude.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 0.6 lc rgb 'black' title 'measured', \
     'fit_OOP_peaks_amplitude.dat' index 0 using 1:4 with points pt 6 lc rgb '#1f77b4' title 'start values', \
     'fit_OOP_peaks_amplitude.dat' index 0 using 1:5 with points pt 9 ps 1.2 lc rgb '#d62728' title 'identified'
