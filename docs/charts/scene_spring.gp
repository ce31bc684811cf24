set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set datafile separator ','
set key top left
set grid
set title 'Two masses and a spring (Example 9.3)'
set xlabel 't [s]'
set ylabel 'position [m]'
plot 'docs/charts/scene_spring.csv' using 1:2 with lines lw 2 title 'x_1', \
     'docs/charts/scene_spring.csv' using 1:3 with lines lw 2 title 'x_2', \
     'docs/charts/scene_spring.csv' using 1:4 with lines lw 2 title 'x_G'
