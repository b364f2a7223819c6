#!/usr/bin/env bash
# valgrind memcheck of a fix acoustic/mindlin deck and a compute vibration/modes
# deck (serial, small): prints valgrind's summaries and the errors and leaks
# whose stack passes through the package (none expected).  Open MPI's own
# reports are suppressed with the suppression file it ships
# (/usr/share/openmpi/openmpi-valgrind.supp); the leaks that remain come from
# MPI_Init/MPI_Finalize.  Usage: bench/valgrind/run.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${1:-$here/../../build}/lammps/lmp
supp=/usr/share/openmpi/openmpi-valgrind.supp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
for deck in fix compute; do
  valgrind --tool=memcheck --leak-check=full --suppressions="$supp" --num-callers=40 \
    --log-file="vg.$deck" "$lmp" -in "$here/in.$deck" -screen none -log "log.$deck" >/dev/null 2>&1
  grep -q "Total wall time" "log.$deck" || { echo "$deck: the deck did not finish"; tail -3 "log.$deck"; }
  echo "== in.$deck"
  grep -E "ERROR SUMMARY|definitely lost:|indirectly lost:" "vg.$deck" | sed 's/^==[0-9]*== */  /'
  echo "  memory errors (invalid access, uninitialised values): $(grep -c 'Invalid\|uninitialised\|Conditional jump' "vg.$deck" || true)"
  package=$(awk '/^==[0-9]+== [A-Z].*(lost in loss record|Invalid|uninitialised|Conditional)/ {block=1; text=""}
                 block {text = text "\n" $0}
                 /^==[0-9]+== $/ {if (block && text ~ /ACOUSTIC|acoustic_|vibration_network|vibration_modes|granular_contact_walker|collective_error|gran_sub_mod_tangential_acoustic/) n++; block=0}
                 END {print n+0}' "vg.$deck")
  echo "  reports whose stack passes through the package: $package"
done
