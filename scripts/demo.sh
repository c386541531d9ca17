#!/usr/bin/env bash
# The main job: install, build (Release), then run the demo on Data/dam_break.h5part:
# read it, step it with SPH, save the result and render a PNG (both in build/demo/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
mkdir -p "$build/demo"
cd "$build/demo"
xvfb_run=()
[ -n "${DISPLAY:-}" ] || xvfb_run=(xvfb-run -a -s "-screen 0 1280x1024x24")
"${xvfb_run[@]}" pvpython "$root/scripts/demo.py" \
  --plugin "$build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so" \
  --data "$root/Data/dam_break.h5part" \
  --result "$build/demo/dam_break_result.h5part" --png "$build/demo/dam_break.png" "$@"
