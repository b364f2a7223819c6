#!/usr/bin/env bash
# Cost of fix acoustic/mindlin, coupling once per simulated millisecond
# (every 500 steps of 2 us), on 2 MPI ranks unless said otherwise.  Each line
# gives the time split of the last update, the iterations of solver
# iterative, the peak resident memory per rank (VmHWM from /proc), and the
# overhead: the updates' wall time in the run over the run's loop time.
#
#   bench/fix_overhead/run.sh [BUILD_DIR] [set ...]
#
# sets (default: 2d 3d):
#   2d        2D crystals of 2 000, 8 000 and 32 000 grains, every solver
#             that suits them (auto, iterative with damping 0.05)
#   2dflow    the 2D 32 000-grain layer tilted by 25 degrees (flowing),
#             solver auto, undamped and damped
#   3d        a random 3D layer of 32 000 grains (in.pour3d), static and
#             flowing, damping 0 and 0.05, solvers auto and iterative
#   3diter    the 32 000-grain 3D layer, static and flowing, damping 0.05,
#             solver iterative only
#   3d100k    a random 3D layer of 100 000 grains, static, damping 0.05,
#             solver iterative
#   scaling   the 32 000-grain 3D layer on 1 and 2 ranks, solver iterative
#   sweep     one update of the 32 000-grain 3D layer: iterations and time
#             against the drive frequency and the damping ratio
#   reuse     the 32 000-grain 3D layer at rest, reuse yes, solver iterative
#   direct    one update of the 32 000-grain 3D layer, damping 0.05, by the
#             direct solvers: MUMPS on rank 0 with METIS (auto, the default
#             ordering in 3D) and with its own ordering, block low-rank
#             factors, MUMPS on both ranks from distributed input; and the
#             largest difference of their friction factors from those of
#             auto (bench/factors_diff.py)
# The random layers are poured once (a few minutes for 32 000 grains, about
# 35 for 100 000) and kept in ACOUSTIC_BENCH_CACHE (default
# /var/cache/acoustic/bench).  Variables: ACOUSTIC_BENCH_FREQUENCY (Hz, 3D
# sets, default 5000: a quarter of the 3D layer's band, which ends near
# 20 kHz).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
shift || true
lmp=$build/lammps/lmp
sets=("$@")
[ ${#sets[@]} -gt 0 ] || sets=(2d 3d)
cache=${ACOUSTIC_BENCH_CACHE:-/var/cache/acoustic/bench}
frequency=${ACOUSTIC_BENCH_FREQUENCY:-5000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$cache"
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}

# one rank of LAMMPS, reporting its peak resident memory when it ends
cat > "$work/rank.sh" <<'EOF'
#!/usr/bin/env bash
"$@" &
pid=$!
peak=0
while kill -0 $pid 2>/dev/null; do
  now=$(awk '/^VmHWM/ {print $2}' /proc/$pid/status 2>/dev/null || echo 0)
  [ -n "$now" ] && [ "$now" -gt "$peak" ] && peak=$now
  sleep 0.2
done
wait $pid
status=$?
echo "${OMPI_COMM_WORLD_RANK:-0} $peak" >> "$ACOUSTIC_BENCH_MEMORY"
exit $status
EOF
chmod +x "$work/rank.sh"

printf '%-22s %3s %7s %8s | %7s %7s %7s %7s %5s | %8s %8s %7s %7s\n' case np grains contacts \
  gather setup solve update iters fix_s loop_s overhd MB/rank

# run_case name ranks deck vars...: one LAMMPS run, one line of the table
run_case() {
  local name=$1 np=$2 deck=$3
  shift 3
  export ACOUSTIC_BENCH_MEMORY=$work/mem.$name
  rm -f "$ACOUSTIC_BENCH_MEMORY"
  # in the work directory: the decks take file names without a path
  (cd "$work" && mpirun -np "$np" --oversubscribe -x ACOUSTIC_BENCH_MEMORY "$work/rank.sh" "$lmp" \
    -in "$here/$deck" "$@" -log "$work/log.$name" -screen none -nocite)
  local mb
  mb=$(awk '$2 > m {m = $2} END {printf "%.0f", m / 1024}' "$ACOUSTIC_BENCH_MEMORY")
  awk -v name="$name" -v np="$np" -v mb="$mb" '
    /^ *Step +Atoms/ {inthermo=1; first=""; last=""; next}
    inthermo && /^ *[0-9]/ {if (first == "") first=$0; last=$0; next}
    /^Loop time of/ {loop=$4; inthermo=0}
    END {
      split(first, s, " "); split(last, f, " ")
      # columns: step atoms contacts mean gather assembly factorisation solve update
      #          analyses factorisations reuses total residual iterations
      # the first row is the update at setup (outside the loop time)
      fix = f[13] - s[13]
      share = (loop > 0) ? sprintf("%6.1f%%", 100 * fix / loop) : "     -"
      printf "%-22s %3d %7d %8d | %7.3f %7.3f %7.3f %7.3f %5d | %8.2f %8.2f %s %7s\n",
        name, np, f[2], f[3], f[5], f[6] + f[7], f[8], f[9], f[15], fix, loop, share, mb
    }' "$work/log.$name"
  if grep -q "^WARNING: fix acoustic/mindlin" "$work/log.$name"; then
    grep -m 1 "^WARNING: fix acoustic/mindlin" "$work/log.$name" | cut -c 1-160 | sed 's/^/    /'
  fi
}

# a random 3D layer of $1 grains, $2 grains wide, poured once
layer3d() {
  local data=$cache/layer3d_$1.data
  if [ ! -f "$data" ]; then
    echo "(pouring a random 3D layer of $1 grains into $data)" >&2
    mpirun -np 2 --oversubscribe "$lmp" -in "$here/in.pour3d" -var ngrains "$1" -var width "$2" \
      -var out "$data.tmp" -log "$work/log.pour$1" -screen none -nocite
    mv "$data.tmp" "$data"
  fi
  echo "$data"
}

for set in "${sets[@]}"; do
  case $set in
    2d)
      for size in "100 20 2000" "200 40 8000" "400 80 32000"; do
        read -r nx rows n <<< "$size"
        run_case "2d_${n}_auto" 2 in.layer2d -var nx "$nx" -var rows "$rows" -var solver auto -var model normal
        run_case "2d_${n}_iter_z0.05" 2 in.layer2d -var nx "$nx" -var rows "$rows" -var solver iterative \
          -var damping 0.05 -var model normal
      done ;;
    2dflow)
      for z in 0 0.05; do
        run_case "2dflow_32000_auto_z$z" 2 in.layer2d -var nx 400 -var rows 80 -var solver auto -var damping "$z" \
          -var model normal -var tilt 25
      done ;;
    3d)
      data=$(layer3d 32000 40)
      for flow in 0 1; do
        for z in 0 0.05; do
          for solver in auto iterative; do
            [ "$solver" = iterative ] && [ "$z" = 0 ] && continue
            run_case "3d_32k_flow${flow}_${solver}_z$z" 2 in.layer3d_random -var data "$data" -var flow "$flow" \
              -var damping "$z" -var solver "$solver" -var frequency "$frequency"
          done
        done
      done
      # undamped inside the band: the iterative solver's warning, not a hang
      run_case "3d_32k_iter_z0_maxit200" 2 in.layer3d_random -var data "$data" -var damping 0 \
        -var solver iterative -var frequency "$frequency" -var steps 500 -var maxit 200 ;;
    3diter)
      data=$(layer3d 32000 40)
      for flow in 0 1; do
        run_case "3d_32k_flow${flow}_iterative_f$frequency" 2 in.layer3d_random -var data "$data" -var flow "$flow" \
          -var damping 0.05 -var solver iterative -var frequency "$frequency"
      done ;;
    3d100k)
      data=$(layer3d 100000 72)
      run_case "3d_100k_iter_z0.05" 2 in.layer3d_random -var data "$data" -var damping 0.05 \
        -var solver iterative -var frequency "$frequency" -var steps 2500 ;;
    scaling)
      data=$(layer3d 32000 40)
      for np in 1 2; do
        run_case "3d_32k_iter_np$np" "$np" in.layer3d_random -var data "$data" -var damping 0.05 \
          -var solver iterative -var frequency "$frequency" -var steps 1500
      done ;;
    sweep)
      data=$(layer3d 32000 40)
      for z in 0.01 0.05 0.2; do
        for f in 2500 5000 10000 15000; do
          run_case "sweep_f${f}_z$z" 2 in.layer3d_random -var data "$data" -var damping "$z" \
            -var solver iterative -var frequency "$f" -var steps 0
        done
      done ;;
    direct)
      data=$(layer3d 32000 40)
      for variant in "auto|" "auto_own_ordering|ordering mumps" "auto_low_rank_1e-8|low_rank 1e-8" \
                     "auto_low_rank_1e-4|low_rank 1e-4" "mumps_distributed|" "iterative|"; do
        name=${variant%%|*} extra=${variant#*|}
        solver=${name%%_*}
        run_case "direct_$name" 2 in.layer3d_random -var data "$data" -var damping 0.05 -var solver "$solver" \
          -var frequency "$frequency" -var steps 0 -var extra "$extra" -var factors "factors.$name" -var dump_factors 1
        [ "$name" = auto ] || /usr/bin/python3 "$here/../factors_diff.py" "$work/factors.auto" "$work/factors.$name" |
          sed 's/^/    /'
      done ;;
    reuse)
      data=$(layer3d 32000 40)
      run_case "3d_32k_rest_iter_reuse" 2 in.layer3d_random -var data "$data" -var damping 0.05 \
        -var solver iterative -var frequency "$frequency" -var reuse yes -var rest 1 ;;
    *)
      echo "unknown set $set" >&2; exit 2 ;;
  esac
done
echo "times in seconds, of the last update: gather = contact walk (and gather on rank 0 for the direct"
echo "solvers); setup = assembly and factorisation (direct) or local operator and preconditioner"
echo "(iterative); solve = triangular solves or Krylov iterations; update = friction factors."
echo "fix_s = wall time of the updates during the run; loop_s = LAMMPS loop time; overhd = fix_s / loop_s;"
echo "MB/rank = largest peak resident memory of a rank."
