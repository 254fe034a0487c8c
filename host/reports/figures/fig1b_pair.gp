# fig1b_pair.gp - Fig. 1b for two scenes side by side: variables up1, down1,
# smooth1, ends1, ttl1 (left) and up2, down2, smooth2, ends2, ttl2 (right), out.
set terminal pngcairo size 1600,650 font 'sans,11'
set output out
set multiplot layout 1,2
up = up1; down = down1; smooth = smooth1; ends = ends1; ttl = ttl1
load 'host/reports/figures/fig1b_panel.gp'
up = up2; down = down2; smooth = smooth2; ends = ends2; ttl = ttl2
load 'host/reports/figures/fig1b_panel.gp'
unset multiplot
