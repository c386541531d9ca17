#!/usr/bin/env bash
# The main job: install, build (Release), then run the demo on Data/dam_break.h5part:
# read it, step it with SPH, save the result and render a PNG (both in build/demo/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
mkdir -p "$build/demo"
cd "$build/demo"
with_display=()
[ -n "${DISPLAY:-}" ] || with_display=(bash "$root/scripts/with-xvfb.sh")
"${with_display[@]}" pvpython "$root/scripts/demo.py" \
  --plugin "$build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so" \
  --data "$root/Data/dam_break.h5part" \
  --result "$build/demo/dam_break_result.h5part" --png "$build/demo/dam_break.png" "$@"
