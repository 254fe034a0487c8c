# fig1b_panel.gp - one Fig. 1b panel: the PCS sweep branches amp/h over s~
# with the free slider's 1 s averaged trajectory on top. Loaded by fig1b.gp
# and fig1b_pair.gp with: up, down (sweep CSVs), smooth (smooth.awk CSV of
# the free run), ends (its number of data rows: the end marker), ttl.
set title ttl
set xlabel 's = x_C / L   (PCS sweeps: the prescribed position)'
set ylabel 'amplitude of w(4L/7) / h'
set xrange [-0.005:0.505]
set yrange [0:*]
set grid
set key top left box opaque
set datafile separator ','
plot up every ::1 using 1:2 with linespoints lc rgb '#1f77b4' pt 7 ps 0.5 title 'PCS sweep up (from s = 0, from rest)', \
     down every ::1 using 1:2 with linespoints lc rgb '#d62728' pt 5 ps 0.5 title 'PCS sweep down (from s = 0.5, from rest)', \
     smooth every ::1 using 5:4 with lines lc rgb 'black' lw 2 title 'free slider, 1 s moving average', \
     smooth every ::1::1 using 5:4 with points lc rgb 'black' pt 6 ps 2 title 'free run: start (first 1 s average, t = 0.5 s)', \
     smooth using 5:4 every ::ends::ends with points lc rgb 'black' pt 9 ps 2 title 'free run: end (last 1 s average)'
