# branches.awk - numbers of one scene's PCS sweeps and free run, as shell
# assignments PREFIX_key=value (figures.sh sources them).
#
#   awk -F, -v prefix=P -f branches.awk UP.csv DOWN.csv PERIODS.csv SMOOTH.csv
#
# UP/DOWN: `beamslider sweep` rows in sweep order (s, amp_h, v_mean, ...);
# PERIODS: `beamslider run --periods` (t, amp_h, s, ds); SMOOTH: smooth.awk.
#
# Definitions (docs/validation.md section 7 repeats them):
#   sweep jump    the largest |amp_h difference| between neighbouring grid
#                 points in sweep order, counted as a jump only when it exceeds
#                 a third of the sweep's amplitude range (max - min amp_h);
#                 reported as the two grid points (before, after)
#   window        grid points where the branches are distinct: from the down
#                 sweep's last point before its jump up to the up sweep's last
#                 point before its jump (or the grid's end); there the down
#                 sweep is the low branch and the up sweep the high branch
#   free jump     first excitation period whose amplitude exceeds 0.5 h (as in
#                 section 5: the low branch stays below 0.25 h there)
#   turning point minimum of s over the free run's periods
#   transport     signs of v_mean at the window's grid points inside the range
#                 of s the free run visits on that branch: the low branch
#                 before the free jump, the high branch after it
#   v zero        first grid point of the high branch (ascending s) where
#                 v_mean turns from positive to negative
#   follows       1 s averaged free run samples whose s_avg lies in the window,
#                 more than 0.5 s before / after the free jump: the fraction
#                 closer to the low branch (before) and to the high branch
#                 (after), both branches interpolated linearly at s_avg
function put(key, value) { printf "%s_%s='%s'\n", prefix, key, value }
function interp(ns, ss, aa, x,    i) {
    for (i = 1; i < ns; i++)
        if (ss[i] <= x && x <= ss[i + 1])
            return aa[i] + (aa[i + 1] - aa[i]) * (x - ss[i]) / (ss[i + 1] - ss[i])
    return aa[ns]
}
# the sweep f's jump: sets J_a, J_b (s before, after), J_da; returns 1 if a jump
function find_jump(f,    i, lo, hi, d, best) {
    lo = 1e9; hi = -1e9; best = 0
    for (i = 1; i <= n[f]; i++) { if (A[f, i] < lo) lo = A[f, i]; if (A[f, i] > hi) hi = A[f, i] }
    for (i = 2; i <= n[f]; i++) {
        d = A[f, i] - A[f, i - 1]
        if (d * d > best * best) { best = d; J_a = S[f, i - 1]; J_b = S[f, i]; J_ia = i - 1 }
    }
    J_da = best
    return best * best > (hi - lo) * (hi - lo) / 9
}
FNR == 1 { f++; next }
f <= 2 { n[f]++; S[f, n[f]] = $1; A[f, n[f]] = $2; V[f, n[f]] = $3; next }
f == 3 { np++; pt[np] = $1; pa[np] = $2; ps[np] = $3; next }
f == 4 { nm++; mt[nm] = $1; ma[nm] = $4; ms[nm] = $5; next }
END {
    # sweeps: jumps, amplitudes at the check points
    up_jump = find_jump(1); up_a = J_a; up_b = J_b
    put("up_jump", up_jump ? "yes" : "no"); put("up_jump_a", J_a); put("up_jump_b", J_b); put("up_jump_da", J_da)
    down_jump = find_jump(2); down_a = J_a; down_b = J_b
    put("down_jump", down_jump ? "yes" : "no"); put("down_jump_a", J_a); put("down_jump_b", J_b); put("down_jump_da", J_da)
    for (f = 1; f <= 2; f++)
        for (i = 1; i <= n[f]; i++)
            for (c = 1; c <= 4; c++)
                if ((S[f, i] - c / 10) ^ 2 < 1e-18)
                    put((f == 1 ? "up" : "down") "_amp_" c, sprintf("%.3f", A[f, i]))
    # branches in ascending s, for interpolation
    for (f = 1; f <= 2; f++)
        for (i = 1; i <= n[f]; i++) {
            k = S[f, n[f]] > S[f, 1] ? i : n[f] + 1 - i
            if (f == 1) { us[k] = S[f, i]; ua[k] = A[f, i]; uv[k] = V[f, i] }
            else { ds_[k] = S[f, i]; da[k] = A[f, i]; dv[k] = V[f, i] }
        }
    w_lo = down_jump ? down_a : 2; w_hi = up_jump ? up_a : us[n[1]]
    put("window", w_lo < w_hi ? "yes" : "no"); put("window_lo", w_lo); put("window_hi", w_hi)

    # free run: turning point, jump, range, final position
    smin = 2; smax = -1; tj = -1
    lo_min = hi_min = 2; lo_max = hi_max = -1   # s visited before / after the free jump
    for (i = 1; i <= np; i++) {
        if (ps[i] < smin) { smin = ps[i]; tmin = pt[i] }
        if (ps[i] > smax) smax = ps[i]
        if (tj < 0 && pa[i] > 0.5) { tj = pt[i]; sj = ps[i] }
        if (tj < 0) { if (ps[i] < lo_min) lo_min = ps[i]; if (ps[i] > lo_max) lo_max = ps[i] }
        else { if (ps[i] < hi_min) hi_min = ps[i]; if (ps[i] > hi_max) hi_max = ps[i] }
        if (pt[i] >= pt[np] - 10) { last_s += ps[i]; last_a += pa[i]; nlast++ }
    }
    put("s_min", sprintf("%.4f", smin)); put("t_min", sprintf("%.2f", tmin))
    put("s_max", sprintf("%.4f", smax)); put("t_end", sprintf("%.0f", pt[np]))
    put("free_jump", tj >= 0 ? "yes" : "no"); put("free_jump_t", sprintf("%.2f", tj)); put("free_jump_s", sprintf("%.4f", sj))
    put("s_last10", sprintf("%.4f", last_s / nlast)); put("amp_last10", sprintf("%.3f", last_a / nlast))

    # transport signs on each branch inside the visited range and the window
    lo_n = lo_p = hi_n = hi_p = 0; lo_list = hi_list = ""; vzero = ""
    for (k = 1; k <= n[1]; k++) {
        x = us[k]
        if (x < w_lo - 1e-9 || x > w_hi + 1e-9) continue
        if (vzero == "" && k > 1 && us[k - 1] >= w_lo - 1e-9 && uv[k - 1] > 0 && uv[k] <= 0)
            vzero = sprintf("%.3f-%.3f", us[k - 1], x)
        if (x >= lo_min - 1e-9 && x <= lo_max + 1e-9) {
            if (dv[k] < 0) lo_n++; else { lo_p++; lo_list = lo_list " " sprintf("%.3f", x) }
            lo_sum += dv[k]
        }
        if (x >= hi_min - 1e-9 && x <= hi_max + 1e-9) {
            if (uv[k] > 0) hi_p++; else { hi_n++; hi_list = hi_list " " sprintf("%.3f", x) }
            hi_sum += uv[k]
        }
    }
    put("low_range", sprintf("%.4f-%.4f", lo_min, lo_max)); put("high_range", sprintf("%.4f-%.4f", hi_min, hi_max))
    put("low_v_neg", lo_n); put("low_v_pos", lo_p); put("low_v_pos_at", substr(lo_list, 2))
    put("high_v_pos", hi_p); put("high_v_neg", hi_n); put("high_v_neg_at", substr(hi_list, 2))
    put("low_v_mean", lo_n + lo_p ? sprintf("%.2e", lo_sum / (lo_n + lo_p)) : "-")
    put("high_v_mean", hi_n + hi_p ? sprintf("%.2e", hi_sum / (hi_n + hi_p)) : "-")
    put("v_zero", vzero == "" ? "none" : vzero)

    # does the averaged free trajectory follow the branches?
    pre = pre_low = post = post_high = 0
    for (i = 1; i <= nm; i++) {
        x = ms[i]
        if (tj < 0 || x < w_lo || x > w_hi) continue
        low = interp(n[2], ds_, da, x); high = interp(n[1], us, ua, x)
        closer_low = (ma[i] - low) ^ 2 < (ma[i] - high) ^ 2
        if (mt[i] < tj - 0.5) { pre++; pre_low += closer_low }
        else if (mt[i] > tj + 0.5) { post++; post_high += !closer_low }
    }
    put("pre", pre); put("pre_low", pre ? sprintf("%.0f", 100 * pre_low / pre) : "-")
    put("post", post); put("post_high", post ? sprintf("%.0f", 100 * post_high / post) : "-")
}
