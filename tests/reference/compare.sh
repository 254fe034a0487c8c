#!/bin/sh
# compare.sh - core (build/beamslider) against the reference (build/bs-reference).
#
#   sh tests/reference/compare.sh CORE_BIN REF_BIN SCENE.ini [T_END] [T_WAVE] [EXTRA_REF_OPTIONS...]
#       runs both on SCENE for T_END seconds (default 10) with --periods and for
#       T_WAVE seconds (default 0.05) with --out --every 1, then prints both reports.
#   sh tests/reference/compare.sh --periods A.csv B.csv
#       turning point and amplitudes of two per-period CSVs (t,amp_h,s,ds).
#   sh tests/reference/compare.sh --steps A.csv B.csv [T_WAVE]
#       RMS and max difference of w_sensor of two steps CSVs (--every 1) over
#       t <= T_WAVE, with the first times the difference exceeds 1e-9 m and 1e-6 m.
#
# Needs only POSIX sh and awk. Outputs of the run mode stay in ${TMPDIR:-/tmp}/bs-compare.$$.
set -eu

periods_report() {
    # $1: per-period CSV, $2: label
    awk -F, -v label="$2" '
        NR == 1 { next }
        { n++; t[n] = $1; a[n] = $2; s[n] = $3
          if (n == 1 || $3 < smin) { smin = $3; tmin = $1 } }
        END {
            if (n == 0) { printf "%-10s no periods\n", label; exit }
            k = n < 25 ? n : 25; sum = 0
            for (i = n - k + 1; i <= n; i++) sum += a[i]
            # 1 s windows (docs/model.md 7): mean amplitude before and after the turning point
            lo = 0; ln = 0; hi = 0; hn = 0
            for (i = 1; i <= n; i++) {
                if (t[i] > tmin - 1 && t[i] <= tmin) { lo += a[i]; ln++ }
                if (t[i] > t[n] - 1) { hi += a[i]; hn++ }
            }
            printf "%-10s periods %d  t_end %.4f  s_final %.6f  turning point s_min %.6f at t %.3f  amp_h last 25 periods %.4f  amp_h 1 s before turn %.4f  last 1 s %.4f\n",
                   label, n, t[n], s[n], smin, tmin, sum / k, ln ? lo / ln : 0, hn ? hi / hn : 0
        }' "$1"
}

steps_report() {
    # $1, $2: steps CSVs; $3: t limit
    awk -F, -v tmax="$3" '
        FNR == 1 { next }
        NR == FNR { w[$1] = $2; next }
        ($1 in w) && $1 + 0 <= tmax + 1e-12 {
            d = $2 - w[$1]; if (d < 0) d = -d
            n++; ss += d * d; ref2 += $2 * $2
            if (d > max) { max = d; tmaxd = $1 }
            if (d > 1e-9 && t9 == "") t9 = $1
            if (d > 1e-6 && t6 == "") t6 = $1
        }
        END {
            if (n == 0) { print "no common rows"; exit 1 }
            printf "w_sensor over t <= %g s (%d common rows): RMS difference %.3e m, max %.3e m at t %s; RMS of w %.3e m; first |dw| > 1e-9 m at t %s, > 1e-6 m at t %s\n",
                   tmax, n, sqrt(ss / n), max, tmaxd, sqrt(ref2 / n), t9 == "" ? "never" : t9, t6 == "" ? "never" : t6
        }' "$1" "$2"
}

case "${1:-}" in
--periods)
    periods_report "$2" A
    periods_report "$3" B
    ;;
--steps)
    steps_report "$2" "$3" "${4:-0.05}"
    ;;
""|-h|--help)
    sed -n '2,14p' "$0"
    exit 2
    ;;
*)
    core=$1 ref=$2 scene=$3
    t_end=${4:-10}
    t_wave=${5:-0.05}
    shift 3
    [ $# -gt 0 ] && shift
    [ $# -gt 0 ] && shift
    dir=${TMPDIR:-/tmp}/bs-compare.$$
    mkdir -p "$dir"
    "$core" run "$scene" --t-end "$t_end" --periods "$dir/core_periods.csv" > "$dir/core.json" 2>/dev/null
    "$ref" run "$scene" --t-end "$t_end" --periods "$dir/ref_periods.csv" "$@" > "$dir/ref.json"
    "$core" run "$scene" --t-end "$t_wave" --out "$dir/core_steps.csv" --every 1 > /dev/null 2>&1
    "$ref" run "$scene" --t-end "$t_wave" --out "$dir/ref_steps.csv" --every 1 "$@" > /dev/null
    echo "core:      $(cat "$dir/core.json")"
    echo "reference: $(cat "$dir/ref.json")"
    periods_report "$dir/core_periods.csv" core
    periods_report "$dir/ref_periods.csv" reference
    steps_report "$dir/core_steps.csv" "$dir/ref_steps.csv" "$t_wave"
    echo "(files in $dir)"
    ;;
esac
