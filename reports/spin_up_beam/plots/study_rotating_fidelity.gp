set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_rotating_fidelity.svg'
set title 'Rotating scene: error of each model level against the finest vs cost (labels: level)'
set logscale xy
set format y '10^{%L}'
set xlabel 'wall time [s]'
set ylabel 'relative error'
set grid
set key outside right
set datafile missing 'nan'
plot 'study_rotating_fidelity.dat' index 0 using 1:2 with points pt 7 title 'steady deflection', 'study_rotating_fidelity.dat' index 0 using 1:2:(sprintf('%d', $3)) with labels offset 0,1 notitle, \
     'study_rotating_fidelity.dat' index 1 using 1:2 with points pt 5 title 'largest motion', \
     'study_rotating_fidelity.dat' index 2 using 1:2 with points pt 9 title 'first rotating frequency'
