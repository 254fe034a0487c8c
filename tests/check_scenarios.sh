#!/bin/sh
# check_scenarios.sh - the outcome classes of the papers' six scenarios
# (docs/validation.md section 7, docs/maps.md): the class most of 3 starts of
# each end in, through `beamslider map`. 18 runs of 60-120 s, two at a time:
# part of `make test-long` (make test classifies fig6 alone, tests/check_map.sh).
#
# usage, from the repository root:  sh tests/check_scenarios.sh PATH/TO/beamslider

bin=${1:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_scenarios.sh "$bin"

echo "check_scenarios: 6 scenarios x 3 starts of 60-120 s, two at a time ($bin)"
for scene in fig6 fig7 fig8 fig9 fig12a fig12b; do echo "$scene"; done |
    xargs -P 2 -I '{}' "$bin" map configs/'{}'.ini --repeat 3 --jobs 1 --out "$tmp/scene_{}" \
        >"$tmp/o" 2>"$tmp/e"
for pair in fig6:signature fig7:trivial fig8:relaxation fig9:self_damping fig12a:trivial fig12b:signature; do
    scene=${pair%%:*}
    want=${pair#*:}
    got=$(tail -n 1 "$tmp/scene_$scene/map.csv" 2>/dev/null | cut -d, -f3,4)
    if [ "${got%%,*}" = "$want" ]; then
        pass "$scene: $want (agreement ${got#*,} of 3 starts)"
    else
        fail "$scene: $want" "got ${got:-nothing}; $(cat "$tmp/e")"
    fi
done

echo "check_scenarios: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
