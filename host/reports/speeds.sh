# speeds.sh - sourced by the reports that measure the slow dynamics of fig6.
#
# speeds PERIODS -> "low high amp" from the per-period CSV of a run (beamslider
# run --periods): the drift speed of s on the low branch (time to cross
# s = 0.295 -> 0.27, toward the clamp) and on the high branch (0.27 -> 0.32,
# back toward the centre, after the jump: amplitude above 0.5 h), and the
# settled amplitude (mean per-period amplitude / h over 20-30 s); 0 where the
# run does not cross a stretch.
speeds() {
    awk -F, 'NR > 1 { t = $1; s = $3; a = $2
            if (!d1 && s <= 0.295) d1 = t; if (!d2 && s <= 0.27) d2 = t
            if (a > 0.5 && !j) j = t
            if (j && !w1 && s >= 0.27) w1 = t; if (j && !w2 && s >= 0.32) w2 = t
            if (t >= 20 && t < 30) { h += a; nh++ } }
        END { printf "%.6e %.6e %.6f\n", (d2 > d1 ? 0.025 / (d2 - d1) : 0), (w2 > w1 ? 0.05 / (w2 - w1) : 0), nh ? h / nh : 0 }' "$1"
}

