# twin_rows.sh - sourced by the twin studies of host/reports (twin_report.sh,
# twin_ceiling_maps.sh, twin_step.sh, twin_fast.sh): where their plants' files
# go, how their plants are run, and statistics of a twin's estimate rows as
# `beamslider twin --out` writes them (t,s_hat,s_sigma,amplitude,power,y,y_hat,
# s_true,phase_error,s_error,...) after the first 5 s, as twin_report.sh reads
# them. Sourced, not run.

# work_dir: TMP, the plants' files: TWIN_REPORT_DIR if set (created if need
# be, kept), else a new temporary directory removed when the script exits
work_dir() {
    if [ -n "${TWIN_REPORT_DIR:-}" ]; then
        TMP=$TWIN_REPORT_DIR
        mkdir -p "$TMP"
    else
        TMP=$(mktemp -d)
        trap 'rm -rf "$TMP"' EXIT
    fi
}

# run_plants SCENE DIR SUFFIX [NAME=VALUE...]: the twin report's first PLANTS
# plants of SCENE (fig6 or fig8: its draws, seed = plant number) closed loop into
# DIR, JOBS at a time (twin_report.sh --plant with the environment NAME=VALUE...,
# e.g. TWIN_DT, and TWIN_REPORT_SIGNALS from the environment); with
# TWIN_REPORT_REUSE=1 a plant whose DIR/SCENE_K.SUFFIX is there
# is not run again
run_plants() {
    case $1 in
    fig6) _run="fig6 fig6 60 71e3" _drive="124 14" ;; # as twin_report.sh's plants
    fig8) _run="fig8 fig8 120 none" _drive="126 10" ;;
    *) echo "run_plants: no such scene of the twin report: $1" >&2; return 1 ;;
    esac
    mkdir -p "$2"
    _k=1
    while [ "$_k" -le "$PLANTS" ]; do
        if [ "${TWIN_REPORT_REUSE:-0}" != 1 ] || [ ! -s "$2/$1_$_k.$3" ]; then
            echo "$_run $_k $2 $_drive"
        fi
        _k=$((_k + 1))
    done > "$2/cases"
    _dir=$2
    shift 3
    [ ! -s "$_dir/cases" ] || env "$@" xargs -P "$JOBS" -L 1 sh host/reports/twin_report.sh --plant < "$_dir/cases"
}

# within FILE...: the fraction of the rows with |s_twin - s_plant| <= 0.005, to
# three digits; within_digits DIGITS FILE...: to DIGITS
within() {
    within_digits 3 "$@"
}
within_digits() {
    digits=$1
    shift
    awk -F, -v f="%.${digits}f" '$1 + 0 > 5 { d = $2 - $8; if (d < 0) d = -d; n++; if (d <= 0.005) w++ }
                                 END { printf f, n ? w / n : 0 }' "$@"
}

# branches FILE: "share bias within_high within_low": the share of the rows with the
# measured amplitude above 0.7 h (the high branch), there the mean of the measured
# s (s_hat + s_error) less the plant's, and the fraction within 0.005 on the high
# branch and on the low one (amplitude below 0.25 h; h = 1 mm)
branches() {
    awk -F, '$1 + 0 > 5 { n++; d = $2 - $8; if (d < 0) d = -d
                          if ($4 > 7e-4) { h++; b += $2 + $10 - $8; wh += d <= 0.005 }
                          else if ($4 < 2.5e-4) { l++; wl += d <= 0.005 } }
             END { printf "%.2f %+.4f %.3f %.3f", h / n, h ? b / h : 0, h ? wh / h : 0, l ? wl / l : 0 }' "$1"
}
