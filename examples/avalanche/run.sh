#!/usr/bin/env bash
# The main job: paper 000's tilt ramp on a layer of H = 6 d (80 d long, periodic),
# without and with 70 kHz ultrasound from the base; prints a line per angle and
# the two avalanche angles theta_m at the end.  2 MPI ranks.
# Usage: examples/avalanche/run.sh BUILD_DIR   (./run.sh demo passes it)
# Environment: AVALANCHE_NP (MPI ranks, default 2), AVALANCHE_H (H/d, default 6),
#              AVALANCHE_L (L/d, default 80), AVALANCHE_THETA0 (first angle, default 10),
#              AVALANCHE_OUT (output directory, default examples/avalanche/out/demo),
#              AVALANCHE_SOURCE (bottom: paper 000's source, default; base: the rough base),
#              AVALANCHE_TFOLLOW (s a rearrangement is followed after the 0.1 s window,
#              default 0.3; the deck's default and paper 000's is 1.2),
#              AVALANCHE_TSETTLE (longest hold for rest after the pre-ramp, s, default 0.2),
#              AVALANCHE_SEED (seed of the deposit, default in.deposit's)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:-$here/../../build}
build=$(cd "$build" 2>/dev/null && pwd || echo "$build")   # absolute: the runs cd
lmp=$build/lammps/lmp
[ -x "$lmp" ] || { echo "avalanche: no LAMMPS executable at $lmp (build first: ./run.sh build)" >&2; exit 1; }
np=${AVALANCHE_NP:-2}
H=${AVALANCHE_H:-6}
L=${AVALANCHE_L:-80}
theta0=${AVALANCHE_THETA0:-10}
kappa=0.3     # kappa_scale: puts 70 kHz in the top of the network's spectrum (RESULTS.md)
source=${AVALANCHE_SOURCE:-bottom}
tfollow=${AVALANCHE_TFOLLOW:-0.3}   # shorter than paper 000's 1.2 s: the demo stays at about 2 minutes
tsettle=${AVALANCHE_TSETTLE:-0.2}
out=${AVALANCHE_OUT:-$here/out/demo}
mkdir -p "$out"
cd "$out"
out=$(pwd)
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mpi=(mpirun -np "$np")
if mpirun --version 2>/dev/null | grep -q "Open MPI"; then mpi+=(--oversubscribe); fi
start=$SECONDS
stamp() { while IFS= read -r line; do printf '[%4ds] %s\n' $((SECONDS - start)) "$line"; done; }

echo "avalanche demo: H = $H d, L = $L d, periodic, source $source, $np MPI ranks, outputs in $out"
"${mpi[@]}" "$lmp" -nocite -in "$here/in.deposit" -var dir "$here" -var H "$H" -var L "$L" \
  -var out deposit.restart -log log.deposit -echo none -screen none ${AVALANCHE_SEED:+-var seed "$AVALANCHE_SEED"}
grep '^deposit:' log.deposit | stamp
for f in 0 70e3; do
  tag=f${f%e3}
  rm -f "log.$tag" "$tag".*       # no stale log for the progress reader below
  # progress: the print lines of the deck, as they come
  "${mpi[@]}" "$lmp" -nocite -in "$here/in.avalanche" -var dir "$here" -var restart deposit.restart \
    -var tag "$tag" -var freq "$f" -var kappa "$kappa" -var source "$source" -var tfollow "$tfollow" -var tsettle "$tsettle" -var theta0 "$theta0" -var thetamax 30 \
    -var dumpevery 20 -var dumplocal 1 -log "log.$tag" -echo none -screen none &
  pid=$!
  ( tail -n +1 --pid=$pid -F "log.$tag" 2>/dev/null | grep --line-buffered '^angle\|^avalanche' | stamp ) &
  tailpid=$!
  wait $pid
  sleep 1; kill $tailpid 2>/dev/null || true; wait $tailpid 2>/dev/null || true
done
echo
echo "result (H = $H d): $(grep -h 'theta_m =' log.f0 | sed 's/^avalanche //')"
echo "result (H = $H d): $(grep -h 'theta_m =' log.f70 | sed 's/^avalanche //')"
a0=$(sed -n 's/.*theta_m = \([0-9.]*\) deg.*/\1/p' log.f0)
a70=$(sed -n 's/.*theta_m = \([0-9.]*\) deg.*/\1/p' log.f70)
echo "theta_m without ultrasound: ${a0:-none} deg; with 70 kHz: ${a70:-none} deg (paper 000: about 2 deg lower with 70 kHz)"
echo "wall time $((SECONDS - start)) s; logs, series and dumps in $out"
