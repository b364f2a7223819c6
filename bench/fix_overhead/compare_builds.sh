#!/usr/bin/env bash
# The default solver of two builds on the same flowing 2D layer (32 000
# grains tilted by 25 degrees, coupled every simulated millisecond for 10
# ms, 2 ranks): the loop time and the updates' time of each, measured in
# turn (A B A B A B) so that the ratios hold when the machine's speed drifts,
# and whether the two give bitwise the same positions and velocities at the
# end.  Usage: bench/fix_overhead/compare_builds.sh OLD_BUILD_DIR NEW_BUILD_DIR
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
old=$(cd "$1" && pwd)/lammps/lmp new=$(cd "$2" && pwd)/lammps/lmp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
cd "$work"    # the deck takes a file name without a path
run() {    # lmp tag: prints loop time and fix time of the run
  mpirun -np 2 --oversubscribe "$1" -in "$here/in.layer2d" -var nx 400 -var rows 80 -var model normal \
    -var solver auto -var tilt 25 -var positions "end.$2" -var write_positions 1 -var last_columns "f_ac[5]" \
    -log "$work/log.$2" -screen none -nocite
  awk '/^ *Step +Atoms/ {on=1; first=""; next} on && /^ *[0-9]/ {if (first == "") first=$13; last=$13}
       /^Loop time of/ {loop=$4; on=0} END {printf "%s %s\n", loop, last - first}' "$work/log.$2"
}
printf '%-6s %10s %10s %10s %10s %8s %8s\n' pair old_loop new_loop old_fix new_fix loop_r fix_r
for k in 1 2 3; do
  read -r lo fo < <(run "$old" old$k)
  read -r ln fn < <(run "$new" new$k)
  awk -v k="$k" -v lo="$lo" -v ln="$ln" -v fo="$fo" -v fn="$fn" \
    'BEGIN {printf "%-6d %10.2f %10.2f %10.3f %10.3f %8.3f %8.3f\n", k, lo, ln, fo, fn, ln / lo, fn / fo}'
  if cmp -s "$work/end.old$k" "$work/end.new$k"; then echo "       end state: bitwise identical"
  else echo "       end state: DIFFERENT"; fi
done
echo "loop_r = new / old loop time, fix_r = new / old time of the updates in the run (ratios per pair)"
