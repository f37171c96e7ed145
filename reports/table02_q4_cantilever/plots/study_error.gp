set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'study_error.svg'
set title 'Tip deflection error vs DOFs'
set logscale xy
set format y '10^{%L}'
set xlabel 'free DOFs'
set ylabel 'relative error'
set grid
set key outside right
plot 'study_error.dat' using 1:2 with linespoints pt 7 lc rgb '#bf1f1f' title 'vs Timoshenko beam', \
     'study_error.dat' using 1:($3 > 0 ? $3 : 1/0) with linespoints pt 5 lc rgb '#1f5fbf' title 'vs Richardson limit'
