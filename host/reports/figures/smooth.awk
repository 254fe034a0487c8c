# smooth.awk - 1 s centred moving average of a per-period CSV of
# `beamslider run --periods` (t, amp_h, s, ds; t is the end of the period).
#
#   awk -F, [-v window=1] -f smooth.awk PERIODS.csv > SMOOTH.csv
#
# Output columns t, amp_h, s, amp_avg, s_avg: amp_avg and s_avg are the means
# of amp_h and s over the periods with t' in [t - window/2, t + window/2].
# Only periods whose whole window lies inside the run are written, so every
# average covers the same time span.
BEGIN { if (window == "") window = 1.0 }
NR == 1 { next }
{ n++; t[n] = $1; a[n] = $2; s[n] = $3 }
END {
    print "t,amp_h,s,amp_avg,s_avg"
    lo = 1; hi = 0; sum_a = 0; sum_s = 0
    for (i = 1; i <= n; i++) {
        while (hi < n && t[hi + 1] <= t[i] + window / 2) { hi++; sum_a += a[hi]; sum_s += s[hi] }
        while (t[lo] < t[i] - window / 2) { sum_a -= a[lo]; sum_s -= s[lo]; lo++ }
        if (t[i] - window / 2 >= 0 && t[i] + window / 2 <= t[n])
            printf "%.6f,%.6e,%.9f,%.6e,%.9f\n", t[i], a[i], s[i], sum_a / (hi - lo + 1), sum_s / (hi - lo + 1)
    }
}
