set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set datafile separator ','
set key top left
set grid
set title 'Two-ball bounce (Example 9.6)'
set xlabel 't [s]'
set ylabel 'height [m]'
plot 'docs/charts/scene_bounce.csv' using 1:2 with lines lw 2 title 'y_1', \
     'docs/charts/scene_bounce.csv' using 1:4 with lines lw 2 title 'y_2'
