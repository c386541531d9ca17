#!/usr/bin/env bash
# The tests: install what is missing, build if needed, run the whole suite with ctest
# (Core GoogleTest, pvpython pipelines, the image baselines under Xvfb, the 2-rank MPI tests,
# the reader's fuzz corpus), then the sanitizer build of the Cores (scripts/sanitize.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
cd "$build"
# Tests run side by side, each with its OpenMP threads: waiting threads sleep instead of spinning
# on cores the other tests need.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-PASSIVE}"
ctest --output-on-failure --parallel "$(nproc)" "$@"
bash "$root/scripts/sanitize.sh"
