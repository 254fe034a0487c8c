# fig1b.gp - Fig. 1b: gnuplot -e "up='..'; down='..'; smooth='..'; ends=N; ttl='..'; out='..'" fig1b.gp
set terminal pngcairo size 1000,650 font 'sans,11'
set output out
load 'host/reports/figures/fig1b_panel.gp'
