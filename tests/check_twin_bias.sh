#!/bin/sh
# check_twin_bias.sh - the observer's measured s on its own nominal plant
# (docs/twin.md, "Observer" 3-4; issue 30): fig6 for 60 s as `twin-plant`
# makes it (40 dB noise on both signals, 12 bits, seed 1) and the twin on it,
# commissioned as the twin report's third twin is (--deadband 0.001
# --position-gain 10 --position-rate 0.02). On the high branch's plateau (t >= 20 s, the twin's
# amplitude above 0.7 h) the s the observer measures, s_hat + s_error, has
# no mean bias beyond 0.0005 against the plant's s (before 0.8.0: +0.0023,
# +0.0016 of it the lock-in's, +0.0007 the map's). About 10 CPU-s: part of
# `make test-long` (twin-bias-long); tests/test_observer.c has the cheap
# version (a PCS plant held at a point of the map).
#
# usage, from the repository root:  sh tests/check_twin_bias.sh PATH/TO/beamslider

bin=${1:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_twin_bias.sh "$bin"

"$bin" twin-plant configs/fig6.ini --snr 40 --accel-snr 40 --bits 12 --seed 1 --out "$tmp/plant.csv" \
    >/dev/null 2>"$tmp/e"
check_status "twin-plant fig6 (60 s) exits 0" 0 $? "$tmp/e"
"$bin" twin configs/fig6.ini --measured "$tmp/plant.csv" --out "$tmp/est.csv" --every 50 --deadband 0.001 \
    --position-gain 10 --position-rate 0.02 >/dev/null 2>"$tmp/e"
check_status "twin on it exits 0" 0 $? "$tmp/e"
# t, s_hat, s_sigma, amplitude (columns 1-4), s_true (8), s_error (10)
awk -F, 'NR > 1 && $1 >= 20 && $4 > 7e-4 {
             n++; twin += $2 - $8
             if ($3 < 1) { m++; measured += $2 + $10 - $8 }
         }
         END { if (m < 30000) { printf "%d rows on the plateau, %d with s known\n", n, m; exit 1 }
               printf "%.6f %.6f %d\n", measured / m, twin / n, m }' "$tmp/est.csv" > "$tmp/bias" 2>&1
if [ $? -ne 0 ]; then
    fail "the plant reaches its high branch's plateau and the twin measures s there" "$(cat "$tmp/bias")"
else
    read -r measured twin rows < "$tmp/bias"
    if awk -v b="$measured" 'BEGIN { exit !(b <= 5e-4 && b >= -5e-4) }'; then
        pass "measured s - s_plant on the plateau: mean $measured over $rows estimates (twin s - s_plant $twin)"
    else
        fail "measured s - s_plant on the plateau: mean $measured, beyond 0.0005 (twin s - s_plant $twin)"
    fi
fi

echo "check_twin_bias: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
