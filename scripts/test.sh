#!/usr/bin/env bash
# The tests: install what is missing, build if needed, run the whole suite with ctest
# (Core GoogleTest, pvpython pipelines, the image baseline under Xvfb, the 2-rank MPI test).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure --parallel "$(nproc)" "$@"
