set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set datafile separator ','
set key top left
set grid
set title 'Ballistic pendulum (Example 9.5)'
set xlabel 't [s]'
set ylabel 'theta [rad]'
plot 'docs/charts/scene_pendulum.csv' using 1:2 with lines lw 2 title 'theta'
