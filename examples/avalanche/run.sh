#!/usr/bin/env bash
# The main job (./run.sh demo): paper 000's tilt ramp on a layer of H = 6 d
# (80 d long, periodic), without and with 70 kHz ultrasound from the base;
# prints a line per angle and the two avalanche angles theta_m at the end.
# 2 MPI ranks.  It is `study.py demo` (options: study.py demo --help).
# Usage: examples/avalanche/run.sh BUILD_DIR [study.py demo options]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${1:-$here/../../build}
shift || true
exec /usr/bin/python3 "$here/study.py" demo --build "$build" "$@"
