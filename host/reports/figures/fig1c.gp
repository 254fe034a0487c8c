# fig1c.gp - Fig. 1c: averaged slider velocity on the PCS model over s~ for
# both sweeps; the shaded band is the range of s the free run visits.
#   gnuplot -e "up='..'; down='..'; smin=..; smax=..; ttl='..'; out='..'" fig1c.gp
set terminal pngcairo size 1000,650 font 'sans,11'
set output out
set title ttl
set xlabel 's = x / L (the prescribed position of the PCS model)'
set ylabel 'v_{mean}: x_C displacement per period / L  [10^{-5}]   (+: toward the centre)'
set xrange [-0.005:0.505]
set grid
set key bottom left box opaque width 2
set datafile separator ','
set object 1 rectangle from smin, graph 0 to smax, graph 1 fillcolor rgb '#e8e8e8' fillstyle solid noborder behind
set label 1 'range of the free run' at (smin + smax) / 2, graph 0.96 center
plot 0 with lines lc rgb 'gray40' notitle, \
     up every ::1 using 1:($3 * 1e5) with linespoints lc rgb '#1f77b4' pt 7 ps 0.5 title 'PCS sweep up', \
     down every ::1 using 1:($3 * 1e5) with linespoints lc rgb '#d62728' pt 5 ps 0.5 title 'PCS sweep down'
