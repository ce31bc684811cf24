set terminal pngcairo size 900,500 font 'DejaVu Sans,11'
set datafile separator ','
set key top left
set grid
set title 'Ideal rocket with gravity (§9.4)'
set xlabel 't [s]'
set ylabel 'v [m/s]'
plot 'docs/charts/scene_rocket.csv' using 1:4 with lines lw 2 title 'simulated', \
     'docs/charts/scene_rocket.csv' using 1:5 with lines lw 2 title '-u_eln(m_r/m_0) - g t'
