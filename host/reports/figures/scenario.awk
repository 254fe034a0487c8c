# scenario.awk - what a free run did, as shell assignments PREFIX_key=value
# (figures.sh sources them).
#
#   awk -F, -v prefix=P -v s0=S0 -f scenario.awk PERIODS.csv SMOOTH.csv
#
# From the per-period rows (raw) and their 1 s averages (smooth.awk); the
# thresholds are section 5's: the low branch stays below 0.25 h, the high one
# above 0.5 h (docs/validation.md section 7 lists these definitions):
#   s_min, s_max, s_final    extremes and last value of s (raw)
#   amp_last10               mean amplitude over the last 10 s
#   amp_avg_max              largest 1 s averaged amplitude
#   ups, downs               rises of the 1 s averaged amplitude above 0.5 h
#                            (from below 0.25 h or the start) and falls back
#                            below 0.25 h: one cycle is a rise and a fall
#   cycle_t                  mean time between successive rises [s]
#   drop_s, rise_s           largest retreat of the averaged s below its running
#                            maximum and above its running minimum: a monotone
#                            walk has one of them near 0
#   first_fall               how far the averaged s fell below s0 before the
#                            first rise (drift toward the clamp)
#   walk_back                how far it rose above its minimum after that rise
#   rest                     |change of the averaged s over the last 10 s|
function put(key, value) { printf "%s_%s='%s'\n", prefix, key, value }
FNR == 1 { f++; next }
f == 1 { np++; pt[np] = $1; pa[np] = $2; ps[np] = $3; next }
f == 2 { nm++; mt[nm] = $1; ma[nm] = $4; ms[nm] = $5; next }
END {
    smin = 2; smax = -1
    for (i = 1; i <= np; i++) {
        if (ps[i] < smin) smin = ps[i]
        if (ps[i] > smax) smax = ps[i]
        if (pt[i] >= pt[np] - 10) { la += pa[i]; nl++ }
    }
    high = 0; ups = downs = 0; amax = 0; t_first_up = -1
    run_max = run_min = ms[1]; drop_s = rise_s = 0; fall = 0; min_after = 2
    for (i = 1; i <= nm; i++) {
        if (ma[i] > amax) amax = ma[i]
        if (!high && ma[i] > 0.5) {
            high = 1; ups++
            if (ups == 1) t_first_up = mt[i]; else cycle_sum += mt[i] - t_last_up
            t_last_up = mt[i]
        } else if (high && ma[i] < 0.25) { high = 0; downs++ }
        if (ms[i] > run_max) run_max = ms[i]
        if (ms[i] < run_min) run_min = ms[i]
        if (run_max - ms[i] > drop_s) drop_s = run_max - ms[i]
        if (ms[i] - run_min > rise_s) rise_s = ms[i] - run_min
        if (ups == 0 && s0 - ms[i] > fall) fall = s0 - ms[i]
        if (ups >= 1 && ms[i] < min_after) min_after = ms[i]
        if (ups >= 1 && ms[i] - min_after > walk) walk = ms[i] - min_after
        if (mt[i] <= mt[nm] - 10) s_10 = ms[i]
    }
    put("s_min", sprintf("%.4f", smin)); put("s_max", sprintf("%.4f", smax)); put("s_final", sprintf("%.4f", ps[np]))
    put("t_end", sprintf("%.0f", pt[np]))
    put("amp_last10", sprintf("%.3f", la / nl)); put("amp_avg_max", sprintf("%.3f", amax))
    put("ups", ups); put("downs", downs); put("t_first_up", sprintf("%.1f", t_first_up))
    put("cycle_t", ups > 1 ? sprintf("%.1f", cycle_sum / (ups - 1)) : "-")
    put("drop_s", sprintf("%.4f", drop_s)); put("rise_s", sprintf("%.4f", rise_s))
    put("first_fall", sprintf("%.4f", fall)); put("walk_back", sprintf("%.4f", walk))
    put("rest", sprintf("%.4f", (ms[nm] - s_10) ^ 2 > 0 ? sqrt((ms[nm] - s_10) ^ 2) : 0))
}
