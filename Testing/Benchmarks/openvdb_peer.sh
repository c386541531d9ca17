#!/bin/bash
# Builds and runs the OpenVDB peer of the particle-surface benchmark (issue 6). Needs Debian's
# libopenvdb-dev (sudo apt-get install libopenvdb-dev); not part of the CMake build or of CI.
# Usage: Testing/Benchmarks/openvdb_peer.sh [threads=2] [particles=1000000]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${TMPDIR:-/tmp}/parafluid-openvdb-peer"
g++ -O3 -DNDEBUG -std=c++17 -o "$out" "$here/openvdb_peer.cxx" -lopenvdb -ltbb -lImath-3_1 -lpthread
"$out" "$@"
