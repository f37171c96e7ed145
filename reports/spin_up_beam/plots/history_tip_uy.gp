set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'history_tip_uy.svg'
set title 'Node set ''tip'': y displacement in the rotating frame (spin-up to 6 rad/s in 15 s)'
set xlabel 'time [s]'
set ylabel 'u_y [m]'
set grid
set key bottom right
plot 'history_tip_uy.dat' using 1:2 with lines lc rgb '#1f5fbf' title 'u_y', -1.35083617595e-10 with lines dt 2 lc rgb '#bf1f1f' title 'steady centrifugal deflection'
