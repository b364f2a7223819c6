#!/usr/bin/env bash
# ACOUSTIC driver: installs what is missing, builds what is not built, runs.
#
#   ./run.sh demo     the main job (avalanche demo; see README.md)
#   ./run.sh test     the whole test suite (CTest)
#   ./run.sh build    only install and build
#
# On a fresh Debian 12 machine run it as root: it installs the Debian packages
# it needs and fetches the source of LAMMPS 4 Feb 2025 (Debian 13's lammps
# package) through apt, from a deb-src entry for trixie it adds in a file of
# its own, derived from the machine's Debian entry.
# Environment:
#   ACOUSTIC_CACHE       where the LAMMPS source is kept (default /var/cache/acoustic)
#   LAMMPS_SOURCE_DIR    use this LAMMPS source tree (4 Feb 2025 or later) instead
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
  libpetsc-complex-dev libmetis-dev
  libgtest-dev patch
  python3-numpy python3-scipy python3-matplotlib python3-pytest python3-pip python3-setuptools
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

# the Python tools (tools/, package acoustic_tools) in Debian's interpreter,
# editable, unless acoustic_tools already imports from this checkout's tools/
install_tools() {
  local found
  found=$(/usr/bin/python3 -I -c 'import acoustic_tools, os; print(os.path.realpath(acoustic_tools.__path__[0]))' \
    2>/dev/null) || true
  [ "$found" = "$(realpath "$top/tools/acoustic_tools")" ] && return
  say "installing the Python tools of $top/tools (editable)"
  as_root /usr/bin/python3 -m pip install -q --root-user-action=ignore --no-deps --no-build-isolation \
    --no-index --break-system-packages \
    -e "$top/tools" >/dev/null
}

# LAMMPS "4 Feb 2025": the upstream source of Debian 13 (trixie)'s lammps package
lammps_upstream=20250204+dfsg.1
lammps_dirname=lammps-4Feb2025
lammps_sources_file=/etc/apt/sources.list.d/acoustic-lammps-source.sources

# the URI and keyring of the machine's Debian archive entry (the one serving
# the main suite of this release), from deb822 or one-line apt sources
debian_archive_entry() {
  local codename f
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  [ -n "$codename" ] || die "cannot tell the Debian release from /etc/os-release"
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && [ "$f" != "$lammps_sources_file" ] || continue
    awk -v suite="$codename" '
      /^[[:space:]]*$/ { if (uri != "" && hit) { print uri, key; exit } uri = ""; key = ""; hit = 0; next }
      /^URIs:/ { uri = $2 }
      /^Signed-By:/ { key = $2 }
      /^Suites:/ { for (k = 2; k <= NF; k++) if ($k == suite) hit = 1 }
      END { if (uri != "" && hit) print uri, key }' "$f"
  done | head -n 1 | grep . && return
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    sed -nE "s/^deb[[:space:]]+(\[[^]]*signed-by=([^] ]+)[^]]*\][[:space:]]+)?([^[:space:]]+)[[:space:]]+$codename[[:space:]].*/\3 \2/p" "$f"
  done | head -n 1 | grep . && return
  die "found no Debian archive entry for suite $codename in the apt sources"
}

# a deb-src entry for trixie in a file of its own, next to the machine's entries
add_trixie_sources() {
  [ -f "$lammps_sources_file" ] && return
  local uri key
  read -r uri key < <(debian_archive_entry)
  say "adding a deb-src entry for trixie ($uri) in $lammps_sources_file"
  {
    echo "# added by ACOUSTIC's run.sh: the source of LAMMPS 4 Feb 2025 (Debian 13)"
    echo "Types: deb-src"
    echo "URIs: $uri"
    echo "Suites: trixie"
    echo "Components: main"
    if [ -n "$key" ]; then echo "Signed-By: $key"; fi
  } | as_root tee "$lammps_sources_file" >/dev/null
  apt_updated=0
}

# fetch lammps_$lammps_upstream.orig.tar.xz through apt, check it against the
# SHA256 of apt's Sources index, unpack it into the cache
fetch_lammps_source() {
  add_trixie_sources
  apt_update
  local version tarball sha
  version=$(apt-cache showsrc lammps | awk -v up="$lammps_upstream" \
    '/^Version:/ && index($2, up "-") == 1 { print $2; exit }')
  [ -n "$version" ] || die "apt knows no lammps source package $lammps_upstream-*; check $lammps_sources_file"
  tarball=lammps_$lammps_upstream.orig.tar.xz
  as_root mkdir -p "$cache"
  if [ ! -f "$cache/$tarball" ]; then
    say "fetching Debian's lammps $version source into $cache"
    # the .dsc of this version may be missing from the archive: apt then
    # fails after the tarballs arrived, which the checksum below settles
    (cd "$cache" && as_root apt-get source --download-only -qq "lammps=$version" >/dev/null 2>&1) || true
  fi
  [ -f "$cache/$tarball" ] || die "apt-get source lammps=$version did not deliver $tarball"
  sha=$(apt-cache showsrc lammps | awk -v v="$version" -v f="$tarball" '
    /^Version:/ { cur = $2 } /^Checksums-Sha256:/ { on = 1; next } /^[A-Za-z-]+:/ { on = 0 }
    on && cur == v && $3 == f { print $1; exit }')
  [ -n "$sha" ] || die "apt's Sources index lists no SHA256 for $tarball"
  echo "$sha  $cache/$tarball" | sha256sum -c --quiet - \
    || die "$cache/$tarball does not match the SHA256 of apt's Sources index; delete it and rerun"
  say "unpacking $tarball (SHA256 checked)"
  as_root rm -rf "$cache/$lammps_dirname.tmp"
  as_root mkdir -p "$cache/$lammps_dirname.tmp"
  as_root tar -xJf "$cache/$tarball" --no-same-owner -C "$cache/$lammps_dirname.tmp"
  as_root mv "$cache/$lammps_dirname.tmp/$lammps_dirname" "$cache/$lammps_dirname"
  as_root rm -rf "$cache/$lammps_dirname.tmp"
}

lammps_source() {
  if [ -n "${LAMMPS_SOURCE_DIR:-}" ]; then
    [ -f "$LAMMPS_SOURCE_DIR/cmake/CMakeLists.txt" ] \
      || die "LAMMPS_SOURCE_DIR=$LAMMPS_SOURCE_DIR has no cmake/CMakeLists.txt"
    return
  fi
  if [ ! -f "$cache/$lammps_dirname/cmake/CMakeLists.txt" ]; then
    fetch_lammps_source
  fi
  LAMMPS_SOURCE_DIR=$cache/$lammps_dirname
}

configure_and_build() {
  install_packages
  install_tools
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
