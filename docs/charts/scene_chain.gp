set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set datafile separator ','
set key top left
set grid
set title 'Chain falling on a scale (Example 9.7)'
set xlabel 't [s]'
set ylabel 'N [N]'
plot 'docs/charts/scene_chain.csv' using 1:4 with lines lw 2 title 'momentum balance', \
     'docs/charts/scene_chain.csv' using 1:5 with lines lw 2 title '3xmg/L'
