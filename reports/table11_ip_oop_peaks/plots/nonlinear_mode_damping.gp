set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'nonlinear_mode_damping.svg'
set title 'Modal damping ratio of the nonlinear modes against the modal amplitude'
set logscale x
set format x '10^{%L}'
set xlabel 'modal amplitude [m kg^{1/2}]'
set ylabel 'damping ratio'
set grid
set key outside right
plot 'nonlinear_mode_damping.dat' index 0 using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'mode 1', \
     'nonlinear_mode_damping.dat' index 1 using 1:2 with lines lw 2 lc rgb '#bf1f1f' title 'mode 2'
