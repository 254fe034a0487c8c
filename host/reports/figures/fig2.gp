# fig2.gp - Fig. 2b/2c: relative slider rotation beta + alpha(x_C) over a few
# excitation periods of a PCS sweep point (`beamslider sweep --trace`), the
# sensor signal for the phase, and which slot corners are in contact
# (contacts bit mask: bit 0..3 = P1..P4; P1, P4 top corners, P2, P3 bottom).
#   gnuplot -e "trace='..'; ttl='..'; out='..'" fig2.gp
set terminal pngcairo size 1000,800 font 'sans,11'
set output out
set datafile separator ','
set multiplot title ttl
set lmargin at screen 0.12
set rmargin at screen 0.96
set xrange [0:*]
set autoscale xfix
set grid
unset key
set origin 0, 0.5
set size 1, 0.44
set format x ''
set ylabel 'beta + alpha(x_C)  [mrad]'
plot trace every ::1 using 1:($6 * 1e3) with lines lc rgb 'black' lw 2
set origin 0, 0.28
set size 1, 0.24
set ylabel 'w(4L/7) / h'
plot trace every ::1 using 1:3 with lines lc rgb '#1f77b4' lw 1.5
set origin 0, 0.02
set size 1, 0.28
set format x '%g'
set xlabel 'excitation periods (from the start of the recorded periods)'
set ylabel 'in contact'
set yrange [0.5:4.5]
set ytics ('P1' 1, 'P2' 2, 'P3' 3, 'P4' 4)
plot for [c = 1:4] trace every ::1 using 1:((int($7) & (1 << (c - 1))) ? c : NaN) with points pt 7 ps 0.35 lc c
unset multiplot
