#!/usr/bin/env bash
# The runs behind RESULTS.md: the tilt ramp for every H/d (periodic, L = 80 d
# for H <= 6 d, 40 d above, to keep the machine time modest),
# with and without 70 kHz; t_con above theta_m for one H/d (Fig. 8); the
# free-ends variant (Fig. 5) for H = 6 d.  Outputs in out/prod (git-ignored).
# Usage: examples/avalanche/run_production.sh BUILD_DIR [H ...]
#   AVALANCHE_TCON_H (default 6): H/d of the t_con runs ("" to skip)
#   AVALANCHE_FREE (default 1): 1 runs the free-ends variant
#   AVALANCHE_OUT (default out/prod): output directory
#   AVALANCHE_SOURCE (default bottom): source of in.avalanche, bottom (paper 000)
#     or base (the rough base; the source of the tables of RESULTS.md)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:-$here/../../build}; shift || true
build=$(cd "$build" 2>/dev/null && pwd || echo "$build")   # absolute: the runs cd
lmp=$build/lammps/lmp
heights=("$@"); [ ${#heights[@]} -gt 0 ] || heights=(3 6 8.7 11.4 14.4)
Lthin=${AVALANCHE_L:-80}    # L/d for H <= 6 d
Lthick=${AVALANCHE_L_THICK:-40}   # L/d for H > 6 d
kappa=0.3
source=${AVALANCHE_SOURCE:-bottom}
tcon_h=${AVALANCHE_TCON_H-6}
free=${AVALANCHE_FREE:-1}
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mpi=(mpirun -np "${AVALANCHE_NP:-2}")
if mpirun --version 2>/dev/null | grep -q "Open MPI"; then mpi+=(--oversubscribe); fi
lmprun() { "${mpi[@]}" "$lmp" -nocite -echo none -screen none "$@"; }
top=${AVALANCHE_OUT:-$here/out/prod}
mkdir -p "$top"
summary=$top/summary.txt
t00=$SECONDS
for H in "${heights[@]}"; do
  d=$top/H$H; mkdir -p "$d"; cd "$d"
  t0=$SECONDS
  L=$(awk -v h="$H" -v a="$Lthin" -v b="$Lthick" 'BEGIN{print (h <= 6 ? a : b)}')
  lmprun -in "$here/in.deposit" -var dir "$here" -var H "$H" -var L "$L" -var out deposit.restart -log log.deposit
  grep '^deposit:' log.deposit | sed "s/^/H$H /" >> "$summary"
  for f in 0 70e3; do
    tag=f${f%e3}; t1=$SECONDS
    # first tested angle 10 deg; 4 deg for thick layers at 70 kHz, which flow below 10 deg
    theta0=$(awk -v h="$H" -v f="$f" 'BEGIN{print (h > 10 && f > 0 ? 4 : 10)}')
    lmprun -in "$here/in.avalanche" -var dir "$here" -var restart deposit.restart -var tag "$tag" \
      -var freq "$f" -var kappa "$kappa" -var source "$source" -var theta0 "$theta0" -var thetamax 30 -var dumpevery 20 \
      -var dumplocal 1 -log "log.$tag"
    echo "H$H $(grep 'theta_m =' "log.$tag" | sed 's/^avalanche //')  wall $((SECONDS - t1)) s" >> "$summary"
  done
  echo "H$H done in $((SECONDS - t0)) s" >> "$summary"
done
# t_con above theta_m (Fig. 8): from the last state below theta_m that did not flow
# (stable, stopped or local: TAG.static.restart), one angle each
if [ -n "$tcon_h" ] && [ -d "$top/H$tcon_h" ]; then
  cd "$top/H$tcon_h"
  for f in 0 70e3; do
    tag=f${f%e3}
    tm=$(sed -n 's/.*theta_m = \([0-9.]*\) deg.*/\1/p' "log.$tag")
    [ -n "$tm" ] && [ -f "$tag.static.restart" ] || continue
    for k in 1 2 3; do
      th=$(awk -v a="$tm" -v k="$k" 'BEGIN{printf "%.1f", a + k}')
      t1=$SECONDS
      lmprun -in "$here/in.avalanche" -var dir "$here" -var restart "$tag.static.restart" -var pre 0 \
        -var tag "tcon_${tag}_$th" -var freq "$f" -var kappa "$kappa" -var source "$source" -var theta0 "$th" -var thetamax "$th" \
        -var tfollow 1.2 -var dumpevery 0 -log "log.tcon_${tag}_$th"
      echo "H$tcon_h tcon $(grep 'theta_m =' "log.tcon_${tag}_$th" | sed 's/^avalanche //')  wall $((SECONDS - t1)) s" >> "$summary"
    done
  done
fi
# free ends (paper 000 Fig. 5): layer on the middle 60 % of a 160 d base, observed in the middle 20 %
if [ "$free" = 1 ]; then
  d=$top/free_H6; mkdir -p "$d"; cd "$d"
  lmprun -in "$here/in.deposit" -var dir "$here" -var H 6 -var L 160 -var free 1 -var span 0.6 \
    -var out deposit.restart -log log.deposit
  grep '^deposit:' log.deposit | sed "s/^/free /" >> "$summary"
  for f in 0 70e3; do
    tag=f${f%e3}; t1=$SECONDS
    lmprun -in "$here/in.avalanche" -var dir "$here" -var restart deposit.restart -var tag "$tag" \
      -var freq "$f" -var kappa "$kappa" -var source "$source" -var theta0 10 -var thetamax 30 -var obslo 0.4 -var obshi 0.6 \
      -var dumpevery 20 -log "log.$tag"
    echo "free_H6 $(grep 'theta_m =' "log.$tag" | sed 's/^avalanche //')  wall $((SECONDS - t1)) s" >> "$summary"
  done
fi
echo "all done in $((SECONDS - t00)) s" >> "$summary"
