#!/usr/bin/env bash
# Installs what is missing, then configures and builds ParaFluid in Release (build/ by default).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_BUILD_DIR:-$root/build}"
bash "$root/scripts/install-deps.sh"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --parallel "$(nproc)"
echo "ParaFluid plugin: $build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so"
