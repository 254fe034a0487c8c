#!/bin/sh
# check_cli.sh - the beamslider command line: output formats, exit codes and
# error messages (0 ok, 1 the work failed, 2 bad usage or input; host/cli/cli.h).
#
# usage, from the repository root:  sh tests/check_cli.sh PATH/TO/beamslider
# Prints one line per check and a summary; exits 1 if any check failed.

bin=${1:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_cli.sh "$bin"

# ---- modes: the five natural frequencies of docs/model.md 8 (Hz, as rounded there)
"$bin" modes configs/fig6.ini >"$tmp/modes.out" 2>"$tmp/modes.err"
check_status "modes configs/fig6.ini exits 0" 0 $? "$tmp/modes.err"
if report=$(awk '
    BEGIN { split("260.28 719.01 1412.3 2339.0 3500.1", want, " ") }
    $1 ~ /^[0-9]+$/ && NF >= 2 { ++n; got[$1 + 0] = $2 }
    END {
        if (n != 5) { printf "%d mode lines, expected 5\n", n; exit 1 }
        for (k = 1; k <= 5; ++k) {
            d = got[k] - want[k]
            if (d < 0) d = -d
            if (!(d <= 1e-4 * want[k])) { printf "mode %d: %s Hz, expected %s Hz\n", k, got[k], want[k]; bad = 1 }
        }
        exit bad
    }' "$tmp/modes.out"); then
    pass "modes: f_1..f_5 = 260.28, 719.01, 1412.3, 2339.0, 3500.1 Hz (relative 1e-4)"
else
    fail "modes: f_1..f_5 = 260.28, 719.01, 1412.3, 2339.0, 3500.1 Hz (relative 1e-4)" "$report"
fi

# ---- run: CSV and JSON summary
csv="$tmp/fig6.csv"
"$bin" run configs/fig6.ini --t-end 0.2 --out "$csv" --every 10 >"$tmp/run.json" 2>"$tmp/run.err"
check_status "run fig6 --t-end 0.2 --every 10 exits 0" 0 $? "$tmp/run.err"
if [ -f "$csv" ]; then pass "run writes the --out file"; else fail "run writes the --out file"; fi
touch "$csv"
header=$(head -n 1 "$csv")
if [ "$header" = "t,w_sensor,s,z_r,beta,contacts,pgs_iters,pgs_residual" ]; then
    pass "CSV header"
else
    fail "CSV header" "got: $header"
fi
rows=$(($(wc -l <"$csv") - 1))
if [ "$rows" -eq 1001 ]; then
    pass "CSV has 1001 data rows (steps 0, 10, ..., 10000)"
else
    fail "CSV has 1001 data rows (steps 0, 10, ..., 10000)" "got $rows"
fi
if report=$(awk -F, 'NF != 8 { printf "line %d has %d fields\n", NR, NF; ++bad } END { exit NR < 2 || bad > 0 }' "$csv"); then
    pass "every CSV line has 8 fields"
else
    fail "every CSV line has 8 fields" "$report"
fi
# row i is step 10 i of dt = 2e-5 s: t = i * 2e-4 s
if report=$(awk -F, 'NR > 1 { want = (NR - 2) * 2e-4; d = $1 - want; if (d < 0) d = -d
                               if (!(d <= 1e-9)) { printf "line %d: t = %s, expected %.6f\n", NR, $1, want; ++bad } }
                     END { exit NR < 2 || bad > 0 }' "$csv"); then
    pass "CSV times are 0, 2e-4, ..., 0.2 s"
else
    fail "CSV times are 0, 2e-4, ..., 0.2 s" "$(printf '%s\n' "$report" | head -n 3)"
fi
json_lines=$(wc -l <"$tmp/run.json")
if [ "$json_lines" -eq 1 ] && grep -q '^{.*}$' "$tmp/run.json"; then
    pass "stdout is one line of JSON"
else
    fail "stdout is one line of JSON" "$(head -c 400 "$tmp/run.json")"
fi
missing=
for key in t_end steps s_final amp_final_h wall_s steps_per_s max_pgs_iters unconverged_steps; do
    grep -q "\"$key\":" "$tmp/run.json" || missing="$missing $key"
done
if [ -z "$missing" ]; then pass "JSON summary has its keys"; else fail "JSON summary has its keys" "missing:$missing"; fi
if grep -q '"steps":10000[,}]' "$tmp/run.json"; then
    pass "JSON steps = 10000"
else
    fail "JSON steps = 10000" "$(cat "$tmp/run.json")"
fi

# ---- the summary escapes the scene name (it comes from the file name when
# [scene] name is not set, and a file name may hold quotes and backslashes)
cp configs/mssp2023.ini "$tmp/mssp2023.ini"
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n[run]\ns0 = 0.3\nt_end = 0.001\n' \
    >"$tmp/q\"b\\c.ini"
"$bin" run "$tmp/q\"b\\c.ini" >"$tmp/name.json" 2>"$tmp/name.err"
check_status "run of a scene whose file name holds a quote and a backslash exits 0" 0 $? "$tmp/name.err"
check_has "the summary escapes the quote and the backslash of the name" "$tmp/name.json" '{"scene":"q\"b\\c","model"'

# ---- the twin refuses a measured stream with NaN, a gap or another rate,
# naming file and line, and writes no estimates
"$bin" twin-plant configs/fig6.ini --out "$tmp/measured.csv" --t-end 0.01 --snr 40 >/dev/null 2>"$tmp/e"
check_status "twin-plant of 0.01 s exits 0" 0 $? "$tmp/e"
sed '15s/,[^,]*,/,nan,/' "$tmp/measured.csv" >"$tmp/m_nan.csv"
sed '16d' "$tmp/measured.csv" >"$tmp/m_gap.csv"
sed 's/^# sample_rate = 50000 Hz/# sample_rate = 40000 Hz/' "$tmp/measured.csv" >"$tmp/m_rate.csv"
for bad in nan:m_nan.csv:15:finite gap:m_gap.csv:16:gap rate:m_rate.csv:sample_rate:needs; do
    what=${bad%%:*} rest=${bad#*:} file=${rest%%:*} rest=${rest#*:} where=${rest%%:*} word=${rest#*:}
    "$bin" twin configs/fig6.ini --measured "$tmp/$file" --out "$tmp/est_$what.csv" >/dev/null 2>"$tmp/e"
    check_status "twin on a stream with a $what exits 2" 2 $? "$tmp/e"
    check_has "... naming $file, $where" "$tmp/e" "$file"
    check_has "... and what is wrong ($word)" "$tmp/e" "$word"
    [ -e "$tmp/est_$what.csv" ] && fail "twin on a stream with a $what writes no estimates" "est_$what.csv exists" \
        || pass "twin on a stream with a $what writes no estimates"
done

# ---- one glitch in the measured signal (1e10 m at t = 0.04 s) neither ends
# the twin nor throws it off the beam: skipped, counted, flagged
"$bin" twin-plant configs/fig6.ini --out "$tmp/clean.csv" --t-end 0.1 --snr 40 >/dev/null 2>"$tmp/e"
awk -F, 'NR == 2010 && /^[0-9]/ { $3 = "1e10" } { print }' OFS=, "$tmp/clean.csv" >"$tmp/glitch.csv"
"$bin" twin configs/fig6.ini --measured "$tmp/glitch.csv" --out "$tmp/est_glitch.csv" >"$tmp/o" 2>"$tmp/e"
check_status "twin on a stream with one glitch of 1e10 m exits 0" 0 $? "$tmp/e"
check_has "... and counts it as an outlier" "$tmp/o" '"outliers":1,'
check_has "... its estimates say so from then on (outliers, health)" "$tmp/est_glitch.csv" ',1,1'
if report=$(awk -F, 'NR > 1 && ($2 < 0.25 || $2 > 0.35) { printf "t = %s: s_hat = %s\n", $1, $2; exit 1 }' \
               "$tmp/est_glitch.csv"); then
    pass "... and its s stays near the plant's (0.25 .. 0.35)"
else
    fail "... and its s stays near the plant's (0.25 .. 0.35)" "$report"
fi
"$bin" twin configs/fig6.ini --measured "$tmp/clean.csv" --out "$tmp/est_clean.csv" >"$tmp/o" 2>"$tmp/e"
check_has "the stream without the glitch has no outlier" "$tmp/o" '"outliers":0,'

# ---- the observer design's cost is bounded: maps at 1-8 Hz (some 4.6e9
# steps of simulation, minutes) are refused at once with the estimate
"$bin" twin-gains configs/fig6.ini --noise 1e-6 --map-frequencies 1,2,3,4,5,6,7,8 >"$tmp/o" 2>"$tmp/e"
check_status "twin-gains with maps at 1-8 Hz exits 2" 2 $? "$tmp/e"
check_has "... with the cost it would have and the bound" "$tmp/e" "need about 4.57e+09 steps of simulation, more than the design's bound of 4e+08"
[ -s "$tmp/o" ] && fail "... and writes no header" "$(head -c 80 "$tmp/o")" || pass "... and writes no header"

# ---- twin-plant steps the scene's [excitation] schedule as run does: with
# no noise and no quantisation its signal is run's w(4L/7), step for step
# (here through a ramp from 124 to 110 Hz within the first 0.2 s; a plant
# that kept the scene's first frequency parts from run within the ramp)
ramp="--set excitation.schedule=0:124:14,0.2:110:14 --set run.t_end=0.3"
# shellcheck disable=SC2086
"$bin" twin-plant configs/fig6.ini $ramp --snr inf --bits 0 --out "$tmp/plant.csv" >/dev/null 2>"$tmp/e"
check_status "twin-plant of a scene with a schedule exits 0" 0 $? "$tmp/e"
# shellcheck disable=SC2086
"$bin" run configs/fig6.ini $ramp --every 1 --out "$tmp/run.csv" >/dev/null 2>"$tmp/e"
check_status "run of the same scene exits 0" 0 $? "$tmp/e"
if report=$(awk -F, 'NR == FNR { if ($1 ~ /^[0-9]/) y[++n] = $3; next }
                     FNR > 2 { k = FNR - 2; d = y[k] - $2; if (d < 0) d = -d; m = $2 < 0 ? -$2 : $2
                               if (!(d <= 6e-9 * m + 1e-18)) { printf "step %d: plant %s, run %s\n", k, y[k], $2; exit 1 } ++c }
                     END { if (c != 15000) { printf "%d steps compared, expected 15000\n", c; exit 1 } }' \
               "$tmp/plant.csv" "$tmp/run.csv"); then
    pass "twin-plant follows the schedule: its w(4L/7) is run's at every step (to its 9 digits)"
else
    fail "twin-plant follows the schedule: its w(4L/7) is run's at every step (to its 9 digits)" "$report"
fi

# ---- response maps: a schedule wider than the observer's maps cover, and
# --map-frequencies out of order, are refused saying so (docs/twin.md, "Observer")
"$bin" twin-gains configs/fig6.ini --noise 1e-6 --set excitation.schedule=0:60:14,10:124:14 >/dev/null 2>"$tmp/e"
check_status "twin-gains on a schedule from 60 Hz to 124 Hz exits 2" 2 $? "$tmp/e"
check_has "... naming the span, the maps it needs and the option" "$tmp/e" \
    "the [excitation] schedule spans 60 Hz to 124 Hz, which needs 38 response maps spaced by 1.02; at most 24 fit (name the frequencies the twin will meet with --map-frequencies)"
"$bin" twin-gains configs/fig6.ini --noise 1e-6 --map-frequencies 124,110 >/dev/null 2>"$tmp/e"
check_status "twin-gains --map-frequencies 124,110 exits 2" 2 $? "$tmp/e"
check_has "... naming the frequency out of order" "$tmp/e" "--map-frequencies 124,110: frequency 2: allowed: 1 to 24 frequencies [Hz], > 0, ascending"
"$bin" twin-gains configs/fig6.ini --noise 1e-6 --map-frictions 0.2,0.15 >/dev/null 2>"$tmp/e"
check_status "twin-gains --map-frictions 0.2,0.15 exits 2" 2 $? "$tmp/e"
check_has "... naming the mu out of order" "$tmp/e" "--map-frictions 0.2,0.15: mu 2: allowed: 1 to 24 friction coefficients, >= 0, ascending"
"$bin" twin-gains configs/fig6_shift.ini --noise 1e-6 --map-frictions 0.1,0.15,0.2,0.25 >/dev/null 2>"$tmp/e"
check_status "twin-gains of fig6_shift's 8 excitations at 4 mu exits 2" 2 $? "$tmp/e"
check_has "... counting the maps that would need" "$tmp/e" "8 excitations with maps at 4 friction coefficients each need 32 response maps; at most 24 fit"

# ---- a negative load is refused with its file, line and range
printf '[scene]\nbase = mssp2023.ini\n[transducer]\nload = resistor\nresistance = -5\n' >"$tmp/negative.ini"
"$bin" run "$tmp/negative.ini" --out "$tmp/negative.csv" >/dev/null 2>"$tmp/e"
check_status "a negative load resistance exits 2" 2 $? "$tmp/e"
check_has "... naming file, line and the allowed range" "$tmp/e" "negative.ini:5: [transducer] resistance = -5: out of range; allowed: a finite number in (0, inf) Ohm"
[ -e "$tmp/negative.csv" ] && fail "a refused scene writes no --out file" "$tmp/negative.csv exists" || pass "a refused scene writes no --out file"

# ---- a scene with a transducer: the step rows end in v, p, v_s and the
# summary gives the harvested energy and power; without one (fig6 above)
# the columns and keys stay as they were
cp configs/mssp2023.ini "$tmp/mssp2023.ini"
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n[transducer]\nload = resistor\n[run]\ns0 = 0.3\nt_end = 0.02\n' \
    >"$tmp/harvester.ini"
"$bin" run "$tmp/harvester.ini" --out "$tmp/harvester.csv" >"$tmp/harvester.json" 2>"$tmp/e"
check_status "run of a scene with a transducer exits 0" 0 $? "$tmp/e"
touch "$tmp/harvester.csv"
header=$(head -n 1 "$tmp/harvester.csv")
if [ "$header" = "t,w_sensor,s,z_r,beta,contacts,pgs_iters,pgs_residual,v,p,v_s" ]; then
    pass "with a transducer the CSV header ends in v,p,v_s"
else
    fail "with a transducer the CSV header ends in v,p,v_s" "got: $header"
fi
if report=$(awk -F, 'NF != 11 { printf "line %d has %d fields\n", NR, NF; ++bad } END { exit NR < 2 || bad > 0 }' \
                "$tmp/harvester.csv"); then
    pass "with a transducer every CSV line has 11 fields"
else
    fail "with a transducer every CSV line has 11 fields" "$report"
fi
if grep -q '"energy_j":[0-9][^,]*,"power_mean_w":[0-9][^,]*,"power_last_w":[0-9][^,]*,"power_window_s":0.02,' \
        "$tmp/harvester.json"; then
    pass "with a transducer the summary has energy_j, power_mean_w, power_last_w, power_window_s"
else
    fail "with a transducer the summary has energy_j, power_mean_w, power_last_w, power_window_s" \
        "$(cat "$tmp/harvester.json")"
fi
if grep -q -e '"energy_j"' -e '"power_' "$tmp/run.json"; then
    fail "without a transducer the summary has no energy or power" "$(cat "$tmp/run.json")"
else
    pass "without a transducer the summary has no energy or power"
fi

# ---- run --excitation: a recorded base acceleration (docs/twin.md). The
# record is fig6's own excitation, -14 cos(2 pi 124 t) m/s^2, sampled at
# 500 kHz (10 samples per step) for 0.06 s. Its step means miss the
# harmonic's by at most a omega^2 / (8 fs^2) = 4.3e-6 m/s^2 (3e-7 of a;
# docs/twin.md), so the replay of 0.05 s must end where the harmonic run ends:
# within 1e-6 in s. That is 30 ulps of s in float, while reading the record
# 2 us (one sample) late moves s by 1e-5 and a 1 % larger amplitude by 1.6e-4.
# Not longer: after about 0.06 s the contact sequence amplifies differences
# of 1e-9 to 1e-4 (as float against double already shows).
record="$tmp/fig6_harmonic.csv"
awk 'BEGIN {
    pi = atan2(0, -1); fs = 500000
    print "# beamslider base acceleration"; print "# sample_rate = " fs " Hz"; print "# unit = m/s^2"
    for (k = 0; k <= 0.06 * fs; ++k) printf "%.12g\n", -14 * cos(2 * pi * 124 * k / fs)
}' >"$record"
"$bin" run configs/fig6.ini --t-end 0.05 >"$tmp/harmonic.json" 2>"$tmp/e"
check_status "run fig6 --t-end 0.05 exits 0" 0 $? "$tmp/e"
"$bin" run configs/fig6.ini --t-end 0.05 --excitation "$record" >"$tmp/replay.json" 2>"$tmp/e"
check_status "run fig6 --excitation (its own harmonic, 500 kHz) --t-end 0.05 exits 0" 0 $? "$tmp/e"
s_harmonic=$(sed -n 's/.*"s_final":\([^,]*\),.*/\1/p' "$tmp/harmonic.json")
s_replay=$(sed -n 's/.*"s_final":\([^,]*\),.*/\1/p' "$tmp/replay.json")
if awk -v a="$s_replay" -v b="$s_harmonic" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= 1e-6) }'; then
    pass "the replay of the harmonic ends within 1e-6 of its s_final ($s_replay against $s_harmonic)"
else
    fail "the replay of the harmonic ends within 1e-6 of its s_final" "replay $s_replay, harmonic $s_harmonic"
fi
check_has "the summary names the recorded excitation" "$tmp/replay.json" \
    "\"excitation\":\"file\",\"excitation_file\":\"$record\",\"excitation_format\":\"csv\",\"excitation_rate\":500000,\"excitation_samples\":30001,\"excitation_latency\":0,"
check_has "the harmonic run's summary says harmonic" "$tmp/harmonic.json" '"excitation":"harmonic",'
"$bin" run configs/fig6.ini --excitation "$record" >"$tmp/whole.json" 2>"$tmp/e"
check_status "run --excitation without --t-end exits 0" 0 $? "$tmp/e"
check_has "without --t-end the run lasts the record's whole steps (3000 of 0.06 s)" "$tmp/whole.json" '"t_end":0.06,"steps":3000,'
# a WAV file: mono, 16 bit, 1000 Hz, four samples (3 ms: 150 steps)
wav_head='RIFF\054\000\000\000WAVEfmt \020\000\000\000\001\000'
printf "$wav_head"'\001\000\350\003\000\000\320\007\000\000\002\000\020\000data\010\000\000\000\000\100\000\300\377\177\000\200' \
    >"$tmp/mono.wav"
"$bin" run configs/fig6.ini --excitation "$tmp/mono.wav" --scale 10 >"$tmp/wav.json" 2>"$tmp/e"
check_status "run --excitation of a WAV file with --scale exits 0" 0 $? "$tmp/e"
check_has "the WAV record's summary" "$tmp/wav.json" '"excitation_format":"wav","excitation_rate":1000,"excitation_samples":4,'
check_has "the WAV run lasts its 150 steps" "$tmp/wav.json" '"steps":150,'

# ---- bad records: exit 2, the file and what is wrong on stderr, no output
check_record_error() { # DESCRIPTION MESSAGE ARGS...: run fig6 with ARGS, expect exit 2 and MESSAGE
    description=$1
    message=$2
    shift 2
    rm -f "$tmp/bad_record.csv"
    "$bin" run configs/fig6.ini --out "$tmp/bad_record.csv" "$@" >"$tmp/o" 2>"$tmp/e"
    check_status "$description exits 2" 2 $? "$tmp/e"
    check_has "$description: message" "$tmp/e" "$message"
    if [ -e "$tmp/bad_record.csv" ]; then fail "$description creates no --out file"; else pass "$description creates no --out file"; fi
}
printf '# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n1\n2\nnan\n' >"$tmp/nan.csv"
check_record_error "a NaN in a record" "$tmp/nan.csv:6: 'nan' is not a finite number" --excitation "$tmp/nan.csv"
printf '# beamslider base acceleration\n# sample_rate = 1000 Hz\n# unit = m/s^2\n0,1\n0.001,2\n0.003,3\n' >"$tmp/gap.csv"
check_record_error "a gap in a record's time column" "$tmp/gap.csv:6: a gap" --excitation "$tmp/gap.csv"
printf '1\n2\n' >"$tmp/headless.csv"
check_record_error "a record without its header" "$tmp/headless.csv:1: not a base acceleration record" \
    --excitation "$tmp/headless.csv"
check_record_error "a record shorter than --t-end" \
    "$record covers t = 0 .. 0.06 s (0.06 s: 30001 samples at 500000 Hz); the run needs t = 0.001 .. 0.101 s" \
    --excitation "$record" --t-end 0.1 --latency 0.001
check_record_error "--scale with a CSV record" "--scale is for WAV files" --excitation "$record" --scale 9.8
check_record_error "a WAV record without --scale" "$tmp/mono.wav is a WAV file: give --scale S" \
    --excitation "$tmp/mono.wav"
printf "$wav_head"'\002\000\350\003\000\000\240\017\000\000\004\000\020\000data\010\000\000\000\000\000\000\000\000\000\000\000' \
    >"$tmp/stereo.wav"
check_record_error "a stereo WAV without --channel" "$tmp/stereo.wav has 2 channels: choose one with --channel N" \
    --excitation "$tmp/stereo.wav" --scale 10
check_record_error "a missing record" "$tmp/none.csv: cannot open" --excitation "$tmp/none.csv"
check_record_error "--latency without --excitation" "--latency is about a recorded excitation" --latency 0.001
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\nschedule = 0:120:14, 1:130:14\n[run]\ns0 = 0.3\nt_end = 0.2\n' \
    >"$tmp/scheduled.ini"
"$bin" run "$tmp/scheduled.ini" --excitation "$record" >"$tmp/o" 2>"$tmp/e"
check_status "a schedule and --excitation together exit 2" 2 $? "$tmp/e"
check_has "a schedule and --excitation: message names the schedule" "$tmp/e" \
    "$tmp/scheduled.ini:6: [excitation] schedule and --excitation both set the excitation"

# ---- bad usage: exit 2 and a message on stderr
"$bin" run configs/fig6.ini --bogus 1 >"$tmp/o" 2>"$tmp/e"
check_status "unknown option exits 2" 2 $? "$tmp/e"
check_has "unknown option is named on stderr" "$tmp/e" "--bogus"
"$bin" run configs/fig6.ini --t-end >"$tmp/o" 2>"$tmp/e"
check_status "option without a value exits 2" 2 $? "$tmp/e"
check_has "option without a value is named on stderr" "$tmp/e" "--t-end"
"$bin" frobnicate >"$tmp/o" 2>"$tmp/e"
check_status "unknown command exits 2" 2 $? "$tmp/e"
check "unknown command prints a message on stderr" test -s "$tmp/e"

# ---- bad scene: exit 2, file:line named, no output file
cp configs/mssp2023.ini "$tmp/mssp2023.ini"
cat >"$tmp/bad.ini" <<'EOF'
[scene]
base = mssp2023.ini
[excitation]
frequency = 124
acceleration = 14
[contact]
restitution = 1.5
[run]
s0 = 0.3
t_end = 0.2
EOF
"$bin" run "$tmp/bad.ini" --out "$tmp/bad.csv" >"$tmp/o" 2>"$tmp/e"
check_status "out-of-range scene value exits 2" 2 $? "$tmp/e"
check_has "bad scene message names file:line" "$tmp/e" "$tmp/bad.ini:7:"
check_has "bad scene message names [contact] restitution" "$tmp/e" "[contact] restitution"
if [ -e "$tmp/bad.csv" ]; then fail "bad scene creates no --out file"; else pass "bad scene creates no --out file"; fi

# ---- dt above the explicit limit: exit 2, no output file
"$bin" run configs/fig6.ini --dt 1e-4 --out "$tmp/dt.csv" >"$tmp/o" 2>"$tmp/e"
check_status "--dt 1e-4 exits 2" 2 $? "$tmp/e"
check_has "--dt 1e-4 message mentions the explicit limit" "$tmp/e" "explicit limit"
check_has "--dt 1e-4 message names the option" "$tmp/e" "--dt"
if [ -e "$tmp/dt.csv" ]; then fail "--dt 1e-4 creates no --out file"; else pass "--dt 1e-4 creates no --out file"; fi

# ---- output that cannot be written: exit 1 and a message
"$bin" run configs/fig6.ini --t-end 0.01 --out "$tmp/no/such/dir/x.csv" >"$tmp/o" 2>"$tmp/e"
check_status "--out into a missing folder exits 1" 1 $? "$tmp/e"
check_has "--out into a missing folder names the file" "$tmp/e" "$tmp/no/such/dir/x.csv"
if [ -c /dev/full ]; then
    "$bin" run configs/fig6.ini --t-end 0.2 --out /dev/full >"$tmp/o" 2>"$tmp/e"
    check_status "--out /dev/full exits 1" 1 $? "$tmp/e"
    check_has "--out /dev/full message names the file" "$tmp/e" "/dev/full"
    # past the "beamslider: error:" prefix every message has
    if sed 's/^beamslider: error: //' "$tmp/e" | grep -q -i -e failed -e error; then
        pass "--out /dev/full message says failed/error"
    else
        fail "--out /dev/full message says failed/error" "$(cat "$tmp/e")"
    fi
else
    echo "skip - --out /dev/full (no /dev/full here)"
fi

# ---- gen prints text from the scene file as escaped string literals only:
# a description that would close a comment and inject code, quotes, a
# backslash and trigraph question marks come back as they were written
cat > "$tmp/evil.ini" <<EOF
[scene]
base = $(pwd)/configs/fig6_1mode.ini
name = evil"na\me??/
description = */ int injected = 1; /* "quoted" ??= back\slash
EOF
if "$bin" gen "$tmp/evil.ini" > "$tmp/evil.h" 2>"$tmp/e"; then
    pass "gen of a scene with hostile text exits 0"
else
    fail "gen of a scene with hostile text exits 0" "$(cat "$tmp/e")"
fi
cat > "$tmp/evil.c" <<'EOF'
#include <stdio.h>
#include "beamslider.h"
#include "evil.h"
int main(void) { printf("%s\n%s\n", BS_SCENE_NAME, BS_SCENE_DESCRIPTION); return bs_compiled_scene.n_modes != 1; }
EOF
if ${CC:-cc} -std=c99 -Wall -Wextra -Werror -I"$(dirname "$bin")/include" -Icore/include -I"$tmp" \
       -o "$tmp/evil" "$tmp/evil.c" 2>"$tmp/e" && "$tmp/evil" > "$tmp/o"; then
    pass "the header of a scene with hostile text compiles and holds its scene"
else
    fail "the header of a scene with hostile text compiles and holds its scene" "$(cat "$tmp/e")"
fi
printf '%s\n%s\n' 'evil"na\me??/' '*/ int injected = 1; /* "quoted" ??= back\slash' > "$tmp/want"
if cmp -s "$tmp/o" "$tmp/want"; then
    pass "name and description come back unchanged from the header"
else
    fail "name and description come back unchanged from the header" "$(cat "$tmp/o")"
fi

# ---- version and field reference
"$bin" --version >"$tmp/o" 2>"$tmp/e"
check_status "--version exits 0" 0 $? "$tmp/e"
check_has "--version names the version" "$tmp/o" "beamslider $(sed -n 's/^#define BS_VERSION_STRING "\(.*\)"/\1/p' core/include/beamslider.h) (revision "
"$bin" fields extra >"$tmp/o" 2>"$tmp/e"
check_status "fields with an argument exits 2" 2 $? "$tmp/e"

# ---- twin: a stream shorter than --score-after says why within is null
"$bin" twin-plant configs/fig6.ini --t-end 0.05 --out "$tmp/short.csv" >"$tmp/o" 2>"$tmp/e"
check_status "twin-plant of 0.05 s exits 0" 0 $? "$tmp/e"
"$bin" twin configs/fig6.ini --measured "$tmp/short.csv" --out "$tmp/short_est.csv" --map-frequencies 2000 \
    --noise 1e-6 --score-after 5 >"$tmp/o" 2>"$tmp/e"
check_status "twin on a stream shorter than --score-after exits 0" 0 $? "$tmp/e"
check_has "its summary has within null and scored 0" "$tmp/o" '"scored":0,"within":null'
check_has "and stderr says why" "$tmp/e" "no row was scored (within and rms_s_error are null): the stream ends at t = 0.05 s, before --score-after 5 s"
# ---- twin: --friction and --restitution set the running twin's contact laws
# (bs_sim_set_contact_laws; the twin report's ceiling), out-of-range values refused
"$bin" twin configs/fig6.ini --measured "$tmp/short.csv" --out "$tmp/laws_est.csv" --map-frequencies 2000 \
    --noise 1e-6 --friction 0.25 --restitution 0.4 >"$tmp/o" 2>"$tmp/e"
check_status "twin --friction 0.25 --restitution 0.4 exits 0" 0 $? "$tmp/e"
check_has "... and its summary reports mu 0.25" "$tmp/o" '"mu_final":0.25,'
check_has "... as its estimates' mu column does" "$tmp/laws_est.csv" ',0.25,0'
for bad in "--friction -0.1" "--restitution 1.5" "--estimate-friction -1" "--friction-time 0" \
    "--friction-deadband -0.001" "--friction-sigma 0" "--friction-amplitude -1" "--friction-climb -0.001" \
    "--jump-hold -1"; do
    "$bin" twin configs/fig6.ini --measured "$tmp/short.csv" --out "$tmp/bad_est.csv" $bad >"$tmp/o" 2>"$tmp/e"
    check_status "twin $bad exits 2" 2 $? "$tmp/e"
    check_has "... naming the option and its range" "$tmp/e" "${bad%% *} ${bad#* }: allowed: a number in"
done

# ---- help: each command's own, and the top-level usage lists every option
"$bin" --help >"$tmp/usage" 2>"$tmp/e"
check_status "--help exits 0" 0 $? "$tmp/e"
for command in modes gen sweep run twin twin-plant twin-gains map map-merge map-plot fields; do
    "$bin" "$command" --help >"$tmp/o" 2>"$tmp/e"
    status=$?
    if [ "$status" -eq 0 ] && [ "$(head -n 1 "$tmp/o" | cut -d' ' -f1-3)" = "usage: beamslider $command" ] \
        && ! grep -q "^usage: beamslider [a-z-]* " "$tmp/e"; then
        pass "$command --help prints its own usage (exit 0)"
    else
        fail "$command --help prints its own usage (exit 0)" "exit $status: $(head -n 2 "$tmp/o") $(cat "$tmp/e")"
    fi
    if [ "$(grep -c '^usage: ' "$tmp/o")" -ne 1 ]; then
        fail "$command --help prints one command's usage only" "$(grep '^usage: ' "$tmp/o")"
    fi
    missing=""
    for option in $(grep -o -e '--[a-z][a-z-]*' "$tmp/o" | sort -u); do
        grep -q -e "$option" "$tmp/usage" || missing="$missing $option"
    done
    if [ -z "$missing" ]; then
        pass "beamslider --help lists every option of $command"
    else
        fail "beamslider --help lists every option of $command" "missing:$missing"
    fi
done

echo "check_cli: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
