#!/usr/bin/env bash
# Memory safety: an AddressSanitizer + UndefinedBehaviorSanitizer build of every Core (the
# numerical cores and the H5Part file-format core), running their GoogleTests and the H5Part core
# over the reader's fuzz corpus. Any sanitizer report aborts its test, and the script fails.
# The long stress runs (ten thousand steps; wall friction at extremes, 200 s under ASan) and the
# SPH validation scenes and the rain basin (minutes of flow each; the same solvers run under ASan in the stress,
# periodic, implicit-viscosity and surface-tension tests) are left to the Release suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARAFLUID_CORE_ONLY=ON \
    -DPARAFLUID_BUILD_BENCHMARKS=OFF -DPARAFLUID_SANITIZE=ON -DPARAFLUID_CUDA=OFF
fi
cmake --build "$build" --parallel "$(nproc)"
# halt_on_error + -fno-sanitize-recover: the first report ends the test with a failure.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export OMP_WAIT_POLICY=PASSIVE
cd "$build"
ctest --output-on-failure --parallel "$(nproc)" -E "TenThousandSteps|DFSPHDamBreakThreeThousandSteps|WallFrictionAtExtremes|SPHValidation|Runoff.BasinKeepsTheRainVolume|TenTimesTheCflLimit" "$@"
