#!/bin/sh
# fig6_report.sh - the signature move of fig6 in numbers, five modes and one
# mode, double and float: turning point, jump, amplitudes before and after,
# final position; and the turning point's sensitivity to the numerics.
# Rewrites the tables between the fig6 markers in docs/validation.md. Run
# through `make fig6-report`.
#
# From the per-period CSV of `beamslider run --periods` (one row per
# excitation period: t, amp_h, s, ds):
#   turning point  min of s and its time
#   jump           first period whose amplitude exceeds 0.5 h (the low branch
#                  stays below 0.25 h, the high one above 0.7 h)
#   amp before     mean amplitude over [t_jump - 1.5 s, t_jump - 0.5 s]
#   amp after      mean amplitude over the last 10 s
#   walk back      mean ds per period over [t_jump + 1 s, t_jump + 5 s]
set -eu
DOC=${DOC:-docs/validation.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# the section's stamp (host/reports/provenance.sh), and a line saying it: at the top
# of the first table's markers (both tables are this command's)
. host/reports/provenance.sh
stamp=$(provenance_stamp "make fig6-report")

for marker in fig6-table fig6-sensitivity; do
    if ! grep -q "<!-- $marker -->" "$DOC"; then
        echo "fig6_report: $DOC has no <!-- $marker --> marker" >&2
        exit 1
    fi
done

json() { # json FIELD FILE
    sed -n "s/.*\"$1\":\"\{0,1\}\([^,\"}]*\).*/\1/p" "$2"
}

table="$stamp
$(provenance_text "$stamp")

| scene | precision | turning point s_min | at t [s] | jump at t [s] | jump at s | amp before jump [h] | amp last 10 s [h] | s after 60 s | walk back ds/period (1-5 s after jump) | wall [s] |
|---|---|---|---|---|---|---|---|---|---|---|
"
for scene in fig6 fig6_1mode; do
    for real in double float; do
        build/$real/beamslider run "configs/$scene.ini" --periods "$TMP/p.csv" > "$TMP/run.json"
        wall=$(json wall_s "$TMP/run.json")
        row=$(awk -F, -v scene="$scene" -v real="$real" -v wall="$wall" '
            NR == 1 { next }
            { t[NR] = $1; a[NR] = $2; s[NR] = $3; d[NR] = $4; n = NR }
            END {
                smin = 2; for (i = 2; i <= n; ++i) if (s[i] < smin) { smin = s[i]; tmin = t[i] }
                tj = -1; for (i = 2; i <= n && tj < 0; ++i) if (a[i] > 0.5) { tj = t[i]; sj = s[i] }
                if (tj < 0) { printf "| %s | %s | %.4f | %.2f | no jump | - | - | - | %.4f | - | %s |", scene, real, smin, tmin, s[n], wall; exit }
                for (i = 2; i <= n; ++i) {
                    if (t[i] >= tj - 1.5 && t[i] < tj - 0.5) { lo += a[i]; nlo++ }
                    if (t[i] >= t[n] - 10) { hi += a[i]; nhi++ }
                    if (t[i] >= tj + 1 && t[i] < tj + 5) { v += d[i]; nv++ }
                }
                printf "| %s | %s | %.4f | %.2f | %.2f | %.4f | %.3f | %.3f | %.4f | %+.2e | %s |", scene, real, smin, tmin, tj, sj, lo / nlo, hi / nhi, s[n], v / nv, wall
            }' "$TMP/p.csv")
        table="$table$row
"
        echo "fig6_report: $row" >&2
    done
done

# Sensitivity of the turning point to the numerics: 20 s runs of fig6 (the
# turn comes before 10 s).
printf '[scene]\nbase = %s/configs/fig6.ini\n[solver]\nmax_sweeps = 100000\ntol_rel = 1e-10\ntol_abs = 1e-14\n' \
    "$(pwd)" > "$TMP/tight.ini"
sensitivity="| variant (20 s of fig6) | turning point s_min | s at 20 s | amp last 25 periods [h] | max systems | unconverged steps |
|---|---|---|---|---|---|
"
variant() { # variant LABEL BINARY SCENE [OPTION...]
    label=$1
    bin=$2
    file=$3
    shift 3
    "$bin" run "$file" --t-end 20 "$@" > "$TMP/v.json"
    sensitivity="$sensitivity| $label | $(printf %.4f "$(json s_min "$TMP/v.json")") | \
$(printf %.4f "$(json s_final "$TMP/v.json")") | $(printf %.3f "$(json amp_final_h "$TMP/v.json")") | \
$(json max_systems "$TMP/v.json") | $(json unconverged_steps "$TMP/v.json") |
"
    echo "fig6_report: $label: s_min $(json s_min "$TMP/v.json")" >&2
}
variant "default (dt 2e-5, cap 2, tolerance 1e-5 / 1e-7 N s), double" build/double/beamslider configs/fig6.ini
variant "default, float" build/float/beamslider configs/fig6.ini
variant "dt = 1e-5 s" build/double/beamslider configs/fig6.ini --dt 1e-5
variant "dt = 5e-6 s" build/double/beamslider configs/fig6.ini --dt 5e-6
variant "cap 1 sweep (bounds only three or more contacts)" build/double/beamslider configs/fig6.ini --pgs-iters 1
variant "tolerance 1e-10 / 1e-14 N s, cap 100000" build/double/beamslider "$TMP/tight.ini"

# Replace what lies between each pair of markers.
awk -v table="$table" -v sensitivity="$sensitivity" '
    /<!-- fig6-table -->/ { print; printf "%s", table; skip = 1; next }
    /<!-- fig6-sensitivity -->/ { print; printf "%s", sensitivity; skip = 1; next }
    /<!-- \/fig6-(table|sensitivity) -->/ { skip = 0 }
    !skip { print }' "$DOC" > "$TMP/doc.md"
cp "$TMP/doc.md" "$DOC"
echo "fig6_report: updated $DOC" >&2
