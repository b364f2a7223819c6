#!/usr/bin/env bash
# Cost of fix acoustic/mindlin: time split of one update and overhead ratio
# (fix time / total loop time) for 2D layers of 2 000, 8 000 and 32 000 grains
# and a 3D layer of 32 000 grains, coupling once per simulated millisecond,
# on 2 MPI ranks.  Usage: bench/fix_overhead/run.sh [BUILD_DIR] [model]
# (ACOUSTIC_BENCH_SOLVER=lu|ldlt|mumps: another solver; ACOUSTIC_BENCH_3D=0: 2D only)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${1:-$here/../../build}/lammps/lmp
model=${2:-normal}
solver=${ACOUSTIC_BENCH_SOLVER:-auto}    # solver keyword of the fix (auto, mumps, lu, ldlt)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}

printf '%-10s %7s %8s | %8s %8s %8s %8s %8s | %7s %8s %8s %8s %8s\n' case grains contacts \
  gather assembly factor solve update fact/all setup_s fix_s loop_s overhead
run_case() {    # name deck vars...
  local name=$1 deck=$2; shift 2
  mpirun -np 2 --oversubscribe "$lmp" -in "$here/$deck" -var model "$model" -var solver "$solver" "$@" \
    -log "$work/log.$name" -screen none -nocite
  awk -v name="$name" '
    /^ *Step +Atoms/ {inthermo=1; first=""; last=""; next}
    inthermo && /^ *[0-9]/ {if (first == "") first=$0; last=$0; next}
    /^Loop time of/ {loop=$4; inthermo=0}
    END {
      split(first, s, " ")
      split(last, f, " ")
      # f: step atoms contacts mean gather assembly factor solve update nanal nfact nreuse total
      # the first row is the update at setup (outside the loop time)
      fix = f[13] - s[13]
      printf "%-10s %7d %8d | %8.4f %8.4f %8.4f %8.4f %8.4f | %3d/%-3d %8.2f %8.2f %8.2f %7.1f%%\n",
        name, f[2], f[3], f[5], f[6], f[7], f[8], f[9], f[11], f[11]+f[12], s[13], fix, loop, 100*fix/loop
    }' "$work/log.$name"
}
run_case 2d_2000 in.layer2d -var nx 100 -var rows 20
run_case 2d_8000 in.layer2d -var nx 200 -var rows 40
run_case 2d_32000 in.layer2d -var nx 400 -var rows 80
[ "${ACOUSTIC_BENCH_3D:-1}" = 1 ] && run_case 3d_32000 in.layer3d -var nx 20 -var nz 20
echo "times in seconds: the split is that of the last update; fact/all = factorisations / solves"
echo "(the others reuse the last solution, or its factors in BiCGSTAB); setup_s = the update at setup;"
echo "fix_s = the updates during the run; loop_s = LAMMPS loop time; overhead = fix_s / loop_s"
