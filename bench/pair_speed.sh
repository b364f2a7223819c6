#!/usr/bin/env bash
# Pair time per step of granular/acoustic relative to granular, same deck,
# measured in one invocation (serial).  Usage: bench/pair_speed.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${1:-$here/../build}/lammps/lmp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
pair_time() {    # Pair time of the last run (avg column of the timing breakdown)
  "$lmp" -in "$here/in.pair_speed" -var style "$1" -log "log.$2" -screen none -nocite
  awk '/^Pair/ {t=$5} END {print t}' "log.$2"
}
for repeat in 1 2 3; do
  g=$(pair_time granular g$repeat)
  a=$(pair_time granular/acoustic a$repeat)
  awk -v g="$g" -v a="$a" -v r="$repeat" \
    'BEGIN {printf "repeat %d: pair time granular %.3f s, granular/acoustic %.3f s, ratio %.3f\n", r, g, a, a/g}'
done
