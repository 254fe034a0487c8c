# scenario.gp - a free run over its whole t_end: the envelope of w(4L/7)/h
# (per excitation period: +- half peak-to-peak) with its 1 s average, and s.
#   gnuplot -e "periods='..'; smooth='..'; ttl='..'; out='..'" scenario.gp
set terminal pngcairo size 1000,700 font 'sans,11'
set output out
set datafile separator ','
set multiplot title ttl
set lmargin at screen 0.1
set rmargin at screen 0.96
set origin 0, 0.47
set size 1, 0.47
set xlabel ''
set format x ''
set ylabel 'w(4L/7) / h'
set grid
set key top right box opaque
set offsets 0, 0, graph 0.3, 0
set arrow 1 from graph 0, first 0.25 to graph 1, first 0.25 nohead dt 2 lc rgb 'gray30'
set arrow 2 from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb 'gray30'
plot periods every ::1 using 1:(-$2):2 with filledcurves fc rgb '#9ecae1' title 'envelope: +- amplitude per excitation period', \
     smooth every ::1 using 1:4 with lines lc rgb 'black' lw 2 title 'amplitude, 1 s moving average (dashed: 0.25 h, 0.5 h)'
set origin 0, 0.02
set size 1, 0.47
set format x '%g'
set xlabel 't [s]'
set ylabel 's = x_C / L'
unset arrow
unset key
plot periods every ::1 using 1:3 with lines lc rgb '#d62728' lw 2
unset multiplot
