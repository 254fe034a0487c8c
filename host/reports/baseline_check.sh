#!/bin/sh
# baseline_check.sh BASELINE - does a change keep the slow dynamics? Run through
# `make baseline-check [BASELINE=COMMIT]` (which builds this tree's beamslider in both
# precisions): docs/baseline.md.
#
# A change that moves the state hashes (tests/test_golden.c) changes every trajectory,
# and the contact dynamics are chaotic, so single runs cannot say whether it changed
# the physics. This compares ensembles instead: ENSEMBLE (default 512) runs of fig6
# over 60 s started 1e-5 L apart (s0 = 0.3 + 1e-5 k), of this tree and of the commit
# BASELINE (checked out and built in build/baseline/src), per precision, in:
#   low- and high-branch speed and settled amplitude (host/reports/speeds.sh): the
#       relative difference of the means with its 95 % confidence interval,
#       +-1.96 sqrt(se_this^2 + se_baseline^2) / mean_baseline (independent
#       ensembles); "within" when the whole interval lies within +-TOLERANCE (2 %);
#   unconverged contact steps per run (the JSON summary): the mean, this tree's no
#       larger than the baseline's.
# BASELINE "this": this tree's own build as the baseline, so that THIS_ARGS (run
# options of this tree's runs, e.g. "--set numerics.dt=4e-5 --set numerics.prewarp=on")
# is compared with the scene as it is (docs/baseline_prewarp.md).
set -eu
BASELINE=${1:?usage: baseline_check.sh COMMIT|this}
THIS_ARGS=${THIS_ARGS:-}
export THIS_ARGS
OUT=${OUT:-docs/baseline.md}
ENSEMBLE=${ENSEMBLE:-512}
TOLERANCE=${TOLERANCE:-2}
JOBS=${JOBS:-$(nproc)}
TMP=$(mktemp -d)
export TMP
trap 'rm -rf "$TMP"' EXIT
. host/reports/speeds.sh
# the page's stamp (host/reports/provenance.sh), naming the make line that made it
. host/reports/provenance.sh
make_line="make baseline-check BASELINE=$BASELINE$( [ "$OUT" = docs/baseline.md ] || printf " OUT=%s" "$OUT")$( [ -z "$THIS_ARGS" ] || printf " THIS_ARGS='%s'" "$THIS_ARGS")$( [ "$TOLERANCE" = 2 ] || printf " TOLERANCE=%s" "$TOLERANCE")"
stamp=$(provenance_stamp "$make_line")

# the baseline's tree and binaries (build/baseline/src, reused while it is the same commit)
if [ "$BASELINE" = this ]; then
    commit=$(git rev-parse HEAD)
    base_bin=.
else
    . host/reports/baseline_tree.sh
    commit=$(baseline_tree "$BASELINE")
    base_bin=build/baseline/src
fi

# ENSEMBLE starts x {this, baseline} x {double, float}, JOBS at a time
: > "$TMP/jobs"
k=0
while [ "$k" -lt "$ENSEMBLE" ]; do
    s0=$(awk -v k="$k" 'BEGIN { printf "%.5f", 0.3 + 1e-5 * k }')
    for real in double float; do
        echo "this-$real build/$real/beamslider $s0 this" >> "$TMP/jobs"
        echo "baseline-$real $base_bin/build/$real/beamslider $s0 baseline" >> "$TMP/jobs"
    done
    k=$((k + 1))
done
echo "baseline_check: $ENSEMBLE runs of 60 s per build and precision, $JOBS at a time" >&2
xargs -P "$JOBS" -L 1 sh -c 'name=$1; bin=$2; s0=$3; side=$4
    # shellcheck disable=SC2086
    "$bin" run configs/fig6.ini --t-end 60 --s0 "$s0" --periods "$TMP/$name-$s0.csv" $([ "$side" = this ] && echo $THIS_ARGS) \
        > "$TMP/$name-$s0.json"' sh < "$TMP/jobs"

# per build: "low high amp unconverged" per run, then means and standard errors
for name in this-double baseline-double this-float baseline-float; do
    for f in "$TMP"/$name-*.csv; do
        unconverged=$(sed -n 's/.*"unconverged_steps":\([0-9]*\).*/\1/p' "${f%.csv}.json")
        echo "$(speeds "$f") ${unconverged:?no summary for $f}"
    done > "$TMP/$name.txt"
    awk -v name=$name '{ for (i = 1; i <= 4; ++i) { m[i] += $i; q[i] += $i * $i } n++ }
        END { printf "%s", name
              for (i = 1; i <= 4; ++i) { mean = m[i] / n; v = (q[i] - n * mean * mean) / (n - 1); if (v < 0) v = 0
                                         printf " %.6e %.3e", mean, sqrt(v / n) }
              printf "\n" }' "$TMP/$name.txt" >> "$TMP/means"
done

# rows: quantity, baseline, this, difference and its 95 % interval, verdict
rows() { # rows REAL
    awk -v real=$1 -v tol=$TOLERANCE '
        { for (i = 2; i <= 9; ++i) v[$1, i] = $i }
        END {
            split("low-branch speed [1/s],high-branch speed [1/s],settled amplitude / h", label, ",")
            b = "baseline-" real; t = "this-" real
            for (q = 1; q <= 3; ++q) {
                mb = v[b, 2 * q]; sb = v[b, 2 * q + 1]; mt = v[t, 2 * q]; st = v[t, 2 * q + 1]
                d = 100 * (mt / mb - 1); h = 196 * sqrt(st * st + sb * sb) / mb
                ok = d - h >= -tol && d + h <= tol
                printf "| %s | %s | %.4e +- %.1e | %.4e +- %.1e | %+.2f %% | %+.2f .. %+.2f %% | %s |\n", real, label[q],
                    mb, sb, mt, st, d, d - h, d + h, ok ? "within" : "**outside**"
                if (!ok) fail = 1
            }
            printf "| %s | unconverged steps per run | %.2f +- %.2f | %.2f +- %.2f | | | %s |\n", real,
                v[b, 8], v[b, 9], v[t, 8], v[t, 9], v[t, 8] <= v[b, 8] ? "no more" : "**more**"
            if (v[t, 8] > v[b, 8]) fail = 1
            exit fail
        }' "$TMP/means"
}
status=0
double_rows=$(rows double) || status=1
float_rows=$(rows float) || status=1
verdict=$([ $status -eq 0 ] && echo "Every mean is within +-$TOLERANCE % of the baseline's at 95 % confidence, and no build leaves more steps unconverged." \
    || echo "**Not every quantity is within +-$TOLERANCE % of the baseline at 95 % confidence, or a build leaves more steps unconverged: see the rows marked.**")

cat > "$OUT" <<DOC
# Slow dynamics against a baseline

$stamp

Produced by \`$make_line\` (host/reports/baseline_check.sh) on
$(date -u +%Y-%m-%d), $ENSEMBLE runs per build and precision: this tree's build ($(build/double/beamslider --version | sed 's/, core precision.*//'))$( [ -z "$THIS_ARGS" ] || printf ", run with \`%s\`," "$THIS_ARGS")
against $( [ "$BASELINE" = this ] && echo "the same build running the scene as it is" || echo "commit $(git rev-parse --short "$commit") ($(git log -1 --format=%s "$commit" | cut -c1-60)...)").

A change to the contact solve or the detection moves every trajectory (the state hashes
of tests/test_golden.c), and the contact dynamics are chaotic, so what a change must
keep is statistical: the means over $ENSEMBLE runs of fig6 (60 s, dt 2e-5 s, the scene's
solver settings) started 1e-5 L apart, s0 = 0.3 + 1e-5 k, of the quantities
docs/accuracy.md uses: the drift speed on the low branch (s from 0.295 to 0.27), on the
high branch (0.27 to 0.32 after the jump) and the settled amplitude (20-30 s). Means with
their standard errors; the interval is the 95 % confidence interval of the relative
difference of the means.

| real | quantity | baseline | this tree | difference | 95 % interval | |
|---|---|---|---|---|---|---|
$double_rows
$float_rows

$verdict
DOC
echo "baseline_check: wrote $OUT" >&2
exit $status
