#!/bin/bash
# Builds and runs the noise peers of the terrain benchmark (issue 22), outside the CMake build and
# CI: FastNoise Lite (one MIT header: FASTNOISELITE_H, else downloaded) and FastNoise2 (MIT, a
# CMake library with its SIMD layer FastSIMD: FASTNOISE2_SRC and FASTSIMD_SRC name source trees,
# else they are cloned at the commit FastNoise2 pins; FASTNOISE2=0 leaves it out).
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
extra=()
if [ "${FASTNOISE2:-1}" != 0 ]; then
  fn2="${FASTNOISE2_SRC:-$work/FastNoise2}"
  simd="${FASTSIMD_SRC:-$work/FastSIMD}"
  if [ ! -d "$fn2" ]; then
    git clone -q https://github.com/Auburn/FastNoise2 "$fn2"
  fi
  if [ ! -d "$simd" ]; then
    pinned="$(sed -n 's/.*GIT_TAG \([0-9a-f]*\).*/\1/p' "$fn2/src/CMakeLists.txt" | head -1)"
    git clone -q https://github.com/Auburn/FastSIMD "$simd" && git -C "$simd" checkout -q "$pinned"
  fi
  cmake -S "$fn2" -B "$work/fn2-build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFASTNOISE2_TOOLS=OFF \
    -DFASTNOISE2_TESTS=OFF -DCPM_FastSIMD_SOURCE="$simd" >/dev/null
  cmake --build "$work/fn2-build" >/dev/null
  config="$(dirname "$(dirname "$(find "$work/fn2-build" -name FastSIMD_FastNoise_config.h | head -1)")")"
  extra=(-DPARAFLUID_WITH_FASTNOISE2 -I"$fn2/include" -I"$simd/include" -I"$config"
    "$(find "$work/fn2-build" -name libFastNoise.a | head -1)")
fi
core="$root/Filters/Terrain/Core"
g++ -O3 -DNDEBUG -std=c++17 -fopenmp -fno-math-errno -fno-trapping-math -I"$(dirname "$header")" -I"$core" \
  -I"$root/Filters/Common/Core" -o "$work/peer" "$here/fastnoise_peer.cxx" "$core/FractalNoise.cxx" \
  "$core/PerlinNoise.cxx" "${extra[@]}"
"$work/peer" "$@"
