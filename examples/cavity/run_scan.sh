#!/usr/bin/env bash
# The runs behind RESULTS.md, one job per cavity, each finishing on its own
# (a job whose log has its "cavity result" line is skipped, so the command can
# be repeated until everything is there).  Outputs in out/<set>/<tag>/.
#
# Usage: examples/cavity/run_scan.sh BUILD_DIR SET...
#   scan    H/d = 10, L/H = 5: I_M from 1e-3 to 0.6 through N_P and N_U (7 runs)
#   paper   H/d = 30, L/H = 5, 10 s of shear at I_M = 0.3 (N_U = 10, N_P = 0.04)
#   size    H/d = 20 at I_M = 0.1 and 0.01 beside the scan's H/d = 10 (size check)
#   us      H/d = 10 at I_M = 0.01, 0.1, 0.3 with 70 kHz from the bottom
# Environment: CAVITY_NP (MPI ranks, default 1), CAVITY_OUT (default out).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:?usage: run_scan.sh BUILD_DIR SET...}; shift
build=$(cd "$build" 2>/dev/null && pwd || echo "$build")
lmp=$build/lammps/lmp
[ -x "$lmp" ] || { echo "run_scan: no LAMMPS executable at $lmp (build first: ./run.sh build)" >&2; exit 1; }
top=${CAVITY_OUT:-$here/out}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mpi=(mpirun -np "${CAVITY_NP:-1}")
if mpirun --version 2>/dev/null | grep -q "Open MPI"; then mpi+=(--oversubscribe); fi

# set tag Hd NP NU strain tskip freq: I_M = NU / sqrt(NP) (d/H)^(3/2); the
# strain (sheared length over H, recording after tskip) shrinks with I_M so
# that the cost, proportional to strain / I_M, stays bounded.  Records at
# paper 004's 10 kHz: nrec = 10 kHz x d/U = 101 / NU records per d/U
jobs() {
  case $1 in
    scan)  cat <<'EOF'
scan im1e-3   10 1000  1  7  1 0
scan im3e-3   10  100  1 12  2 0
scan im1e-2   10   10  1 22  2 0
scan im3e-2   10  100 10 42  2 0
scan im1e-1   10   10 10 62  2 0
scan im3e-1   10    1 10 102 2 0
scan im6e-1   10 0.25 10 102 2 0
EOF
    ;;
    paper) echo "paper im3e-1_H30 30 0.04 10 330 33 0" ;;   # 10 s of shear: 330 H/U, recorded after 1 s
    size)  printf '%s\n' "size im1e-1_H20 20 1.25 10 42 2 0" "size im1e-2_H20 20 1.25 1 12 2 0" ;;
    us)    printf '%s\n' "us im1e-2_f0 10 10 1 22 2 0" "us im1e-2_f70 10 10 1 22 2 70e3" \
                         "us im1e-1_f0 10 10 10 42 2 0" "us im1e-1_f70 10 10 10 42 2 70e3" \
                         "us im3e-1_f0 10 1 10 62 2 0" "us im3e-1_f70 10 1 10 62 2 70e3" ;;
    *) echo "run_scan: unknown set $1 (scan, paper, size, us)" >&2; exit 1 ;;
  esac
}

for set in "$@"; do
  jobs "$set" | while read -r s tag Hd NP NU strain tskip freq; do
    nrec=$(awk -v nu="$NU" 'BEGIN{printf "%.6g", 1e4 * 1e-3 / (nu * sqrt(9.81e-3))}')
    d=$top/$s/$tag; mkdir -p "$d"; cd "$d"
    if [ -f log.lammps ] && grep -q '^cavity result' log.lammps; then echo "$s/$tag: done before, skipped"; continue; fi
    t0=$SECONDS
    # stdin from /dev/null: mpirun would read the rest of the job list
    "${mpi[@]}" "$lmp" -nocite -echo none -screen none -in "$here/in.cavity" -var dir "$here" -var tag cavity \
      -var Hd "$Hd" -var NP "$NP" -var NU "$NU" -var strain "$strain" -var tskip "$tskip" -var freq "$freq" -var nrec "$nrec" -log log.lammps < /dev/null
    echo "$s/$tag: $(grep -h '^cavity cavity:' log.lammps | sed 's/^cavity cavity: //')  wall $((SECONDS - t0)) s" | tee -a "$top/runs.txt"
  done
done
