set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'von_mises.svg'
set title 'von Mises stress (nodal averages) [Pa]'
set view map
set size ratio -1
unset ztics
unset zlabel
set format x '%.3g'
set format y '%.3g'
set xtics nomirror rotate by 90 right
set ytics nomirror
set xtics 2
set xlabel 'x [m]'
set ylabel 'y [m]'
set pm3d corners2color mean
set style fill solid noborder
set palette rgbformulae 22,13,-31
set format cb '%.3g'
unset key
splot 'von_mises.dat' using 1:2:3:4 with pm3d
