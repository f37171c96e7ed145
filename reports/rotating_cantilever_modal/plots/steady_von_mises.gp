set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'steady_von_mises.svg'
set title 'von Mises stress of the steady centrifugal deflection (nodal averages) [Pa]'
set view 55, 35, 1.4
set view equal xyz
set xyplane 0
set zlabel 'z [m]' rotate parallel
set pm3d depthorder
unset ztics
unset zlabel
set xlabel 'x [m]'
set ylabel 'y [m]'
set pm3d corners2color mean
set style fill solid noborder
set palette rgbformulae 22,13,-31
set format cb '%.3g'
unset key
splot 'steady_von_mises.dat' using 1:2:3:4 with pm3d
