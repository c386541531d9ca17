#!/usr/bin/env bash
# The CUDA backend's tests and benchmark on a machine with a GPU and no ParaView: a core-only build
# with PARAFLUID_CUDA=ON (build-gpu/ by default). Where GoogleTest or Eigen are not installed, it
# takes them from .deps/googletest (Debian's googletest sources) and .deps/eigen (include/eigen3
# and share/eigen3 of libeigen3-dev). Runs the GPU's tests (the SPH core's CudaBackend.* and the
# runoff's), then the benchmark, whose arguments are the particle spacings [m].
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_GPU_BUILD_DIR:-$root/build-gpu}"
jobs="$(nproc)"
prefix=()
if [ -d "$root/.deps/googletest" ] && [ ! -f /usr/lib/x86_64-linux-gnu/libgtest.a ]; then
  if [ ! -f "$build/googletest-install/lib/libgtest.a" ] && [ ! -f "$build/googletest-install/lib64/libgtest.a" ]; then
    cmake -S "$root/.deps/googletest" -B "$build/googletest" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_INSTALL_PREFIX="$build/googletest-install" >/dev/null
    cmake --build "$build/googletest" --parallel "$jobs" --target install >/dev/null
  fi
  prefix+=("$build/googletest-install")
fi
[ -d "$root/.deps/eigen" ] && prefix+=("$root/.deps/eigen")
joined="$(IFS=';'; echo "${prefix[*]:-}")"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPARAFLUID_CORE_ONLY=ON -DPARAFLUID_BUILD_BENCHMARKS=OFF \
  -DPARAFLUID_CUDA=ON -DCMAKE_PREFIX_PATH="$joined" >/dev/null
cmake --build "$build" --parallel "$jobs" --target ParaFluidSPHCoreTests ParaFluidRainCoreTests \
  ParaFluidSPHBackendBenchmark
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader || true
program() { find "$build" -name "$1" -type f -perm -u+x | head -1; }
"$(program ParaFluidSPHCoreTests)" --gtest_filter='CudaBackend.*'
"$(program ParaFluidRainCoreTests)" --gtest_filter='Runoff.*Gpu*'
"$(program ParaFluidSPHBackendBenchmark)" "$@"
