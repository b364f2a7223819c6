#!/usr/bin/env bash
# Paper 003's pressure series: packings at p = 1e-7 ... 1e-4, heights 8 and
# 25 d, width 24 d, several seeds; each sample is one LAMMPS run of in.sound
# (packing, static network, pulse, moduli) into out/p<p>_H<H>_s<seed>/,
# skipped when it is already there.  Runs SOUND_JOBS samples at a time
# (default 2, one core each).  Each sample's settings go to its job.json,
# the deck writes result.json, this script adds wall_seconds to it.
# Superseded by study.py run (the same samples, the same directories);
# then: examples/sound/study.py collect
# Usage: examples/sound/run_production.sh [BUILD_DIR]
# Environment: SOUND_SEEDS (default "1 2 3 4"), SOUND_PRESSURES, SOUND_HEIGHTS,
# SOUND_WIDTH (24), SOUND_DEPTH (0: 2D; > 0: 3D packings of monodisperse
# spheres, that deep), SOUND_OUT (out), SOUND_PISTON_MASS (1: the piston's
# mass in units of the grains'; other values go to ..._m<mass>/ directories),
# SOUND_PISTON_SPEED (0.001: the terminal speed of a dashpot on the piston;
# other values, 0 for a free piston, go to ..._v<speed>/ directories).
# The 3D samples of RESULTS.md:
#   SOUND_PRESSURES=1e-4 SOUND_SEEDS="1 2" SOUND_WIDTH=8 SOUND_DEPTH=8 SOUND_OUT=out3d run_production.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
lmp=$build/lammps/lmp
[ -x "$lmp" ] || { echo "no LAMMPS at $lmp (./run.sh build first)" >&2; exit 1; }
jobs=${SOUND_JOBS:-2}
seeds=${SOUND_SEEDS:-1 2 3 4}
pressures=${SOUND_PRESSURES:-1e-4 1e-5 1e-6 1e-7}
heights=${SOUND_HEIGHTS:-25 8}
width=${SOUND_WIDTH:-24}
depth=${SOUND_DEPTH:-0}
out=$here/${SOUND_OUT:-out}
mass=${SOUND_PISTON_MASS:-1}
speed=${SOUND_PISTON_SPEED:-0.001}
suffix=""
[ "$mass" = "1" ] || suffix="_m$mass"
[ "$speed" = "0.001" ] || suffix="${suffix}_v$speed"
mkdir -p "$out"
for p in $pressures; do for H in $heights; do for s in $seeds; do
  echo "$p $H $s"
done; done; done | xargs -P "$jobs" -L 1 bash -c '
  p=$0; H=$1; s=$2; dir='"$out"'/p${p}_H${H}_s${s}'"$suffix"'
  { [ -f "$dir/result.json" ] || [ -f "$dir/moduli.txt" ]; } && exit 0
  mkdir -p "$dir"
  /usr/bin/python3 -c "import sys; from acoustic_tools import sound_study; sound_study.write_sample_job(*sys.argv[1:])" \
    "$dir" $p $H $s '"$width"' '"$depth"' '"$mass"' '"$speed"'
  start=$(date +%s)
  '"$lmp"' -in '"$here"'/in.sound -var here '"$here"' -var p $p -var W '"$width"' -var D '"$depth"' -var H $H -var seed $s -var piston_mass '"$mass"' -var piston_speed '"$speed"' \
    -var dir "$dir" -log "$dir/log.lammps" -screen none -nocite \
    || { echo "p=$p H=$H seed=$s: FAILED, see $dir/log.lammps"; exit 0; }
  if [ -f "$dir/result.json" ]; then
    /usr/bin/python3 -c "import sys; from acoustic_tools import sound_study; sound_study.add_wall_seconds(*sys.argv[1:])" \
      "$dir" $(( $(date +%s) - start ))
  else
    echo "wall_seconds $(( $(date +%s) - start ))" >> "$dir/summary.txt"
  fi
  echo "p=$p H=$H seed=$s: $(grep "^moduli" "$dir/log.lammps") ($(( $(date +%s) - start )) s)"'
