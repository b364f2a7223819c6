#!/usr/bin/env bash
# ACOUSTIC driver: installs what is missing, builds what is not built, runs.
#
#   ./run.sh demo     the main job (avalanche demo; see README.md)
#   ./run.sh test     the whole test suite (CTest)
#   ./run.sh build    only install and build
#
# On a fresh Debian 12 machine run it as root: it installs the Debian packages
# it needs and fetches through apt the source of LAMMPS 4 Feb 2025 (Debian
# 13's lammps package) and of LIGGGHTS 3.8.0 (Debian 12's liggghts package),
# from deb-src entries for trixie and for the machine's own suite that it adds
# in files of their own, derived from the machine's Debian entry.
# Environment:
#   ACOUSTIC_CACHE       where the sources are kept (default /var/cache/acoustic)
#   LAMMPS_SOURCE_DIR    use this LAMMPS source tree (4 Feb 2025 or later) instead
#   LIGGGHTS_SOURCE_DIR  use this LIGGGHTS-PUBLIC 3.8 source tree instead
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
  python3-numpy python3-scipy python3-matplotlib python3-pytest python3-pytest-xdist python3-pip python3-setuptools
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
    [ -f "$f" ] && [ "$f" != "$lammps_sources_file" ] && [ "$f" != "$liggghts_sources_file" ] || continue
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

# a deb-src entry for `suite` in the file `file` of its own, next to the
# machine's entries (what: the comment naming the source it is for)
add_source_entry() {
  local suite=$1 file=$2 what=$3 uri key
  [ -f "$file" ] && return
  read -r uri key < <(debian_archive_entry)
  say "adding a deb-src entry for $suite ($uri) in $file"
  {
    echo "# added by ACOUSTIC's run.sh: $what"
    echo "Types: deb-src"
    echo "URIs: $uri"
    echo "Suites: $suite"
    echo "Components: main"
    if [ -n "$key" ]; then echo "Signed-By: $key"; fi
  } | as_root tee "$file" >/dev/null
  apt_updated=0
}

# the Debian version of source package `pkg` whose upstream part is `up`
# (the first apt lists), and the SHA256 apt's Sources index gives `tarball`
source_version() {
  apt-cache showsrc "$1" | awk -v up="$2" '/^Version:/ && index($2, up "-") == 1 { print $2; exit }'
}
source_sha256() {
  apt-cache showsrc "$1" | awk -v v="$2" -v f="$3" '
    /^Version:/ { cur = $2 } /^Checksums-Sha256:/ { on = 1; next } /^[A-Za-z-]+:/ { on = 0 }
    on && cur == v && $3 == f { print $1; exit }'
}

# fetch the orig tarball of pkg=version through apt into the cache (once),
# check it against the SHA256 of apt's Sources index, unpack its top
# directory `dirname` into the cache
fetch_orig_tarball() {
  local pkg=$1 version=$2 tarball=$3 dirname=$4 sha
  as_root mkdir -p "$cache"
  if [ ! -f "$cache/$tarball" ]; then
    say "fetching Debian's $pkg $version source into $cache"
    # the .dsc or the Debian part of this version may be missing from the
    # archive: apt then fails after the tarball arrived, which the checksum
    # below settles
    (cd "$cache" && as_root apt-get source --download-only -qq "$pkg=$version" >/dev/null 2>&1) || true
  fi
  [ -f "$cache/$tarball" ] || die "apt-get source $pkg=$version did not deliver $tarball"
  sha=$(source_sha256 "$pkg" "$version" "$tarball")
  [ -n "$sha" ] || die "apt's Sources index lists no SHA256 for $tarball"
  echo "$sha  $cache/$tarball" | sha256sum -c --quiet - \
    || die "$cache/$tarball does not match the SHA256 of apt's Sources index; delete it and rerun"
  say "unpacking $tarball (SHA256 checked)"
  as_root rm -rf "$cache/$dirname.tmp"
  as_root mkdir -p "$cache/$dirname.tmp"
  as_root tar -xJf "$cache/$tarball" --no-same-owner -C "$cache/$dirname.tmp"
  as_root mv "$cache/$dirname.tmp/$dirname" "$cache/$dirname"
  as_root rm -rf "$cache/$dirname.tmp"
}

# LAMMPS's source: lammps_$lammps_upstream.orig.tar.xz, from trixie
fetch_lammps_source() {
  add_source_entry trixie "$lammps_sources_file" "the source of LAMMPS 4 Feb 2025 (Debian 13)"
  apt_update
  local version
  version=$(source_version lammps "$lammps_upstream")
  [ -n "$version" ] || die "apt knows no lammps source package $lammps_upstream-*; check $lammps_sources_file"
  fetch_orig_tarball lammps "$version" "lammps_$lammps_upstream.orig.tar.xz" "$lammps_dirname"
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

# LIGGGHTS 3.8.0: the upstream source of Debian 12 (bookworm)'s liggghts
# package, from a deb-src entry for the machine's own suite (added only if
# apt does not know the source package yet)
liggghts_upstream=3.8.0+repack1
liggghts_dirname=LIGGGHTS-PUBLIC-3.8.0
liggghts_sources_file=/etc/apt/sources.list.d/acoustic-liggghts-source.sources

fetch_liggghts_source() {
  local version codename
  version=$(source_version liggghts "$liggghts_upstream")
  if [ -z "$version" ]; then
    codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
    add_source_entry "$codename" "$liggghts_sources_file" "the source of LIGGGHTS 3.8.0 (Debian 12)"
    apt_update
    version=$(source_version liggghts "$liggghts_upstream")
  fi
  [ -n "$version" ] || die "apt knows no liggghts source package $liggghts_upstream-*; check $liggghts_sources_file"
  fetch_orig_tarball liggghts "$version" "liggghts_$liggghts_upstream.orig.tar.xz" "$liggghts_dirname"
}

liggghts_source() {
  if [ -n "${LIGGGHTS_SOURCE_DIR:-}" ]; then
    [ -f "$LIGGGHTS_SOURCE_DIR/src/Make.sh" ] \
      || die "LIGGGHTS_SOURCE_DIR=$LIGGGHTS_SOURCE_DIR has no src/Make.sh"
    return
  fi
  if [ ! -f "$cache/$liggghts_dirname/src/Make.sh" ]; then
    fetch_liggghts_source
  fi
  LIGGGHTS_SOURCE_DIR=$cache/$liggghts_dirname
}

configure_and_build() {
  install_packages
  install_tools
  lammps_source
  liggghts_source
  say "LAMMPS source: $LAMMPS_SOURCE_DIR"
  say "LIGGGHTS source: $LIGGGHTS_SOURCE_DIR"
  mkdir -p "$build"
  cmake -S "$top" -B "$build" -DLAMMPS_SOURCE_DIR="$LAMMPS_SOURCE_DIR" \
    -DLIGGGHTS_SOURCE_DIR="$LIGGGHTS_SOURCE_DIR" >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log"; die "configure failed"; }
  say "building in $build (log: $build/build.log)"
  cmake --build "$build" -j "$jobs" >"$build/build.log" 2>&1 \
    || { tail -n 60 "$build/build.log"; die "build failed (full log: $build/build.log)"; }
  say "built: $build/lammps/lmp and $build/lammps/liblammps.so, $build/liggghts-tree/src/lmp_acoustic"
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
    # as many tests at a time as cores; a test of 2 MPI ranks takes 2 (its
    # PROCESSORS property)
    ctest --test-dir "$build" --output-on-failure -j "$jobs" ;;
  demo)
    configure_and_build
    exec "$top/examples/avalanche/run.sh" "$build" ;;
  *)
    sed -n '2,17p' "$0"; exit 2 ;;
esac
