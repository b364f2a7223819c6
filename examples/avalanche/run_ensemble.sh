#!/usr/bin/env bash
# Paper 000's geometry, one job at a time: a layer of H/d with free ends, LAYER d
# long, on a rough base with 50 d of bare base on each side, observed in the
# middle half of the layer (AVALANCHE_FREE=1, default), or a periodic layer
# LAYER d long observed everywhere (AVALANCHE_FREE=0: the cheap variant of the
# ensembles); one tilt ramp (0 or 70 kHz) of one packing per job,
# so that every job finishes on its own and the ensemble is built by repeating
# the command.  A job whose log already has its theta_m line is skipped; the
# deposit of a packing is made by its first job and reused by the other.
#
# Usage: examples/avalanche/run_ensemble.sh BUILD_DIR H SEED JOB [H SEED JOB ...]
#   JOB = 0 or 70e3: the tilt ramp at that frequency (Hz);
#   JOB = tcon0 or tcon70e3: t_con above theta_m (paper 000 Fig. 8): from the
#         last state of the ramp that did not flow (TAG.static.restart), the
#         layer is tilted at once to theta_m + 1, + 2 and + 3 deg (one run each),
#         (AVALANCHE_TCON_STEPS, default "1 2 3"; "" for none),
#         and to the angles of AVALANCHE_TCON_ANGLES above theta_m (e.g. "19":
#         paper 000's t_con at H = 6 d is given at 19 deg); with
#         AVALANCHE_TUNIFORM (s) the sigma criteria must hold that long for a
#         uniform flow (in.avalanche's tuniform, default 0.01 s) and the logs are
#         log.tcon_TAG_<theta>_u<tuniform>, beside those of the default
#   e.g. run_ensemble.sh build 3 1 0 3 1 70e3      (H = 3 d, packing 1, both ramps)
# Environment: AVALANCHE_FREE (1: free ends, default; 0: periodic),
#   AVALANCHE_LAYER (layer length in d, default 400 with free ends, 80 periodic),
#   AVALANCHE_EDEM, AVALANCHE_REST (contact law of the grains: Young's modulus in
#   Pa and restitution, default in.material's 1e7 and 0.3; the time step follows
#   the modulus; a deposit already in the packing's directory is reused as it is,
#   so a test of the contact law can start from the deposits of the default set),
#   AVALANCHE_OUT (default examples/avalanche/out/ensemble, ensemble_periodic, or
#   ensemble_L<LAYER> for free ends not 400 d long, with _E<EDEM> and
#   _e<REST> appended when those are set), AVALANCHE_NP (2),
#   AVALANCHE_SOURCE (bottom: paper 000's source, default; base: the rough base),
#   AVALANCHE_KAPPA (kappa_scale of the vibration network, default 0.3),
#   AVALANCHE_TFOLLOW (s, default 1.2 as paper 000), AVALANCHE_TSETTLE (s, 0.5),
#   AVALANCHE_THETA0 (first tested angle; default 10 deg, 4 deg for H > 10 d at 70 kHz),
#   AVALANCHE_SWITCH_ON (deg; a ramp with ultrasound only: the layer is first
#   tilted without it to this angle, the pre-ramp and that one tested angle at
#   0 Hz, log.quiet; it must be stable there, and the ramp goes on from its
#   state at rest, ultrasound on, 0.5 deg higher: no creep before),
#   AVALANCHE_PIECE (simulated seconds per LAMMPS process, "auto": 20000 / atoms,
#   about 20 min on 2 cores at 70 kHz, plus the angle under way; 0: one process),
#   AVALANCHE_MAXPIECES (processes per ramp in one call; default: until the ramp ends).
# A ramp runs as pieces: each angle's end state is kept (TAG.last0/1.restart,
# named by TAG.resume), so a ramp that paused or was killed goes on from its
# last whole angle when the command is repeated; outputs written after that
# angle by a killed piece are cut off first.
# Outputs: OUT/H<H>/s<SEED>/{log.deposit,log.f0,log.f70,f*.series,f*.dump,...} and
# one line per job in OUT/jobs.txt (angle, t_con, wall time); tools read them
# with examples/avalanche/collect.py.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:?usage: run_ensemble.sh BUILD_DIR H SEED FREQ [H SEED FREQ ...]}; shift
build=$(cd "$build" 2>/dev/null && pwd || echo "$build")
lmp=$build/lammps/lmp
[ -x "$lmp" ] || { echo "run_ensemble: no LAMMPS executable at $lmp (build first: ./run.sh build)" >&2; exit 1; }
[ $(($# % 3)) -eq 0 ] && [ $# -gt 0 ] || { echo "run_ensemble: arguments come in triples H SEED FREQ" >&2; exit 1; }
free=${AVALANCHE_FREE:-1}
if [ "$free" = 1 ]; then
  layer=${AVALANCHE_LAYER:-400}
  margin=50                                      # bare base on each side, d
  L=$((layer + 2 * margin))
  span=$(awk -v a="$layer" -v b="$L" 'BEGIN{printf "%.6f", a / b}')
  obslo=$(awk -v a="$layer" -v b="$L" 'BEGIN{printf "%.6f", (b - a / 2) / (2 * b)}')   # middle half of the layer
  obshi=$(awk -v x="$obslo" 'BEGIN{printf "%.6f", 1 - x}')
else
  layer=${AVALANCHE_LAYER:-80}; L=$layer; span=1; obslo=0; obshi=1
fi
kappa=${AVALANCHE_KAPPA:-0.3}                 # kappa_scale (calibrate.py, RESULTS.md)
source=${AVALANCHE_SOURCE:-bottom}
tfollow=${AVALANCHE_TFOLLOW:-1.2}
tsettle=${AVALANCHE_TSETTLE:-0.5}
if [ "$free" != 1 ]; then geometry=ensemble_periodic
elif [ "$layer" = 400 ]; then geometry=ensemble
else geometry=ensemble_L$layer; fi            # a layer-length test beside the 400 d set
contact=()                                    # a contact-law test beside the default set
if [ -n "${AVALANCHE_EDEM:-}" ]; then contact+=(-var Edem "$AVALANCHE_EDEM"); geometry+=_E$AVALANCHE_EDEM; fi
if [ -n "${AVALANCHE_REST:-}" ]; then contact+=(-var rest "$AVALANCHE_REST"); geometry+=_e$AVALANCHE_REST; fi
top=${AVALANCHE_OUT:-$here/out/$geometry}
mkdir -p "$top"; top=$(cd "$top" && pwd)
if [ "$(id -u)" -eq 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mpi=(mpirun -np "${AVALANCHE_NP:-2}")
if mpirun --version 2>/dev/null | grep -q "Open MPI"; then mpi+=(--oversubscribe); fi
lmprun() { "${mpi[@]}" "$lmp" -nocite -echo none -screen none "${contact[@]}" "$@"; }

while [ $# -gt 0 ]; do
  H=$1 seed=$2 f=$3; shift 3
  d=$top/H$H/s$seed; mkdir -p "$d"; cd "$d"
  if [ "${f#tcon}" != "$f" ]; then
    f=${f#tcon}; tag=f${f%e3}
    tm=$(sed -n 's/.*theta_m = \([0-9.]*\) deg.*/\1/p' "log.$tag" 2>/dev/null)
    if [ -z "$tm" ] || [ ! -f "$tag.static.restart" ]; then
      echo "H$H s$seed tcon $tag: no theta_m or no $tag.static.restart (run the ramp first), skipped"; continue
    fi
    angles=$(awk -v a="$tm" -v steps="${AVALANCHE_TCON_STEPS-1 2 3}" -v extra="${AVALANCHE_TCON_ANGLES:-}" 'BEGIN{
      n = split(steps, s, " "); for (k = 1; k <= n; k++) printf "%.1f ", a + s[k]
      n = split(extra, e, " "); for (i = 1; i <= n; i++) if (e[i] > a + 1e-6) printf "%.1f ", e[i]}')
    hold=(); suffix=
    if [ -n "${AVALANCHE_TUNIFORM:-}" ]; then hold=(-var tuniform "$AVALANCHE_TUNIFORM"); suffix=_u$AVALANCHE_TUNIFORM; fi
    for th in $angles; do
      ttag=tcon_${tag}_$th$suffix
      if [ -f "log.$ttag" ] && grep -q 'theta_m =' "log.$ttag"; then continue; fi
      t0=$SECONDS
      lmprun -in "$here/in.avalanche" -var dir "$here" -var restart "$tag.static.restart" -var pre 0 \
        -var tag "$ttag" -var freq "$f" -var kappa "$kappa" -var source "$source" -var theta0 "$th" -var thetamax "$th" \
        -var tfollow "$tfollow" -var obslo "$obslo" -var obshi "$obshi" -var dumpevery 0 "${hold[@]}" -log "log.$ttag"
      echo "H$H s$seed $(grep -h 'theta_m =' "log.$ttag" | sed 's/^avalanche //')  layer $layer d free $free  wall $((SECONDS - t0)) s" | tee -a "$top/jobs.txt"
    done
    continue
  fi
  tag=f${f%e3}
  if [ -f "log.$tag" ] && grep -q 'theta_m =' "log.$tag"; then
    echo "H$H s$seed $tag: done before, skipped"; continue
  fi
  if ! { [ -f deposit.restart ] && grep -q '^deposit:' log.deposit 2>/dev/null; }; then
    rm -f "log.$tag" "$tag.resume" "$tag.wall"      # a new packing: its ramps start anew
    lmprun -in "$here/in.deposit" -var dir "$here" -var H "$H" -var L "$L" -var free "$free" -var span "$span" \
      -var seed "$seed" -var out deposit.restart -log log.deposit
  fi
  piece=${AVALANCHE_PIECE:-auto}
  if [ "$piece" = auto ]; then
    piece=$(sed -n 's/^deposit: \([0-9]*\) grains on \([0-9]*\) base.*/\1 \2/p' log.deposit |
            awk '{printf "%.1f", 20000 / ($1 + $2)}')
  fi
  common=(-var dir "$here" -var tag "$tag" -var freq "$f" -var kappa "$kappa" -var source "$source"
          -var tfollow "$tfollow" -var tsettle "$tsettle" -var thetamax 30 -var obslo "$obslo" -var obshi "$obshi"
          -var dumpevery 50 -var dumplocal 1 -var tpiece "$piece")
  npiece=0
  while ! grep -q 'theta_m =' "log.$tag" 2>/dev/null; do
    if [ -n "${AVALANCHE_MAXPIECES:-}" ] && [ "$npiece" -ge "$AVALANCHE_MAXPIECES" ]; then
      echo "H$H s$seed $tag: paused after $npiece piece(s), at $(cut -d' ' -f1 "$tag.resume") deg; repeat the command to go on"
      break
    fi
    t0=$SECONDS
    if [ -f "log.$tag" ] && [ -f "$tag.resume" ]; then
      # go on after the last whole angle; drop what a killed piece wrote after it
      read -r theta tres step last next < "$tag.resume"
      # (the series line of that angle's last step stays; the one a killed piece
      # wrote there for the next angle goes, as the frames after that step)
      awk -v t="$tres" -v a="$theta" '/^#/ || $1 + 0 < t - 5e-5 || ($1 + 0 < t + 5e-5 && $2 + 0 == a + 0)' \
        "$tag.series" > "$tag.series.cut" && mv "$tag.series.cut" "$tag.series"
      for dump in "$tag.dump" "$tag.contacts"; do
        [ -f "$dump" ] || continue
        awk -v s="$step" '/^ITEM: TIMESTEP/ {getline t; keep = (t + 0 <= s); if (keep) print $0 "\n" t; next} keep' \
          "$dump" > "$dump.cut" && mv "$dump.cut" "$dump"
      done
      # the next angle as the deck wrote it (a resume file of an older deck: theta + 0.5)
      theta0=${next:-$(awk -v a="$theta" 'BEGIN{printf "%.2f", a + 0.5}')}
      lmprun -in "$here/in.avalanche" "${common[@]}" -var restart "$last" -var pre 0 -var theta0 "$theta0" \
        -var append 1 -log "log.$tag.resume"
    else
      rm -f "$tag.resume"
      theta0=${AVALANCHE_THETA0:-$(awk -v h="$H" -v f="$f" 'BEGIN{print (h > 10 && f > 0 ? 4 : 10)}')}
      start=(-var restart deposit.restart)
      if [ -n "${AVALANCHE_SWITCH_ON:-}" ] && [ "$f" != 0 ]; then
        on=$AVALANCHE_SWITCH_ON
        lmprun -in "$here/in.avalanche" -var dir "$here" -var tag quiet -var freq 0 -var kappa "$kappa" \
          -var source "$source" -var tsettle "$tsettle" -var obslo "$obslo" -var obshi "$obshi" -var dumpevery 0 \
          -var restart deposit.restart -var theta0 "$on" -var thetamax "$on" -log log.quiet
        if ! awk -v a="$on" '$1 == "angle" && $2 + 0 == a + 0 && ($4 == "stable" || $4 == "stopped") {ok = 1}
                              END {exit !ok}' log.quiet; then
          echo "run_ensemble: H$H s$seed: the layer is not at rest at $on deg without ultrasound (log.quiet); AVALANCHE_SWITCH_ON must lie below theta_m at 0 Hz" >&2
          exit 1
        fi
        start=(-var restart quiet.static.restart -var pre 0)
        theta0=$(awk -v a="$on" 'BEGIN{printf "%.2f", a + 0.5}')
      fi
      lmprun -in "$here/in.avalanche" "${common[@]}" "${start[@]}" -var theta0 "$theta0" -log "log.$tag"
    fi
    echo $((SECONDS - t0)) >> "$tag.wall"
    npiece=$((npiece + 1))
  done
  if grep -q 'theta_m =' "log.$tag"; then
    wall=$(awk '{s += $1} END {print s}' "$tag.wall")
    line="H$H s$seed $(grep -h 'theta_m =' "log.$tag" | sed 's/^avalanche //')  layer $layer d free $free  wall $wall s"
    echo "$line" | tee -a "$top/jobs.txt"
  fi
done
