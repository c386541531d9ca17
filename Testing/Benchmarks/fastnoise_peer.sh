#!/bin/bash
# Builds and runs the FastNoise Lite peer of the terrain noise benchmark (issue 22). FastNoise Lite
# is one MIT-licensed header, not a Debian package: give its path in FASTNOISELITE_H, or this
# script downloads it (https://github.com/Auburn/FastNoiseLite, Cpp/FastNoiseLite.h). Not part of
# the CMake build or of CI.
# Usage: Testing/Benchmarks/fastnoise_peer.sh [threads=2]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
work="${TMPDIR:-/tmp}/parafluid-fastnoise-peer"
mkdir -p "$work"
header="${FASTNOISELITE_H:-$work/FastNoiseLite.h}"
if [ ! -f "$header" ]; then
  curl -fsSL -o "$header" https://raw.githubusercontent.com/Auburn/FastNoiseLite/master/Cpp/FastNoiseLite.h
fi
core="$root/Filters/Terrain/Core"
g++ -O3 -DNDEBUG -std=c++17 -fopenmp -I"$(dirname "$header")" -I"$core" -I"$root/Filters/Common/Core" \
  -o "$work/peer" "$here/fastnoise_peer.cxx" "$core/FractalNoise.cxx" "$core/PerlinNoise.cxx"
"$work/peer" "$@"
