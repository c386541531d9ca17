#!/usr/bin/env bash
# Runs every SPH validation scene for every solver at its three resolutions, scenes side by side
# (two OpenMP threads each), into the folder given (default validation/). Builds the validation
# program with g++ alone when no build tree is given, so it also runs on a machine without CMake
# packages (the GPU machine: EIGEN_DIR points at Eigen's headers there).
# Usage: Testing/Benchmarks/run_validation.sh [out-dir] [program]
set -euo pipefail
out="${1:-validation}"
program="${2:-}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
mkdir -p "$out"
if [ -z "$program" ]; then
  program="$out/ParaFluidSPHValidation"
  g++ -O3 -march=native -fopenmp -std=c++17 -DNDEBUG \
    -I"$root/Filters/Common/Core" -I"$root/Filters/SPH/Core" -I"$root/Testing/SPH/Validation" \
    -I"${EIGEN_DIR:-/usr/include/eigen3}" \
    "$root"/Filters/Common/Core/*.cxx "$root"/Filters/SPH/Core/*.cxx "$root"/Testing/SPH/Validation/*.cxx \
    "$root/Testing/Benchmarks/SPHValidation.cxx" -o "$program"
fi
pids=()
for scene in hydrostatic stillwater dambreak lobovsky taylorgreen poiseuille standingwave drop; do
  mkdir -p "$out/$scene"
  OMP_NUM_THREADS="${THREADS_PER_SCENE:-2}" "$program" "$out/$scene" --scene "$scene" >"$out/$scene/log.txt" 2>&1 &
  pids+=($!)
done
for pid in "${pids[@]}"; do
  wait "$pid" || true
done
cat "$out"/*/log.txt
