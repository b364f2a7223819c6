#!/usr/bin/env bash
# The incline demo: the same layer at three tilt angles, on 2 MPI ranks.
# Usage: examples/incline/run.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:-$here/../../build}
lmp=$build/lammps/lmp
out=$here/out
mkdir -p "$out"
cd "$out"
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
for theta in 10 20 30; do
  mpirun -np 2 "$lmp" -in "$here/in.incline" -var theta "$theta" -log "log.theta$theta" \
    -screen none -nocite
  grep '^incline:' "log.theta$theta"
done
echo "logs in $out"
