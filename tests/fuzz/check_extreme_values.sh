#!/bin/sh
# check_extreme_values.sh BEAMSLIDER - every real field of a scene, one at a
# time, at tiny and huge values (denormals to DBL_MAX) in a copy of
# configs/mssp2023.ini (tests/robustness.mk: robustness-cli). It found the
# classes of docs/robustness.md section 6 item 13: NaN modal frequencies
# blamed on dt, core refusals without a line or a range.
#
# Each run must end with exit 0 (accepted), 1 (accepted, the run stopped:
# divergence is the model's answer) or 2 (refused), and a refusal must name
# the field under test at its file and line (line 4: not another field, as
# "[transducer] capacitance = 4.9e-324" once blamed coupling), must not quote
# a NaN, fall through to the core's own check or print a number of 300
# digits. The transducer's fields are swept with a resistor load (the
# storage ones with the rectifier). VERBOSE=1 prints every message. Run from
# the repository root.
bin=$1
passed=0
failed=0
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

if [ ! -x "$bin" ] || [ ! -f configs/mssp2023.ini ]; then
    echo "FAIL - usage (from the repository root): sh tests/fuzz/check_extreme_values.sh PATH/TO/beamslider"
    exit 1
fi
cp configs/mssp2023.ini "$tmp/" || exit 1
limit=
if command -v timeout >/dev/null 2>&1; then limit="timeout 60"; fi

fields="beam:length beam:thickness beam:density beam:youngs_modulus beam:mass beam:damping_ratio
clamps:rotational_stiffness clamps:axial_stiffness slider:mass slider:inertia slider:slot_width
slider:com_offset slider:play_ratio contact:friction environment:gravity excitation:frequency
excitation:acceleration numerics:dt solver:tol_rel solver:tol_abs run:t_end transducer:patch_end
transducer:coupling transducer:capacitance transducer:resistance transducer:storage_capacitance
transducer:storage_resistance transducer:diode_drop"
values="4.9e-324 1e-320 1e-310 1e-300 1e-200 1e-100 1e-40 1e-30 1e30 1e40 1e100 1e200 1e300 1.7e308"

for field in $fields; do
    section=${field%%:*}
    key=${field#*:}
    for value in $values; do
        # the field under test on line 4; the run lines without it
        {
            printf '[scene]\nbase = mssp2023.ini\n[%s]\n%s = %s\n' "$section" "$key" "$value"
            case $key in
            storage_* | diode_drop) printf 'load = rectifier\n' ;;
            *) [ "$section" = transducer ] && printf 'load = resistor\n' ;;
            esac
            printf '[excitation]\n'
            [ "$key" = frequency ] || printf 'frequency = 124\n'
            [ "$key" = acceleration ] || printf 'acceleration = 14\n'
            printf '[run]\ns0 = 0.3\n'
            [ "$key" = t_end ] || printf 't_end = 1e-4\n'
        } >"$tmp/s.ini"
        $limit "$bin" run "$tmp/s.ini" >/dev/null 2>"$tmp/err"
        status=$?
        message=$(head -c 2000 "$tmp/err")
        [ -n "${VERBOSE:-}" ] && echo "[$section] $key = $value: exit $status: $message"
        bad=
        case $status in
        0 | 1) ;;
        2)
            case $message in
            *nan* | *"core refuses"*) bad="a NaN or the core's own refusal" ;;
            *[0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9][0-9]*)
                bad="a number of more than 20 digits" ;;
            *"$tmp/s.ini:4"*"[$section] $key"* | *"[$section] $key"*"$tmp/s.ini:4"*) ;;
            *"$tmp/"*.ini:[0-9]*) bad="another field blamed (not [$section] $key at s.ini:4)" ;;
            *) bad="no file:line" ;;
            esac
            ;;
        *) bad="exit $status" ;;
        esac
        if [ -n "$bad" ]; then
            failed=$((failed + 1))
            echo "FAIL - [$section] $key = $value: $bad: $message"
        else
            passed=$((passed + 1))
        fi
    done
done
echo "check_extreme_values: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
