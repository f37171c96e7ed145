set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'history_mid_ux.svg'
set title 'Node set ''mid'': x displacement in the rotating frame (constant speed 300 rad/s)'
set xlabel 'time [s]'
set ylabel 'u_x [m]'
set grid
set key bottom right
plot 'history_mid_ux.dat' using 1:2 with lines lc rgb '#1f5fbf' title 'u_x', -3.96418614662e-08 with lines dt 2 lc rgb '#bf1f1f' title 'steady centrifugal deflection'
