#!/bin/sh
# submit-map.sh - submits a beamslider map to Slurm as an array of N shards
# and the merge step after them (docs/maps.md section 6).
#
#   sh host/slurm/submit-map.sh N BIN SCENE.ini DIR [map options]
#
# Prints the two job IDs. Extra sbatch options (partition, time, log files,
# --cpus-per-task for --jobs) go in SBATCH_OPTIONS; WAIT=1 waits until the
# merge job has ended and exits with its status.
set -eu
if [ $# -lt 4 ]; then
    echo "usage: sh submit-map.sh N BIN SCENE.ini DIR [map options]" >&2
    exit 2
fi
shards=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
dir=$3
# shellcheck disable=SC2086
array=$(sbatch --parsable --array="1-$shards" ${SBATCH_OPTIONS:-} "$here/map-array.sbatch" "$@")
array=${array%%;*}
wait_option=
[ "${WAIT:-0}" = 1 ] && wait_option=--wait
# shellcheck disable=SC2086
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes ${SBATCH_OPTIONS:-} $wait_option \
    "$here/map-merge.sbatch" "$1" "$dir")
echo "array job ${array}, merge job ${merge%%;*}"
