set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set datafile separator ','
set key top left
set grid
set title 'Sliding ladder (Example 9.2)'
set xlabel 't [s]'
set ylabel 'force [N]'
plot 'docs/charts/scene_ladder.csv' using 1:4 with lines lw 2 title 'N_w', \
     'docs/charts/scene_ladder.csv' using 1:5 with lines lw 2 title 'N_f'
