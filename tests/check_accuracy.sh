#!/bin/sh
# check_accuracy.sh REFERENCE - the regression subset of `make accuracy`: each
# line of tests/accuracy_thresholds runs the core (build/REAL/beamslider) and
# the reference on the same scene and step for t_end seconds, every step
# written, and requires the largest difference of w(4L/7), relative to the
# largest |w| of the reference, to stay within the threshold.
ref=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
checked=0
while read -r scene real t_end limit; do
    case $scene in ''|'#'*) continue ;; esac
    build/$real/beamslider run "configs/$scene.ini" --t-end "$t_end" --out "$tmp/core.csv" > /dev/null || exit 1
    "$ref" run "configs/$scene.ini" --t-end "$t_end" --out "$tmp/ref.csv" > /dev/null || exit 1
    error=$(awk -F, 'FNR == 1 { next } NR == FNR { w[FNR] = $2; if ($2 > m) m = $2; if (-$2 > m) m = -$2; next }
        { d = $2 - w[FNR]; if (d < 0) d = -d; if (d > e) e = d } END { printf "%.3e", e / m }' "$tmp/ref.csv" "$tmp/core.csv")
    if awk -v e="$error" -v l="$limit" 'BEGIN { exit !(e <= l) }'; then
        echo "ok   $scene $real, first $t_end s: max |w - w_ref| / max |w_ref| = $error (limit $limit)"
    else
        echo "FAIL $scene $real, first $t_end s: max |w - w_ref| / max |w_ref| = $error (limit $limit)"
        failed=1
    fi
    checked=$((checked + 1))
done < tests/accuracy_thresholds
echo "check_accuracy: $checked checked"
[ "$failed" -eq 0 ] && [ "$checked" -gt 0 ]
