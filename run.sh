#!/usr/bin/env bash
# ACOUSTIC driver: installs what is missing, builds what is not built, runs.
#
#   ./run.sh demo     the main job (avalanche demo; see README.md)
#   ./run.sh test     the whole test suite (CTest)
#   ./run.sh build    only install and build
#
# On a fresh Debian 12 machine run it as root: it installs the Debian packages
# it needs and fetches Debian's LAMMPS source with `apt-get source lammps`.
# Environment:
#   ACOUSTIC_CACHE       where the LAMMPS source is kept (default /var/cache/acoustic)
#   LAMMPS_SOURCE_DIR    use this LAMMPS source tree instead of Debian's
#   ACOUSTIC_BUILD_DIR   build directory (default ./build, ignored by git)
#   ACOUSTIC_JOBS        parallel build jobs (default: number of cores)
set -euo pipefail

top=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cache=${ACOUSTIC_CACHE:-/var/cache/acoustic}
build=${ACOUSTIC_BUILD_DIR:-$top/build}
jobs=${ACOUSTIC_JOBS:-$(nproc)}

debian_packages=(
  build-essential cmake dpkg-dev
  openmpi-bin libopenmpi-dev
  libeigen3-dev libsuitesparse-dev libmumps-dev libspectra-dev liblapack-dev libblas-dev libopenblas0-serial
  libgtest-dev
  python3-lammps python3-numpy python3-matplotlib python3-pytest
)

say() { printf '[acoustic] %s\n' "$*"; }
die() { printf '[acoustic] ERROR: %s\n' "$*" >&2; exit 1; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null 2>&1; then sudo "$@"
  else die "need root to run: $* (run ./run.sh as root, or install it yourself)"
  fi
}

apt_updated=0
apt_update() {
  if [ "$apt_updated" -eq 0 ]; then
    as_root apt-get update -qq
    apt_updated=1
  fi
}

install_packages() {
  local missing=()
  for p in "${debian_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || missing+=("$p")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    say "installing Debian packages: ${missing[*]}"
    apt_update
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      "${missing[@]}" >/dev/null
  fi
}

# add deb-src next to every deb entry of the apt sources (deb822 or one-line format)
enable_deb_src() {
  local changed=0 f
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    if grep -qE '^Types:[[:space:]]*deb[[:space:]]*$' "$f"; then
      as_root sed -i -E 's/^Types:[[:space:]]*deb[[:space:]]*$/Types: deb deb-src/' "$f"
      changed=1
    fi
  done
  f=/etc/apt/sources.list
  if [ -f "$f" ] && grep -qE '^deb ' "$f" && ! grep -qE '^deb-src ' "$f"; then
    as_root sed -i -E 'p; s/^deb /deb-src /' "$f"
    changed=1
  fi
  if [ "$changed" -eq 1 ]; then apt_updated=0; fi
}

lammps_source() {
  if [ -n "${LAMMPS_SOURCE_DIR:-}" ]; then
    [ -f "$LAMMPS_SOURCE_DIR/cmake/CMakeLists.txt" ] \
      || die "LAMMPS_SOURCE_DIR=$LAMMPS_SOURCE_DIR has no cmake/CMakeLists.txt"
    return
  fi
  local dir
  dir=$(ls -d "$cache"/lammps-*/ 2>/dev/null | head -n 1 || true)
  if [ -z "$dir" ] || [ ! -f "$dir/cmake/CMakeLists.txt" ]; then
    say "fetching Debian's LAMMPS source into $cache"
    enable_deb_src
    apt_update
    as_root mkdir -p "$cache"
    (cd "$cache" && as_root apt-get source -qq lammps >/dev/null 2>&1) \
      || die "apt-get source lammps failed in $cache"
    dir=$(ls -d "$cache"/lammps-*/ | head -n 1)
  fi
  LAMMPS_SOURCE_DIR=${dir%/}
}

configure_and_build() {
  install_packages
  lammps_source
  say "LAMMPS source: $LAMMPS_SOURCE_DIR"
  mkdir -p "$build"
  cmake -S "$top" -B "$build" -DLAMMPS_SOURCE_DIR="$LAMMPS_SOURCE_DIR" >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log"; die "configure failed"; }
  say "building in $build (log: $build/build.log)"
  cmake --build "$build" -j "$jobs" >"$build/build.log" 2>&1 \
    || { tail -n 60 "$build/build.log"; die "build failed (full log: $build/build.log)"; }
  say "built: $build/lammps/lmp and $build/lammps/liblammps.so"
}

# Open MPI refuses root without these; tests run 2 ranks on 2 cores
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

cmd=${1:-}
case "$cmd" in
  build)
    configure_and_build ;;
  test)
    configure_and_build
    say "running the test suite"
    ctest --test-dir "$build" --output-on-failure ;;
  demo)
    configure_and_build
    exec "$top/examples/avalanche/run.sh" "$build" ;;
  *)
    sed -n '2,15p' "$0"; exit 2 ;;
esac
