#!/usr/bin/env bash
# compute vibration/modes benchmark (not part of ctest), through LAMMPS:
#  1. KPM against dense on a 5 000-grain disordered 2D packing: L1 difference
#     of the two normalised histograms and the speed-up (wall time of each run);
#  2. KPM spectrum of a packing with more than 300 000 degrees of freedom.
# Usage: bench/modes_kpm.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${1:-$here/../build}/lammps/lmp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
kpm_options="moments 400 vectors 32"

run() {    # name nx ny method extra: prints the wall time of the LAMMPS run
  local start end
  start=$(date +%s.%N)
  "$lmp" -in "$here/in.modes_kpm" -screen none -nocite -log "log.$1" \
    -var nx "$2" -var ny "$3" -var method "$4" -var fmax 60 -var out "hist.$1" -var extra "$5"
  end=$(date +%s.%N)
  awk -v s="$start" -v e="$end" 'BEGIN {printf "%.2f", e - s}'
}
dofs() { awk '/^Created .* atoms/ {print 2 * $2}' "log.$1" | tail -n 1; }

t_dense=$(run dense 100 50 dense "")
t_kpm=$(run kpm 100 50 kpm "$kpm_options")
echo "5000-grain packing ($(dofs dense) DOFs, 2 rows clamped), 20 bins, KPM $kpm_options:"
echo "  dense run ${t_dense} s, KPM run ${t_kpm} s, speed-up $(awk -v d="$t_dense" -v k="$t_kpm" 'BEGIN {printf "%.1f", d / k}')"
paste <(awk 'NF == 4' hist.dense) <(awk 'NF == 4' hist.kpm) | awk '
  { w = $2 - p; p = $2; l1 += ($7 - $3 < 0 ? $3 - $7 : $7 - $3); e += $8 }
  END { w = 2 * ($2 - w / 2) / NR; printf "  L1(KPM - dense) = %.4f, summed KPM error estimate = %.4f\n", l1 * w, e * w }'

t_large=$(run large 500 304 kpm "$kpm_options")
echo "large packing ($(dofs large) DOFs): KPM run (setup included) ${t_large} s"
awk 'NF == 4 {printf "  f %6.1f  density %.5f +- %.5f\n", $2, $3, $4}' hist.large
