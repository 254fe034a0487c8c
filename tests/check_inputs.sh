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
limit= # a FIFO must be refused at once: a regression would block, so bound every refusal
if command -v timeout >/dev/null 2>&1; then limit="timeout 30"; fi
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
    $limit "$bin" "$@" >"$tmp/o" 2>"$tmp/e"
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

# ---- the measured-signals format: one grammar, one reader. The same malformed
# streams to `beamslider twin` and to twin_pack: both refuse each with the same
# line and the same reason (exit 2, no output, the stream unchanged)
"$bin" twin-plant configs/fig6.ini --out "$tmp/good.csv" --t-end 0.004 --snr 40 >/dev/null 2>"$tmp/e"
check_status "twin-plant of 0.004 s exits 0" 0 $? "$tmp/e"
good=$tmp/good.csv
mutate() { # NAME SED-SCRIPT: $tmp/m_NAME.csv from the good stream
    sed "$2" "$good" >"$tmp/m_$1.csv"
}
mutate title '1s/.*/# beamslider signals/'
mutate rate_twice '3a\
# sample_rate = 50000 Hz'
mutate khz 's/^# sample_rate = 50000 Hz$/# sample_rate = 50 kHz/'
mutate unknown_key 's/^# sample_rate = /# sampel_rate = /'
mutate spaced_key 's/^# sample_rate = /# sample rate = /'
mutate noise_unitless 's/^\(# noise = [^ ]*\) m$/\1/'
mutate noise_volts 's/^\(# noise = [^ ]*\) m$/\1 V/'
mutate signal 's/^# signal = deflection$/# signal = velocity/'
mutate no_signal '/^# signal = /d'
mutate columns 's/^t,base_accel,signal,s_true$/t,accel,signal,s_true/'
mutate nan '14s/,[^,]*,/,nan,/'
mutate gap '16d'
mutate five '17s/$/,1/'
mutate empty '18s/.*//'
mutate late_comment '19s/^/# /'
mutate late '20s/^[^,]*,/0.00022,/'
mutate no_rows '11,$d'
awk 'NR == 15 { printf "%s,", $0; for (i = 0; i < 600; ++i) printf "0"; print ""; next } { print }' "$good" >"$tmp/m_long.csv"
{ head -n 14 "$good"; printf '2.8e-04,1,\000,0.3\n'; tail -n +16 "$good"; } >"$tmp/m_nul.csv"
for f in "$tmp"/m_*.csv; do
    name=$(basename "$f" .csv)
    cp "$f" "$tmp/before.csv"
    rm -f "$tmp/est.csv" "$tmp/packed.stream"
    "$bin" twin configs/fig6.ini --measured "$f" --out "$tmp/est.csv" >/dev/null 2>"$tmp/e_twin"
    status_twin=$?
    cp "$tmp/e_twin" "$tmp/e_twin_$name"
    check_status "twin on $name exits 2" 2 $status_twin "$tmp/e_twin"
    if grep -q -F "$f" "$tmp/e_twin"; then pass "twin on $name names the file"; else fail "twin on $name names the file" "$(cat "$tmp/e_twin")"; fi
    if [ -e "$tmp/est.csv" ] || ! cmp -s "$f" "$tmp/before.csv"; then fail "twin on $name: no output, stream unchanged"
    else pass "twin on $name: no output, stream unchanged"; fi
    if [ -n "$pack" ]; then
        "$pack" "$f" "$tmp/packed.stream" 2>"$tmp/e_pack"
        check_status "twin_pack on $name exits 2" 2 $? "$tmp/e_pack"
        sed 's/^beamslider: error: //' "$tmp/e_twin" >"$tmp/why_twin"
        sed 's/^twin_pack: //' "$tmp/e_pack" >"$tmp/why_pack"
        if cmp -s "$tmp/why_twin" "$tmp/why_pack"; then pass "twin and twin_pack refuse $name alike: $(head -c 160 "$tmp/why_twin")"
        else fail "twin and twin_pack refuse $name alike" "twin: $(cat "$tmp/why_twin")
twin_pack: $(cat "$tmp/why_pack")"; fi
        if [ -e "$tmp/packed.stream" ]; then fail "twin_pack on $name writes no stream"; else pass "twin_pack on $name writes no stream"; fi
    fi
done
for what in "khz:m_khz.csv:3: sample_rate must be a finite number followed by Hz, not '50 kHz'" \
            "rate_twice:m_rate_twice.csv:4: sample_rate given twice (first at line 3)" \
            "unknown_key:m_unknown_key.csv:3: unknown header field 'sampel_rate' (known: sample_rate, signal, signal_unit, base_accel_unit, latency, noise, accel_noise, plant)" \
            "spaced_key:m_spaced_key.csv:3: a header line with '=' is a field" \
            "noise_volts:m_noise_volts.csv:8: noise is given in V, but signal = deflection is in m" \
            "gap:m_gap.csv:16: t = 0.00014 s, expected 0.00012 s (row 6 at sample_rate = 50000 Hz): a gap" \
            "nul:m_nul.csv:15: a NUL byte: not a text file"; do
    name=m_${what%%:*}
    check_has "the reason for $name" "$tmp/e_twin_$name" "${what#*:}"
done

# ---- twin --measured -: a live stream on standard input, read once. What
# these check is the reading, not the tracking: the twin's map is designed at
# 10 kHz (five steps a period), 0.05 s of design instead of 1.7 s at the
# scene's 124 Hz (15 s under the sanitizers) for each run that gets that far.
fast_maps="--map-frequencies 10000"
"$bin" twin configs/fig6.ini $fast_maps --measured - --out "$tmp/est_stdin.csv" <"$good" >"$tmp/stdin.json" 2>"$tmp/e"
check_status "twin --measured - exits 0 at the end of its input" 0 $? "$tmp/e"
check_has "... and its summary counts the rows read" "$tmp/stdin.json" '"rows":200,'
"$bin" twin configs/fig6.ini $fast_maps --measured "$good" --out "$tmp/est_file.csv" >/dev/null 2>"$tmp/e"
if cmp -s "$tmp/est_file.csv" "$tmp/est_stdin.csv"; then pass "standard input and the file give the same estimates"
else fail "standard input and the file give the same estimates"; fi
sed '/^# noise = /d' "$good" >"$tmp/quiet.csv"
"$bin" twin configs/fig6.ini --measured - --out "$tmp/est_quiet.csv" <"$tmp/quiet.csv" >/dev/null 2>"$tmp/e"
check_status "twin --measured - without a noise exits 2" 2 $? "$tmp/e"
check_has "... saying to give --noise" "$tmp/e" "give --noise SIGMA or a '# noise = ...' header line"
sed '20s/,[^,]*,/,x,/' "$good" | "$bin" twin configs/fig6.ini $fast_maps --measured - --out "$tmp/est_bad.csv" >/dev/null 2>"$tmp/e"
check_status "a bad row on standard input exits 2" 2 $? "$tmp/e"
check_has "... naming its line" "$tmp/e" "standard input:20: base_accel 'x' is not a finite number"
awk 'NR == 3 { printf "#"; for (i = 0; i < 600; ++i) printf " "; print "."; next } { print }' "$good" \
    | "$bin" twin configs/fig6.ini --measured - --out "$tmp/est_long.csv" >/dev/null 2>"$tmp/e"
check_status "a line over 511 characters on standard input exits 2" 2 $? "$tmp/e"
check_has "... naming its line" "$tmp/e" "standard input:3: longer than 511 characters"
cat "$good" | "$bin" twin configs/fig6.ini --measured /dev/stdin --out "$tmp/est_dev.csv" >/dev/null 2>"$tmp/e"
check_status "--measured /dev/stdin on a pipe exits 2" 2 $? "$tmp/e"
check_has "... saying to use -" "$tmp/e" "/dev/stdin: cannot read measured-signals file: a FIFO (named pipe), not a regular file (a live stream: give --measured - and send it to standard input)"
if mkfifo "$tmp/fifo" 2>/dev/null; then
    refused "--measured FIFO" "$tmp/fifo: cannot read measured-signals file: a FIFO (named pipe), not a regular file (a live stream: give --measured -" \
        "$out" "" -- twin configs/fig6.ini --measured "$tmp/fifo" --out "$out"
fi

# ---- no command writes over one of its inputs: compared as files (device and
# inode), through symbolic and hard links, before anything is truncated
awk 'BEGIN { print "# beamslider base acceleration"; print "# sample_rate = 50000 Hz"; print "# unit = m/s^2"
             for (k = 0; k <= 100; ++k) printf "%.6g\n", -14 * cos(2 * 3.14159265 * 124 * k / 50000) }' >"$tmp/rec.csv"
ln -s rec.csv "$tmp/rec_link.csv"
ln "$tmp/rec.csv" "$tmp/rec_hard.csv"
refused "run --out the --excitation record" "--out $tmp/rec.csv is the --excitation file $tmp/rec.csv: it would be overwritten" \
    - "$tmp/rec.csv" -- run configs/fig6.ini --excitation "$tmp/rec.csv" --out "$tmp/rec.csv"
refused "run --out a symbolic link to the record" "--out $tmp/rec_link.csv is the --excitation file $tmp/rec.csv" \
    - "$tmp/rec.csv" -- run configs/fig6.ini --excitation "$tmp/rec.csv" --out "$tmp/rec_link.csv"
refused "run --periods a hard link to the record" "--periods $tmp/rec_hard.csv is the --excitation file $tmp/rec_link.csv" \
    - "$tmp/rec.csv" -- run configs/fig6.ini --excitation "$tmp/rec_link.csv" --periods "$tmp/rec_hard.csv"
cp "$good" "$tmp/measured.csv"
ln -s measured.csv "$tmp/measured_link.csv"
refused "twin --out the --measured file" "--out $tmp/measured_link.csv is the --measured file $tmp/measured.csv: it would be overwritten" \
    - "$tmp/measured.csv" -- twin configs/fig6.ini --measured "$tmp/measured.csv" --out "$tmp/measured_link.csv"
ln -s mssp2023.ini "$tmp/base_link.ini"
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n[run]\ns0 = 0.3\nt_end = 0.001\n' \
    >"$tmp/plant.ini"
refused "twin-plant --out a link to the scene's base" "--out $tmp/base_link.ini is the scene's base file $tmp/mssp2023.ini" \
    - "$tmp/plant.ini $tmp/mssp2023.ini" -- twin-plant "$tmp/plant.ini" --out "$tmp/base_link.ini"
mkdir "$tmp/mapdir"
cp configs/fig6.ini "$tmp/mapdir/map.csv"
cp configs/mssp2023.ini "$tmp/mapdir/"
refused "map --out the folder holding its scene as map.csv" "--out $tmp/mapdir: $tmp/mapdir/map.csv is the scene file $tmp/mapdir/map.csv: it would be replaced" \
    - "$tmp/mapdir/map.csv" -- map "$tmp/mapdir/map.csv" --vary excitation.frequency=120,124 --set run.t_end=0.002 --out "$tmp/mapdir"

# ---- map --out DIR: missing parents are made (mkdir -p); one that cannot be is named
"$bin" map configs/fig6.ini --vary excitation.frequency=120,124 --set run.t_end=0.002 --jobs 1 \
    --out "$tmp/new/deep/map" >/dev/null 2>"$tmp/e"
check_status "map --out a folder whose parents are missing exits 0" 0 $? "$tmp/e"
if [ -f "$tmp/new/deep/map/map.csv" ]; then pass "... and makes them"; else fail "... and makes them"; fi
: >"$tmp/plain"
refused "map --out under a regular file" "--out $tmp/plain/map: cannot create the folder: $tmp/plain is a file, not a folder" \
    - "" -- map configs/fig6.ini --vary excitation.frequency=120,124 --set run.t_end=0.002 --out "$tmp/plain/map"
if [ "$(id -u)" != 0 ]; then
    mkdir "$tmp/locked" && chmod 555 "$tmp/locked"
    refused "map --out under a folder without write permission" "--out $tmp/locked/a/b: cannot create the folder $tmp/locked/a: Permission denied" \
        - "" -- map configs/fig6.ini --vary excitation.frequency=120,124 --set run.t_end=0.002 --out "$tmp/locked/a/b"
    chmod 755 "$tmp/locked"
fi

# ---- map folder files are opened as every input is: a FIFO or a link to
# /dev/zero among them is refused at once (they used to hang map-merge)
dir=$tmp/new/deep/map
if mkfifo "$dir/runs-fifo.csv" 2>/dev/null; then
    $limit "$bin" map-merge "$dir" >/dev/null 2>"$tmp/e"
    check_status "map-merge with a FIFO among the result files exits 2" 2 $? "$tmp/e"
    check_has "map-merge refuses a FIFO among the result files" "$tmp/e" "$dir/runs-fifo.csv: cannot read map result file: a FIFO (named pipe), not a regular file"
    rm -f "$dir/runs-fifo.csv"
fi
ln -s /dev/zero "$dir/runs-zero.csv"
$limit "$bin" map-merge "$dir" >/dev/null 2>"$tmp/e"
check_has "map-merge refuses a link to /dev/zero among the result files" "$tmp/e" "$dir/runs-zero.csv: cannot read map result file: a character device, not a regular file"
rm -f "$dir/runs-zero.csv"
mv "$dir/map-identity.txt" "$tmp/identity.txt"
ln -s /dev/zero "$dir/map-identity.txt"
$limit "$bin" map-merge "$dir" >/dev/null 2>"$tmp/e"
check_status "map-merge of a folder whose identity is /dev/zero exits 2" 2 $? "$tmp/e"
check_has "... naming it" "$tmp/e" "$dir/map-identity.txt: cannot read map identity: a character device, not a regular file"
rm -f "$dir/map-identity.txt"
mv "$tmp/identity.txt" "$dir/map-identity.txt"
"$bin" map-merge "$dir" >/dev/null 2>"$tmp/e"
check_status "map-merge of the folder as it was exits 0" 0 $? "$tmp/e"

# ---- map-plot reads its table through the same helper: a FIFO as map.csv
# is refused at once (exit 2), a link to /dev/zero too
plot=$tmp/plot
"$bin" map configs/fig6.ini --set run.t_end=0.002 --vary excitation.frequency=120,124 \
    --vary excitation.acceleration=10,14 --out "$plot" >/dev/null 2>"$tmp/e"
check_status "a map of two fields to plot exits 0" 0 $? "$tmp/e"
mv "$plot/map.csv" "$tmp/map.csv"
if mkfifo "$plot/map.csv" 2>/dev/null; then
    $limit "$bin" map-plot "$plot" >/dev/null 2>"$tmp/e"
    check_status "map-plot of a folder whose map.csv is a FIFO exits 2" 2 $? "$tmp/e"
    check_has "... naming it" "$tmp/e" "$plot/map.csv: cannot read map table: a FIFO (named pipe), not a regular file"
    rm -f "$plot/map.csv"
fi
ln -s /dev/zero "$plot/map.csv"
$limit "$bin" map-plot "$plot" >/dev/null 2>"$tmp/e"
check_status "map-plot of a folder whose map.csv is /dev/zero exits 2" 2 $? "$tmp/e"
check_has "... naming it" "$tmp/e" "$plot/map.csv: cannot read map table: a character device, not a regular file"
rm -f "$plot/map.csv"

# ---- --set values with control characters are refused as in a file (they
# reached the map identity and the stream headers, one-line texts)
nl='
'
refused "run --set a name with a newline" "--set scene.name=a...: control character 0x0a after 12 characters" \
    "$out" "" -- run configs/fig6.ini --set "scene.name=a${nl}b" --t-end 0.001 --out "$out"
refused "map --set a name with a newline" "--set scene.name=a...: control character 0x0a" \
    "$tmp/ctl_map" "" -- map configs/fig6.ini --set "scene.name=a${nl}b" --vary excitation.frequency=120,124 --out "$tmp/ctl_map"
esc=$(printf '\033')
refused "twin-plant --set a description with an escape" "--set scene.description=x...: control character 0x1b" \
    "$out" "" -- twin-plant configs/fig6.ini --set "scene.description=x${esc}[31m" --out "$out"

# ---- a refusal names the field that was given (tests/fuzz/check_extreme_values.sh
# sweeps every field at tiny and huge values)
refused "--set transducer.capacitance=4.9e-324" "--set transducer.capacitance=4.9e-324: the values make 1 / C_p, the patch's inverse capacitance about 1e+323" \
    "$out" "" -- run configs/fig6.ini --set transducer.load=resistor --set transducer.capacitance=4.9e-324 --out "$out"
refused "--set transducer.capacitance=1e-30" "--set transducer.capacitance=1e-30: [transducer] capacitance = 1e-30 F: the open patch's stiffness" \
    "$out" "" -- run configs/fig6.ini --set transducer.load=resistor --set transducer.capacitance=1e-30 --out "$out"
refused "--set excitation.frequency=1e30" "--set excitation.frequency=1e30: [excitation] frequency = 1e+30 Hz: fewer than two steps per excitation period, with [numerics] dt = 2e-05 s" \
    "$out" "" -- run configs/fig6.ini --set excitation.frequency=1e30 --out "$out"

echo "check_inputs: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
