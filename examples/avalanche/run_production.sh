#!/usr/bin/env bash
# The runs behind RESULTS.md, as jobs of run_ensemble.sh: one tilt ramp of one
# packing per job, each finishing on its own (about 1 to 15 minutes on 2
# cores, see RESULTS.md; the long free-ends ramps run as pieces of about 20
# minutes); a job already done is skipped and a ramp that was stopped goes on
# from its last whole angle, so the command can be repeated until everything
# is there.  Outputs in out/ensemble_periodic and
# out/ensemble (git-ignored); examples/avalanche/collect.py reads them.
#
# Usage: examples/avalanche/run_production.sh BUILD_DIR [SET ...]
#   periodic  H/d = 3, 6 (L = 80 d) and 14.4 (L = 40 d), periodic, packings
#             4871 1 2 3, 0 and 70 kHz                                  (default)
#   tcon      t_con above theta_m for H/d = 6 (and at 19 deg) and 14.4, and for
#             the free-ends H/d = 6, 11.4 and 14.4 layers at 0 and 70 kHz
#             (after their ramps of the set free)
#   free      H/d = 3, 6, 14.4, 8.7 and 11.4 with free ends, 400 d, packings
#             1 2 3 4, 0 Hz first, then 70 kHz
#   more      H/d = 8.7 and 11.4 (L = 40 d), periodic, packings 4871 1 2 3
#   kappa     the 70 kHz shift against kappa_scale: H/d = 6 (L = 80 d), packings
#             1 and 2 of the periodic set, kappa_scale 0.1, 0.2 and 1 (0.3 is
#             the periodic set), in out/kappa/k<kappa>
#   kappa_free  the same with paper 000's geometry at H/d = 8.7 (free ends,
#             400 d): packings 1 and 2 of the set free at kappa_scale 0.1 and
#             0.2, packings 3 and 4 at 0.1 (0.3 is the set free), in
#             out/kappa_free/k<kappa>
#   switch_on does the creep before the flow lower theta_m? the 70 kHz ramps
#             of the four packings of the set free at H/d = 14.4, tilted at rest
#             without ultrasound to 9.5 deg and driven from 10 deg on
#             (AVALANCHE_SWITCH_ON; the set free creeps under 70 kHz from 4 deg
#             on), in out/switch_on/at9.5; then packings 1 and 3 with
#             kappa_scale 0.17 (the band of paper 000's Fig. 3 at its own
#             14.4 d layer), driven from 11 deg on, in out/switch_on/at10.5_k0.17;
#             then the four packings at H/d = 6 with kappa_scale 0.17, tilted at
#             rest to 13 deg and driven from 13.5 deg on (out/switch_on/at13_k0.17;
#             the deposits of the set free are reused when they are there), and
#             14.4 d packings 2 and 4 at 0.17
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:-$here/../../build}; shift || true
sets=("$@"); [ ${#sets[@]} -gt 0 ] || sets=(periodic)
E=$here/run_ensemble.sh
# reuse_deposit FROM TO: a packing's deposit made by another set, copied
# (the same seed and geometry give the same deposit; making it again costs
# minutes)
reuse_deposit() {
  [ -f "$1/deposit.restart" ] && [ ! -f "$2/deposit.restart" ] || return 0
  mkdir -p "$2" && cp "$1/deposit.restart" "$1/log.deposit" "$2/"
}
seeds=(4871 1 2 3)
for set in "${sets[@]}"; do
  case $set in
    periodic)
      for s in "${seeds[@]}"; do
        AVALANCHE_FREE=0 AVALANCHE_LAYER=80 "$E" "$build" 6 "$s" 0 6 "$s" 70e3
        AVALANCHE_FREE=0 AVALANCHE_LAYER=40 "$E" "$build" 14.4 "$s" 0
        # thick layers at 70 kHz: the first tested angle is 6 deg
        AVALANCHE_FREE=0 AVALANCHE_LAYER=40 AVALANCHE_THETA0=6 "$E" "$build" 14.4 "$s" 70e3
        AVALANCHE_FREE=0 AVALANCHE_LAYER=80 "$E" "$build" 3 "$s" 0 3 "$s" 70e3
      done ;;
    tcon)
      for s in "${seeds[@]}"; do
        AVALANCHE_TCON_ANGLES=19 AVALANCHE_FREE=0 AVALANCHE_LAYER=80 "$E" "$build" 6 "$s" tcon0 6 "$s" tcon70e3
      done
      # free ends, H = 6 d, 0 and 70 kHz: theta_m + 1 deg and 19 deg (paper
      # 000's angle)
      for s in 1 2 3 4; do
        AVALANCHE_TCON_STEPS=1 AVALANCHE_TCON_ANGLES=19 "$E" "$build" 6 "$s" tcon0 6 "$s" tcon70e3
      done
      for s in "${seeds[@]}"; do
        AVALANCHE_FREE=0 AVALANCHE_LAYER=40 "$E" "$build" 14.4 "$s" tcon0 14.4 "$s" tcon70e3
      done
      # free ends, H = 11.4 and 14.4 d (paper 000's Fig. 8): theta_m + 1, 2, 3 deg
      for H in 11.4 14.4; do
        for s in 1 2 3 4; do "$E" "$build" "$H" "$s" tcon0 "$H" "$s" tcon70e3; done
      done ;;
    free)
      # 0 Hz ramps of every H/d first (cheap), then the 70 kHz ones, H/d = 3,
      # 6 and 14.4 before 8.7 and 11.4; a 70 kHz ramp creeps at every angle
      # (1.3 s each) and runs as pieces of about 20 min; at H = 14.4 d it is
      # several hours
      for H in 3 6 14.4 8.7 11.4; do
        for s in 1 2 3 4; do "$E" "$build" "$H" "$s" 0; done
      done
      for H in 3 6 14.4 8.7 11.4; do
        for s in 1 2 3 4; do "$E" "$build" "$H" "$s" 70e3; done
      done ;;
    more)
      for H in 8.7 11.4; do
        for s in "${seeds[@]}"; do
          AVALANCHE_FREE=0 AVALANCHE_LAYER=40 "$E" "$build" "$H" "$s" 0
          AVALANCHE_FREE=0 AVALANCHE_LAYER=40 AVALANCHE_THETA0=6 "$E" "$build" "$H" "$s" 70e3
        done
      done ;;
    kappa)
      for s in 1 2; do
        for k in 0.1 0.2 1; do
          d=$here/out/kappa/k$k/H6/s$s; mkdir -p "$d"
          cp -n "$here/out/ensemble_periodic/H6/s$s/deposit.restart" "$here/out/ensemble_periodic/H6/s$s/log.deposit" "$d/"
          AVALANCHE_KAPPA=$k AVALANCHE_OUT=$here/out/kappa/k$k AVALANCHE_FREE=0 AVALANCHE_LAYER=80 "$E" "$build" 6 "$s" 70e3
        done
      done ;;
    kappa_free)
      # the deposits are made again by each set's first job (the same packings:
      # the deposit is deterministic; log.deposit says so against the set free)
      for s in 1 2; do
        for k in 0.1 0.2; do
          AVALANCHE_KAPPA=$k AVALANCHE_OUT=$here/out/kappa_free/k$k "$E" "$build" 8.7 "$s" 70e3
        done
      done
      for s in 3 4; do
        AVALANCHE_KAPPA=0.1 AVALANCHE_OUT=$here/out/kappa_free/k0.1 "$E" "$build" 8.7 "$s" 70e3
      done ;;
    switch_on)
      # the deposits are made again (the same packings, as for kappa_free)
      for s in 1 2 3 4; do
        AVALANCHE_SWITCH_ON=9.5 AVALANCHE_OUT=$here/out/switch_on/at9.5 "$E" "$build" 14.4 "$s" 70e3
      done
      for s in 1 3; do
        AVALANCHE_KAPPA=0.17 AVALANCHE_SWITCH_ON=10.5 AVALANCHE_OUT=$here/out/switch_on/at10.5_k0.17 \
          "$E" "$build" 14.4 "$s" 70e3
      done
      for s in 1 2 3 4; do
        reuse_deposit "$here/out/ensemble/H6/s$s" "$here/out/switch_on/at13_k0.17/H6/s$s"
        AVALANCHE_KAPPA=0.17 AVALANCHE_SWITCH_ON=13 AVALANCHE_OUT=$here/out/switch_on/at13_k0.17 \
          "$E" "$build" 6 "$s" 70e3
      done
      for s in 2 4; do
        AVALANCHE_KAPPA=0.17 AVALANCHE_SWITCH_ON=10.5 AVALANCHE_OUT=$here/out/switch_on/at10.5_k0.17 \
          "$E" "$build" 14.4 "$s" 70e3
      done ;;
    *) echo "run_production: unknown set $set (periodic, tcon, free, more, kappa, kappa_free, switch_on)" >&2; exit 1 ;;
  esac
done
