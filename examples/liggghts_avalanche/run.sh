#!/usr/bin/env bash
# Paper 000's inclined plane in LIGGGHTS: deposit the layer once (in.deposit),
# then the tilt ramp without and with 70 kHz ultrasound (in.avalanche), and
# print both avalanche angles theta_m.  Each run on NP MPI ranks (default 2).
#
# Usage: examples/liggghts_avalanche/run.sh [LMP_ACOUSTIC] [-var NAME VALUE ...]
#   LMP_ACOUSTIC  LIGGGHTS with ACOUSTIC (default: build/liggghts-tree/src/lmp_acoustic
#                 of this repository, or $ACOUSTIC_LIGGGHTS)
#   -var ...      passed to both ramps (in.avalanche), e.g. -var theta0 18
# Environment: NP (ranks per run, 2), OUT (output directory, default out/
#   beside this script: logs, deposit.restart), DEPOSIT_VARS (-var ... for
#   in.deposit, e.g. "-var N 60"), MPIRUN (default mpirun).
# Output: one line per angle and run, prefixed by the wall time, and at the end
#   result: f = 0 Hz theta_m = X deg
#   result: f = 70000 Hz theta_m = Y deg
# (the reference output: log.05Dec26.liggghts_avalanche.g++.2).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${ACOUSTIC_LIGGGHTS:-$here/../../build/liggghts-tree/src/lmp_acoustic}
if [ $# -gt 0 ] && [ "$1" != -var ]; then lmp=$1; shift; fi
[ -x "$lmp" ] || { echo "ERROR: no LIGGGHTS executable $lmp (./run.sh build makes it)" >&2; exit 1; }
np=${NP:-2}
out=${OUT:-$here/out}
mpirun=${MPIRUN:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
export OMPI_MCA_rmaps_base_oversubscribe=${OMPI_MCA_rmaps_base_oversubscribe:-1}
mkdir -p "$out"
cd "$out"
start=$(date +%s)
stamp() {   # the lines of the decks worth reading, with the wall time
  while IFS= read -r line; do
    case $line in
      deposit:*|avalanche*|angle*|result:*|ERROR*|*"Label source"*)
        printf '[%4ds] %s\n' $(( $(date +%s) - start )) "$line";;
    esac
  done
}
run() {   # run LOG DECK ARGS...: one LIGGGHTS run, its screen output filtered
  local log=$1 deck=$2; shift 2
  "$mpirun" -np "$np" "$lmp" -in "$here/$deck" -var dir "$here" -log "$log" -echo none "$@" 2>&1 \
    | tee "$log.screen" | stamp \
    || { echo "ERROR: $deck failed, see $out/$log.screen" >&2; exit 1; }
  grep -q '^ERROR' "$log.screen" && { echo "ERROR: $deck failed, see $out/$log.screen" >&2; exit 1; }
  return 0
}
echo "LIGGGHTS avalanche example: $lmp, $np ranks per run, outputs in $out"
# shellcheck disable=SC2086
run log.deposit in.deposit -var out deposit.restart ${DEPOSIT_VARS:-}
run log.f0 in.avalanche -var restart deposit.restart -var freq 0 -var tag f0 "$@"
run log.f70 in.avalanche -var restart deposit.restart -var freq 70e3 -var tag f70 "$@"
echo
grep -h '^result:' log.f0.screen log.f70.screen
t0=$(grep -h '^result:' log.f0.screen | sed 's/.*theta_m = \([^ ]*\) deg.*/\1/')
t70=$(grep -h '^result:' log.f70.screen | sed 's/.*theta_m = \([^ ]*\) deg.*/\1/')
echo "theta_m without ultrasound: $t0 deg; with 70 kHz: $t70 deg (paper 000: about 2 deg lower with 70 kHz)"
echo "wall time $(( $(date +%s) - start )) s"
