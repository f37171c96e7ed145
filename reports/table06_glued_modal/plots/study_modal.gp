set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_modal.svg'
set title 'First-frequency error vs DOFs'
set logscale xy
set format y '10^{%L}'
set xlabel 'free DOFs'
set ylabel 'max relative error (vs finest hex20)'
set grid
set key outside right
plot 'study_modal.dat' index 0 using 1:2 with linespoints pt 7 title 'hex8', 'study_modal.dat' index 1 using 1:2 with linespoints pt 7 title 'hex8i', 'study_modal.dat' index 2 using 1:2 with linespoints pt 7 title 'hex20'
