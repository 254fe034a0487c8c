# ensemble.gp - a scene's runs from several starts over its whole t_end: the 1 s
# averaged amplitude of w(4L/7)/h and s of each (smooth.awk's columns 4 and 5), the
# first file's run bold (the one the scene's own figure draws).
#   gnuplot -e "files='A.csv B.csv ...'; ttl='..'; out='..'" ensemble.gp
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
set ylabel 'amplitude / h (1 s average)'
set grid
unset key
set arrow 1 from graph 0, first 0.25 to graph 1, first 0.25 nohead dt 2 lc rgb 'gray30'
set arrow 2 from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb 'gray30'
n = words(files)
plot for [i = n:1:-1] word(files, i) every ::1 using 1:4 with lines \
         lc rgb (i == 1 ? 'black' : '#9ecae1') lw (i == 1 ? 2.5 : 1)
set origin 0, 0.02
set size 1, 0.47
set format x '%g'
set xlabel 't [s]'
set ylabel 's = x_C / L (1 s average)'
unset arrow
plot for [i = n:1:-1] word(files, i) every ::1 using 1:5 with lines \
         lc rgb (i == 1 ? '#d62728' : '#fcae91') lw (i == 1 ? 2.5 : 1)
unset multiplot
