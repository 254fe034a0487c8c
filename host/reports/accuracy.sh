#!/bin/sh
# accuracy.sh - error of the core against the independent double-precision
# reference (host/reference), against host run time: docs/accuracy.md and
# docs/figures/work_precision.png. Run through `make accuracy`.
#
# Reference: build/bs-reference (contact problems solved exactly), at
# dt = 2e-5 s with 4 substeps (5e-6 s) unless said otherwise.
# Metrics of a core run, against the reference run of the same scene:
#   w error      RMS and max of w(4L/7) - w_ref over the first 0.05 s, on the
#                grid of 8e-5 s that every step size hits, relative to
#                max |w_ref| over that window
#   speeds       drift speed of s on the low branch (time to cross
#                s = 0.295 -> 0.27, toward the clamp) and on the high branch
#                (0.27 -> 0.32, back toward the centre), and the settled
#                amplitude (mean per-period amplitude / h over 20-30 s), of a
#                30 s run, relative to the reference at dt 5e-6 s (fig6: the
#                mean of an ensemble; fig6_1mode: one run)
#   cost         host wall time per simulated second (the 30 s run, one core)
# Sweeps: dt in DTS = {5e-6, 1e-5, 2e-5, 4e-5, 8e-5} s, float and double, fig6
# (five modes) and fig6_1mode, at the contact-solve caps CAPS (default 2: the cap
# bounds only solves of three or more contacts, which these scenes never have,
# docs/design.md 6, so other caps give the same runs). ENSEMBLE runs (default 8)
# for the default settings' comparison; FD_ENSEMBLE runs per build (default 512)
# for float against double.
set -eu
OUT=${OUT:-docs/accuracy.md}
FIG=${FIG:-docs/figures/work_precision.png}
JOBS=${JOBS:-$(nproc)}
ENSEMBLE=${ENSEMBLE:-8}
REF=build/bs-reference
TMP=$(mktemp -d)
export TMP
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$(dirname "$FIG")"
# the page's and the figure's stamp (host/reports/provenance.sh)
. host/reports/provenance.sh
stamp=$(provenance_stamp "make accuracy")

json() { sed -n "s/.*\"$1\":\"\{0,1\}\([^,\"}]*\).*/\1/p" "$2"; }

# speeds PERIODS -> "low high amp" (host/reports/speeds.sh)
. host/reports/speeds.sh

# w_error REF CORE -> "rms max" relative to max |w_ref| (matched on t)
w_error() {
    awk -F, 'FNR == 1 { next }
        NR == FNR { ref[sprintf("%.6f", $1)] = $2; if ($2 > m) m = $2; if (-$2 > m) m = -$2; next }
        { key = sprintf("%.6f", $1); if (key in ref) { d = $2 - ref[key]; s += d * d; n++; if (d < 0) d = -d; if (d > mx) mx = d } }
        END { if (n && m > 0) printf "%.3e %.3e\n", sqrt(s / n) / m, mx / m; else print "nan nan" }' "$1" "$2"
}

# --- reference runs --------------------------------------------------------
for scene in fig6 fig6_1mode; do
    echo "accuracy: reference $scene" >&2
    $REF run "configs/$scene.ini" --t-end 0.05 --substeps 4 --out "$TMP/ref-$scene-w.csv" --every 4 > /dev/null
done
$REF run configs/fig6_1mode.ini --t-end 30 --substeps 4 --periods "$TMP/ref-fig6_1mode-p.csv" > /dev/null

# --- the default settings: ensembles ----------------------------------------
# A single run's speeds scatter by several percent (the contact dynamics are
# chaotic), so the default settings are compared as means over ENSEMBLE runs
# started 1e-5 L apart, with their standard errors.
: > "$TMP/ensemble-jobs"
k=0
while [ "$k" -lt "$ENSEMBLE" ]; do
    s0=$(awk -v k="$k" 'BEGIN { printf "%.5f", 0.3 + 1e-5 * k }')
    echo "ref-fine $REF $s0 --substeps 4" >> "$TMP/ensemble-jobs"
    echo "ref-coarse $REF $s0" >> "$TMP/ensemble-jobs"
    echo "double build/double/beamslider $s0" >> "$TMP/ensemble-jobs"
    echo "float build/float/beamslider $s0" >> "$TMP/ensemble-jobs"
    k=$((k + 1))
done
echo "accuracy: ensembles of $ENSEMBLE" >&2
xargs -P "$JOBS" -L 1 sh -c 'name=$1; bin=$2; s0=$3; shift 3;
    "$bin" run configs/fig6.ini --t-end 30 --s0 "$s0" --periods "$TMP/ens-$name-$s0.csv" "$@" > /dev/null 2>&1' sh \
    < "$TMP/ensemble-jobs"
ensemble_rows=""
: > "$TMP/ensemble-means"
for name in ref-fine ref-coarse double float; do
    for f in "$TMP"/ens-$name-*.csv; do speeds "$f"; done > "$TMP/ens-$name.txt"
    set -- $(awk '{ for (i = 1; i <= 3; ++i) { m[i] += $i; q[i] += $i * $i } n++ }
        END { for (i = 1; i <= 3; ++i) { mean = m[i] / n; v = q[i] / n - mean * mean; if (v < 0) v = 0
                                          printf "%.4e %.1e ", mean, sqrt(v) / sqrt(n) } }' "$TMP/ens-$name.txt")
    echo "$name $1 $3 $5" >> "$TMP/ensemble-means"
    case $name in
        ref-fine) label="reference, dt 5e-6 s" ;;
        ref-coarse) label="reference, dt 2e-5 s" ;;
        *) label="core $name, dt 2e-5 s, cap 2" ;;
    esac
    ensemble_rows="$ensemble_rows| $label | $1 +- $2 | $3 +- $4 | $5 +- $6 |
"
done
verdicts=$(awk '{ for (i = 2; i <= 4; ++i) v[$1, i] = $i }
    function row(label, a, b,   i) { printf "| %s |", label; for (i = 2; i <= 4; ++i) printf " %+.1f %% |", 100 * (v[a, i] / v[b, i] - 1); printf "\n" }
    END { row("core double vs reference at dt 2e-5 s", "double", "ref-coarse")
          row("core double vs reference at dt 5e-6 s", "double", "ref-fine")
          row("core float vs reference at dt 2e-5 s", "float", "ref-coarse")
          row("core float vs reference at dt 5e-6 s", "float", "ref-fine")
          row("reference dt 2e-5 s vs 5e-6 s", "ref-coarse", "ref-fine")
          row("core float vs core double (dt 2e-5 s)", "float", "double") }' "$TMP/ensemble-means")
# the acceptance of the accuracy issue: float at the default settings within 2 %
# of the reference at the same dt; and float against double (ensembles)
acceptance=$(awk '{ for (i = 2; i <= 4; ++i) v[$1, i] = $i }
    function worst(a, b,   i, d, w) { w = 0; for (i = 2; i <= 4; ++i) { d = v[a, i] / v[b, i] - 1; if (d < 0) d = -d; if (d > w) w = d }; return 100 * w }
    function pct(a, b, i) { return 100 * (v[a, i] / v[b, i] - 1) }
    END { printf "The float build at the default settings differs from the reference at the same dt by at most %.1f %% in the three quantities (%s the 2 %% of the accuracy issue); from the double build by at most %.1f %%, which these few runs cannot resolve against 2 %% (their standard errors are of the order of a percent; the section \"Float against double\" below does it with many runs).\n\n", \
                 worst("float", "ref-coarse"), worst("float", "ref-coarse") <= 2 ? "within" : "**outside**", \
                 worst("float", "double")
          printf "The error the default settings carry against the converged model (the reference at dt 5e-6 s) is %+.1f %%, %+.1f %% and %+.1f %% (low-branch speed, high-branch speed, amplitude; core float). For comparison, the time discretisation alone, the reference'"'"'s own change from dt 5e-6 to 2e-5 s: %+.1f %%, %+.1f %% and %+.1f %%.", \
                 pct("float", "ref-fine", 2), pct("float", "ref-fine", 3), pct("float", "ref-fine", 4), \
                 pct("ref-coarse", "ref-fine", 2), pct("ref-coarse", "ref-fine", 3), pct("ref-coarse", "ref-fine", 4) }' "$TMP/ensemble-means")

# what single runs are compared with: fig6 the fine ensemble, fig6_1mode one fine run
awk '$1 == "ref-fine" { print "fig6", $2, $3, $4 }' "$TMP/ensemble-means" > "$TMP/reference-speeds"
echo "fig6_1mode $(speeds "$TMP/ref-fig6_1mode-p.csv")" >> "$TMP/reference-speeds"

# --- the sweep of step sizes (and caps), REPEATS starts each, in parallel ------
REPEATS=${REPEATS:-4}
for scene in fig6 fig6_1mode; do
    for real in double float; do
        for dt in ${DTS:-5e-6 1e-5 2e-5 4e-5 8e-5}; do
            for cap in ${CAPS:-2}; do
                k=0
                while [ "$k" -lt "$REPEATS" ]; do
                    echo "$scene $real $dt $cap $(awk -v k="$k" 'BEGIN { printf "%.5f", 0.3 + 1e-5 * k }')"
                    k=$((k + 1))
                done
            done
        done
    done
done > "$TMP/jobs"
echo "accuracy: $(wc -l < "$TMP/jobs") configurations" >&2
xargs -P "$JOBS" -L 1 sh -c 'every=$(awk -v dt="$3" "BEGIN { printf \"%d\", 8e-5 / dt + 0.5 }");
        tag="$1-$2-$3-$4-$5"; bin=build/$2/beamslider;
        "$bin" run "configs/$1.ini" --dt "$3" --pgs-iters "$4" --s0 "$5" --t-end 0.05 --out "$TMP/$tag-w.csv" --every "$every" > /dev/null 2>&1 || true;
        "$bin" run "configs/$1.ini" --dt "$3" --pgs-iters "$4" --s0 "$5" --t-end 30 --periods "$TMP/$tag-p.csv" > "$TMP/$tag.json" 2> /dev/null || true' sh < "$TMP/jobs"

rows=""
: > "$TMP/points"
while read -r scene real dt cap s0; do
    tag="$scene-$real-$dt-$cap-$s0"
    status=$(json status "$TMP/$tag.json")
    capname=$([ "$cap" = 100000 ] && echo none || echo "$cap")
    if [ "$status" != ok ]; then
        rows="$rows| $scene | $real | $dt | $capname | $s0 | - | - | - | - | - | - | $status |
"
        continue
    fi
    cost=$(awk -v w="$(json wall_s "$TMP/$tag.json")" 'BEGIN { printf "%.4f", w / 30 }')
    set -- $(w_error "$TMP/ref-$scene-w.csv" "$TMP/$tag-w.csv") $(speeds "$TMP/$tag-p.csv")
    errors=$(awk -v low="$3" -v high="$4" -v amp="$5" -v scene="$scene" '$1 == scene {
            printf "%s %s %s\n", (low > 0 && $2 > 0) ? sprintf("%+.3f", low / $2 - 1) : "-",
                   (high > 0 && $3 > 0) ? sprintf("%+.3f", high / $3 - 1) : "-",
                   (amp > 0 && $4 > 0) ? sprintf("%+.4f", amp / $4 - 1) : "-" }' "$TMP/reference-speeds")
    set -- "$1" "$2" $errors
    rows="$rows| $scene | $real | $dt | $capname | $s0 | $1 | $2 | $3 | $4 | $5 | $cost | ok, $(json unconverged_steps "$TMP/$tag.json") unconverged |
"
    [ "$4" != - ] && echo "$scene $real $dt $capname $cost $4 $5" >> "$TMP/points"
    [ "$dt" = 2e-5 ] && echo "$scene $real $(json unconverged_steps "$TMP/$tag.json") $(json max_systems "$TMP/$tag.json")" >> "$TMP/solves"
done < "$TMP/jobs"

# Pareto front per scene on cost and |high-branch speed error|.
pareto=$(awk '{ e = $6 < 0 ? -$6 : $6; c[NR] = $5; err[NR] = e; sc[NR] = $1; line[NR] = $0 }
    END { for (i = 1; i <= NR; ++i) { dom = 0
              for (j = 1; j <= NR; ++j)
                  if (j != i && sc[j] == sc[i] && c[j] <= c[i] && err[j] <= err[i] && (c[j] < c[i] || err[j] < err[i])) { dom = 1; break }
              if (!dom) { split(line[i], f, " "); printf "| %s | %s | %s | %s | %s | %s | %s |\n", f[1], f[2], f[3], f[4], f[5], f[6], f[7] } } }' \
    "$TMP/points" | sort -t'|' -k2,2 -k6,6g)

# Per scene and dt: the median error and cost over the starts and both
# precisions, and the Cortex-M4F cost implied by the float build's mean
# estimated cycles per step (pessimistic, constants in flash) over the whole run
# at dt 2e-5 s (docs/embedded.md; the cost per step barely depends on dt, the
# contacts do).
m4f() { # the default core's whole-run mean cycles in docs/embedded.md ("Whole runs"), by column name
    awk -F'|' -v s="$1" 'function cell(i,   x) { x = $i; gsub(/ /, "", x); return x }
        /^$/ { split("", col) }
        /^\| scene \| target \|/ { for (i = 2; i < NF; ++i) col[cell(i)] = i; next }
        ("meancycles:pessimistic" in col) && cell(col["scene"]) == s && cell(col["target"]) == "cortex-m4f" \
            && cell(col["real"]) == "float" && cell(col["variant"]) == "flash" { print cell(col["meancycles:pessimistic"]); exit }' docs/embedded.md
}
by_dt=""
for scene in fig6 fig6_1mode; do
    cycles=$(m4f "$scene")
    for dt in ${DTS:-5e-6 1e-5 2e-5 4e-5 8e-5}; do
        by_dt="$by_dt$(awk -v s="$scene" -v dt="$dt" -v cycles="${cycles:-0}" '
            function median(a, n,   i, j, t) { for (i = 2; i <= n; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
                                              return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
            $1 == s && $3 == dt && $4 != 1 && ($2 == "float" || $2 == "double") { e = $6 < 0 ? -$6 : $6; m = $7 < 0 ? -$7 : $7; err[++n] = e; amp[n] = m; cost[n] = $5 }
            END { if (!n) exit
                  m4 = cycles > 0 ? sprintf("%.0f M (%.0f %% of 168 MHz)", cycles / dt / 1e6, 100 * cycles / dt / 168e6) : "-"
                  printf "| %s | %s | %.1f %% | %.1f %% | %.4f | %s |\n", s, dt, 100 * median(err, n), 100 * median(amp, n), median(cost, n), m4 }' "$TMP/points")
"
    done
done

share_fig6=$(awk -v cycles="$(m4f fig6)" 'BEGIN { printf "%.0f", 100 * cycles / 2e-5 / 168e6 }')
share_1mode=$(awk -v cycles="$(m4f fig6_1mode)" 'BEGIN { printf "%.0f", 100 * cycles / 2e-5 / 168e6 }')

# the contact solve at dt 2e-5 s: unconverged steps and the most systems in a step
solve_verdict=$(awk '{ runs++; u += $3; if ($4 > m) m = $4 }
    END { printf "At dt 2e-5 s the %d runs of 30 s (1.5e6 steps each; fig6 and fig6_1mode, both precisions) leave %d contact steps unconverged in all, and no step needs more than %d active-set systems.", runs, u, m }' "$TMP/solves")

# --- float against double: a larger ensemble ---------------------------------
# Single runs scatter by several percent, so whether float reproduces the
# double build's drift within 2 % needs many runs: FD_ENSEMBLE runs of each
# build (s0 = 0.3 + 1e-5 k), the difference of the means with twice its
# standard error.
FD_ENSEMBLE=${FD_ENSEMBLE:-512}
k=0
while [ "$k" -lt "$FD_ENSEMBLE" ]; do
    s0=$(awk -v k="$k" 'BEGIN { printf "%.5f", 0.3 + 1e-5 * k }')
    echo "double $s0"; echo "float $s0"
    k=$((k + 1))
done > "$TMP/fd-jobs"
echo "accuracy: float against double, $FD_ENSEMBLE runs each" >&2
xargs -P "$JOBS" -L 1 sh -c 'build/$1/beamslider run configs/fig6.ini --t-end 30 --s0 "$2" --periods "$TMP/fd-$1-$2.csv" > /dev/null 2>&1' sh \
    < "$TMP/fd-jobs"
for real in double float; do
    for f in "$TMP"/fd-$real-*.csv; do echo "$real $(speeds "$f")"; done
done > "$TMP/fd-speeds"
fd_rows=$(awk '{ n[$1]++; for (i = 2; i <= 4; ++i) { m[$1, i] += $i; q[$1, i] += $i * $i } }
    END { split("low-branch speed,high-branch speed,settled amplitude", name, ",")
          for (i = 2; i <= 4; ++i) {
              for (b = 1; b <= 2; ++b) { r = b == 1 ? "double" : "float"
                  mean[r] = m[r, i] / n[r]; v = (q[r, i] - n[r] * mean[r] * mean[r]) / (n[r] - 1); se[r] = sqrt(v > 0 ? v : 0) / sqrt(n[r]) }
              d = 100 * (mean["float"] / mean["double"] - 1)
              e = 100 * sqrt(se["float"] ^ 2 + se["double"] ^ 2) / mean["double"]
              ad = d < 0 ? -d : d
              verdict = ad + 2 * e <= 2 ? "within 2 %" : (ad - 2 * e > 2 ? "**outside** 2 %" : "not resolved: the interval straddles 2 %")
              printf "| %s | %.4e +- %.1e | %.4e +- %.1e | %+.2f %% +- %.2f %% | %s |\n", name[i - 1], mean["double"], se["double"], mean["float"], se["float"], d, 2 * e, verdict } }' "$TMP/fd-speeds")

# --- long runs: 60 s and 600 s, float against double -------------------------
long_rows=""
for real in double float; do
    for t_end in 60 600; do
        build/$real/beamslider run configs/fig6.ini --t-end "$t_end" --periods "$TMP/long.csv" > "$TMP/long.json"
        set -- $(speeds "$TMP/long.csv") $(awk -F, 'NR > 1 { t[NR] = $1; a[NR] = $2; s[NR] = $3; n = NR; if (!s10 && $1 >= 10) s10 = $3 }
            END { for (i = 2; i <= n; ++i) if (t[i] >= t[n] - 10) { h += a[i]; nh++ }; printf "%.4f %.4f %.4f\n", h / nh, s10, s[n] }' "$TMP/long.csv")
        long_rows="$long_rows| $real | $t_end | $1 | $2 | $4 | $5 | $6 | $(json wall_s "$TMP/long.json") |
"
        echo "$real $t_end $1 $2" >> "$TMP/long-speeds"
    done
done
long_verdict=$(awk '{ low[$1, $2] = $3; high[$1, $2] = $4 }
    function pct(a, b) { return 100 * (a / b - 1) }
    function verdict(t,   l, h) { l = pct(low["float", t], low["double", t]); h = pct(high["float", t], high["double", t])
                                 return sprintf("%+.1f %% and %+.1f %% at %s s (%s 2 %%)", l, h, t, (l < 0 ? -l : l) <= 2 && (h < 0 ? -h : h) <= 2 ? "within" : "**outside**") }
    END { printf "Float against double, low- and high-branch speed: %s; %s. These are single runs, which scatter by several percent; the section \"Float against double\" above measures the difference with many runs.", verdict(60), verdict(600) }' "$TMP/long-speeds")

# --- figure -------------------------------------------------------------------
for series in "fig6 double" "fig6 float" "fig6_1mode double" "fig6_1mode float"; do
    set -- $series
    awk -v s="$1" -v r="$2" '$1 == s && $2 == r { e = $6 < 0 ? -$6 : $6; if (e < 1e-4) e = 1e-4; print $5, e }' \
        "$TMP/points" > "$TMP/series-$1-$2.dat"
done
gnuplot <<GP
set terminal pngcairo size 900,600
set output "$FIG"
set logscale xy
set xlabel "host time per simulated second [s] (one core)"
set ylabel "|high-branch drift speed error| (vs the reference at dt 5e-6 s)"
set title "Work-precision: fig6 and fig6_1mode, dt 5e-6 ... 8e-5 s, $REPEATS starts each"
set key outside right
set grid
plot "$TMP/series-fig6-double.dat" with points pt 7 title "5 modes, double", \
     "$TMP/series-fig6-float.dat" with points pt 5 title "5 modes, float", \
     "$TMP/series-fig6_1mode-double.dat" with points pt 9 title "1 mode, double", \
     "$TMP/series-fig6_1mode-float.dat" with points pt 11 title "1 mode, float"
GP

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
provenance_figures "$stamp" "$FIG"
cat > "$OUT" <<DOC
# Accuracy

$stamp

Produced by \`make accuracy\` (host/reports/accuracy.sh) on $(date -u +%Y-%m-%d), commit $commit.
The oracle is \`build/bs-reference\` (tests/reference/), a double-precision implementation of
docs/model.md written independently of core/ (dense matrices, closed-form mode shapes in long
double, contact problems solved exactly; tests/reference/README.md says how it is tested).
Metrics are defined in host/reports/accuracy.sh's header: **w error** is the RMS and max of
w(4L/7) - w_ref over the first 0.05 s relative to max |w_ref|; the **slow quantities** are
the slider's drift speed on the low branch (toward the clamp) and on the high branch (back
toward the centre), each measured as the time to cross a stretch of s, and the settled
amplitude; **cost** is host wall time per simulated second on one core.

Why these: the dynamics are chaotic. Contact events amplify differences of the order of
the contact solve's tolerance, so two correct runs part after a few tens of milliseconds
(the w error over 0.05 s mostly measures that: the core and the reference agree to 1e-8
over the first 0.02 s, tests/check_accuracy.sh), and near the turning point the slider
stalls until a fluctuation tips it onto the high branch (docs/validation.md 5), so two
correct runs can jump seconds apart. Quantities compared at fixed times would measure that
timing; speeds over a stretch of s and a settled amplitude are properties of the model and
the numerics. They still scatter from run to run (the ensembles below show how much), so
the default settings are compared as ensemble means, and single-run differences below that
scatter say nothing.

## The default settings against the reference

fig6, dt = 2e-5 s, contact-solve cap 2, each figure the mean +- standard error over
$ENSEMBLE runs started 1e-5 L apart (speeds in 1/s: change of s per second):

| run | low-branch speed | high-branch speed | settled amplitude [h] |
|---|---|---|---|
$ensemble_rows
| comparison | low-branch speed | high-branch speed | settled amplitude |
|---|---|---|---|
$verdicts

$acceptance

## Work-precision

![work-precision](figures/work_precision.png)

Each point is one 30 s run (scene, precision, dt, one of $REPEATS starts 1e-5 L apart); its
error is the high-branch drift speed against the reference at dt 5e-6 s. Runs that no
other beats in both cost and that error, per scene (single runs: errors below a few
percent are within the run-to-run scatter):

| scene | build | dt [s] | cap | cost [s/s] | high-branch speed error | amplitude error |
|---|---|---|---|---|---|---|
$pareto

Single runs scatter, so the front above is ragged; per step size, medians over the
$REPEATS starts and both precisions are steadier. The last column is the cost on a Cortex-M4F:
the float build's mean estimated cycles per step over the whole 60 s run at dt 2e-5 s
(pessimistic, constants in flash; docs/embedded.md, "Whole runs") divided by dt, as a share
of a 168 MHz clock:

| scene | dt [s] | median high-branch speed error | median amplitude error | median cost [s/s] | Cortex-M4F cycles per simulated second (estimated) |
|---|---|---|---|---|---|
$by_dt
**For a digital twin** we recommend the defaults, dt = 2e-5 s, in float (the contact
solve's cap does not enter: next section). The step: the time discretisation dominates the error, so a smaller dt
lowers it (medians above) at proportionally more cost, and from 4e-5 s on the high-branch
speed is off by 10 % and more. The board: the last column is a mean; the five-mode scene
at 2e-5 s asks for $share_fig6 % of a 168 MHz Cortex-M4F's cycles by the pessimistic
estimate, and the worst steps cost several times the mean (docs/embedded.md), so on an
M4F $(awk -v p="$share_fig6" 'BEGIN { print (p < 100 ? "it keeps pace on average, a FIFO of samples absorbing the worst steps (docs/embedded.md: the largest backlog of a whole run)" : "it does not run in real time at this step") }'); a 480 MHz Cortex-M7 has the room (by its
instruction count). The one-mode scene is cheaper ($share_1mode % of the M4F at 2e-5 s), but it
is a different model (turning point, docs/validation.md); its rows compare single runs with
a single reference run, so their errors carry the whole run-to-run scatter.

## The contact solve

One and two contacts, all the contact steps of these scenes, are solved exactly by the
active-set method with a bounded number of systems (docs/design.md 6); the sweep cap
\`max_sweeps\` bounds only solves of three or more contacts (two corners and a clamp stop,
a preloaded slot), so it no longer enters this report (0.5.0 swept it here: with
subspace steps after capped sweeps, the cap of 2 left about 16 steps per 60 s fig6 run
unconverged). $solve_verdict Against 0.5.0 the slow dynamics agree within 2 % at 95 %
confidence over 512-run ensembles (docs/baseline.md).

## Float against double

The accuracy issue asks that float reproduce the double build's transport velocity
within 2 %. A single run cannot show that (next section), so: $FD_ENSEMBLE runs of fig6 per
build at the default settings, started 1e-5 L apart, 30 s each; means with standard
errors, and the float-double difference with twice its standard error (about a 95 %
interval):

| quantity | double | float | float vs double | 2 % |
|---|---|---|---|---|
$fd_rows

## Long runs: float against double

Single runs of fig6. The excitation phase stays exact (tests/test_sim.c checks it after
3e6 and 3e7 steps) and the slow drift of x_C is accumulated without float bias
(docs/model.md 9.2; tests/test_sim.c). Speeds as above; amplitude: the last 10 s.

| build | t_end [s] | low-branch speed | high-branch speed | amplitude, last 10 s [h] | s at 10 s | s at t_end | wall [s] |
|---|---|---|---|---|---|---|---|
$long_rows
$long_verdict

## All configurations

Errors relative to the reference at dt 5e-6 s (signed; "-": the run did not cross the
stretch within 30 s).

| scene | build | dt [s] | cap | s0 | w RMS | w max | low-branch speed | high-branch speed | settled amplitude | cost [s/s] | status |
|---|---|---|---|---|---|---|---|---|---|---|---|
$rows
DOC
echo "accuracy: wrote $OUT and $FIG" >&2
