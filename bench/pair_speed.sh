#!/usr/bin/env bash
# Pair time per step of pair_style granular with tangential mindlin/acoustic
# relative to tangential mindlin, same deck, measured in one invocation (serial).  Usage: bench/pair_speed.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${1:-$here/../build}/lammps/lmp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
pair_time() {    # Pair time of the last run (avg column of the timing breakdown)
  "$lmp" -in "$here/in.pair_speed" -var tangential "$1" -log "log.$2" -screen none -nocite
  awk '/^Pair/ {t=$5} END {print t}' "log.$2"
}
for repeat in 1 2 3; do
  g=$(pair_time mindlin g$repeat)
  a=$(pair_time mindlin/acoustic a$repeat)
  awk -v g="$g" -v a="$a" -v r="$repeat" \
    'BEGIN {printf "repeat %d: pair time mindlin %.3f s, mindlin/acoustic %.3f s, ratio %.3f\n", r, g, a, a/g}'
done
