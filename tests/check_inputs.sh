#!/bin/sh
# check_inputs.sh - what beamslider reads (docs/robustness.md, "Files a
# command reads"; issue 26): counts derived from a record checked before
# anything is allocated, step means and schedule points checked before the
# run starts, files that are not regular files refused, no command writing
# over one of its inputs, the one measured-signals grammar read alike by
# `twin` and twin_pack, --set values with control characters. Each crafted
# input must exit 2 with a message naming what and where, create no output
# file and leave every input byte for byte as it was.
#
# usage, from the repository root:  sh tests/check_inputs.sh PATH/TO/beamslider [PATH/TO/twin_pack]

bin=${1:-}
pack=${2:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_inputs.sh "$bin"
precision=$("$bin" --version | sed -n 's/.*core precision \([a-z]*\).*/\1/p')

# refused DESCRIPTION MESSAGE OUTPUT INPUTS -- ARGS...: beamslider ARGS must
# exit 2 with MESSAGE on stderr, leave OUTPUT (a path; "-": none) uncreated
# and every one of INPUTS (space-separated paths) unchanged
refused() {
    description=$1 message=$2 output=$3 inputs=$4
    shift 5
    rm -rf "$tmp/before"
    mkdir "$tmp/before"
    n=0
    for f in $inputs; do n=$((n + 1)); cp "$f" "$tmp/before/$n" 2>/dev/null; done
    [ "$output" = - ] || rm -f "$output"
    "$bin" "$@" >"$tmp/o" 2>"$tmp/e"
    check_status "$description exits 2" 2 $? "$tmp/e"
    check_has "$description: message" "$tmp/e" "$message"
    n=0 changed=
    [ "$output" != - ] && [ -e "$output" ] && changed=" (the output $output exists)"
    for f in $inputs; do
        n=$((n + 1))
        cmp -s "$f" "$tmp/before/$n" || changed="$changed $f"
    done
    if [ -z "$changed" ]; then pass "$description: no output, inputs unchanged"; else fail "$description: no output, inputs unchanged" "changed:$changed"; fi
}

head_csv='# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n'
out=$tmp/out.csv

# ---- counts from a record: checked in double before any integer or allocation
printf '# beamslider base acceleration\n# sample_rate = 1.0842027145865592e-14 Hz\n# unit = m/s^2\n1\n2\n3\n' \
    >"$tmp/wrap.csv"
refused "a rate whose step count wraps" "$tmp/wrap.csv:2: sample_rate 1.0842e-14 Hz is out of range; allowed: 0.001 .. 1e+10 Hz" \
    "$out" "$tmp/wrap.csv" -- run configs/fig6.ini --excitation "$tmp/wrap.csv" --out "$out"
printf '# beamslider base acceleration\n# sample_rate = 4.9e-324 Hz\n# unit = m/s^2\n1\n2\n3\n' >"$tmp/denormal.csv"
refused "a denormal rate" "$tmp/denormal.csv:2: sample_rate 4.94066e-324 Hz is out of range" \
    "$out" "$tmp/denormal.csv" -- run configs/fig6.ini --excitation "$tmp/denormal.csv" --out "$out"
printf '# beamslider base acceleration\n# sample_rate = 1000 Hz\n# t0 = -1e300 s\n# unit = m/s^2\n1\n2\n' >"$tmp/t0.csv"
refused "t0 = -1e300 s" "$tmp/t0.csv:3: t0 -1e+300 s is out of range; allowed: -1e+09 .. 1e+09 s" \
    "$out" "$tmp/t0.csv" -- run configs/fig6.ini --excitation "$tmp/t0.csv" --out "$out"
printf '# beamslider base acceleration\n# sample_rate = 0.001 Hz\n# unit = m/s^2\n1\n2\n3\n' >"$tmp/long.csv"
refused "a record of more than 2^53 steps" "more than 2^53 steps of dt = 1e-13 s" \
    "$out" "$tmp/long.csv" -- run configs/fig6.ini --excitation "$tmp/long.csv" --set numerics.dt=1e-13 --out "$out"

# ---- step means the core cannot take: refused before the run, naming step and lines
printf "$head_csv"'1e308\n-1e308\n1e308\n' >"$tmp/alternating.csv"
refused "alternating +-1e308" "$tmp/alternating.csv: step 1 (t = 0 .. 2e-05 s) reads lines 4 .. 5" \
    "$out" "$tmp/alternating.csv" -- run configs/fig6.ini --excitation "$tmp/alternating.csv" --out "$out"
printf '# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = g\n1\n1e308\n' >"$tmp/g.csv"
refused "1e308 g" "$tmp/g.csv:5: 1e+308 g is inf m/s^2" \
    "$out" "$tmp/g.csv" -- run configs/fig6.ini --excitation "$tmp/g.csv" --out "$out"
# a float WAV holding FLT_MAX, read with --scale 1e300
printf 'RIFF\054\000\000\000WAVEfmt \020\000\000\000\003\000\001\000\350\003\000\000\240\017\000\000\004\000\040\000data\010\000\000\000\000\000\200\077\377\377\177\177' \
    >"$tmp/flt_max.wav"
refused "--scale 1e300 on FLT_MAX" "$tmp/flt_max.wav: sample 1 (from 0; channel 1) times --scale 1e+300 is beyond the range of double" \
    "$out" "$tmp/flt_max.wav" -- run configs/fig6.ini --excitation "$tmp/flt_max.wav" --scale 1e300 --out "$out"
if [ "$precision" = float ]; then
    printf "$head_csv"'1e38\n1e38\n1e38\n' >"$tmp/large.csv"
    refused "means beyond float's range" "$tmp/large.csv: step 1 (t = 0 .. 2e-05 s) reads lines 4 .. 5, whose mean base acceleration is 1e+38 m/s^2: beyond the core's range; allowed: a finite mean within +-8.50706e+37 m/s^2" \
        "$out" "$tmp/large.csv" -- run configs/fig6.ini --excitation "$tmp/large.csv" --out "$out"
fi

# ---- schedule points: checked when the scene is built, as frequency and acceleration are
cp configs/mssp2023.ini "$tmp/mssp2023.ini"
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\nschedule = 0:124:14, 0.5:30000:14\n[run]\ns0 = 0.3\nt_end = 0.001\n' \
    >"$tmp/nyquist.ini"
refused "a schedule point above 1/(2 dt)" "$tmp/nyquist.ini:6: [excitation] schedule point 2: frequency 30000 Hz is out of range at dt = 2e-05 s; allowed: 5.421011e-15 <= f < 25000 Hz" \
    "$out" "$tmp/nyquist.ini $tmp/mssp2023.ini" -- run "$tmp/nyquist.ini" --out "$out"
refused "a denormal schedule frequency" "--set excitation.schedule=0:1e-320:14: [excitation] schedule point 1: frequency 9.99989e-321 Hz is out of range" \
    "$out" "" -- run configs/fig6.ini --set excitation.schedule=0:1e-320:14 --t-end 0.001 --out "$out"
refused "a schedule amplitude beyond the core's range" "[excitation] schedule point 1: amplitude 1e+308 m/s^2 is out of range; allowed: 0 .. " \
    "$out" "" -- run configs/fig6.ini --set excitation.schedule=0:100:1e308 --t-end 0.001 --out "$out"
refused "twin-plant on a schedule point above 1/(2 dt)" "$tmp/nyquist.ini:6: [excitation] schedule point 2" \
    "$out" "" -- twin-plant "$tmp/nyquist.ini" --out "$out"

echo "check_inputs: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
