set terminal svg size 900,420 dynamic font 'Helvetica,12' background rgb 'white'
set output 'nonlinear_mode_backbones.svg'
set title 'Backbones of the nonlinear modes (EPMC) and the forced-response peaks'
set logscale y
set format y '10^{%L}'
set xlabel 'frequency [Hz]'
set ylabel 'amplitude [m]'
set grid
set key outside right
plot 'nonlinear_mode_backbones.dat' index 0 using 1:2 with lines lw 2 lc rgb '#1f5fbf' title 'mode 1 (IP component)' noenhanced, \
     'nonlinear_mode_backbones.dat' index 1 using 1:2 with lines lw 2 lc rgb '#bf1f1f' title 'mode 2 (OOP component)' noenhanced, \
     'nonlinear_mode_backbones.dat' index 2 using 1:2 with points pt 7 lc rgb '#000000' title 'sweep peaks'
