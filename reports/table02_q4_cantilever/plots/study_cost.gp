set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_cost.svg'
set title 'Cost vs DOFs'
set logscale xy
set xlabel 'free DOFs'
set ylabel 'wall time [s]'
set grid
set key outside right
plot 'study_cost.dat' using 1:2 with linespoints pt 7 title 'assembly', \
     'study_cost.dat' using 1:3 with linespoints pt 5 title 'factorization + solve'
