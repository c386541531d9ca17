#!/usr/bin/env bash
# The main job: install, build (Release), then run the demo on Data/dam_break.h5part:
# read it, step it with SPH, save the result and render a PNG (both in build/demo/).
# `--scene rain`: the rain demo instead (scripts/demo_rain.py): a terrain, a cloudburst on it,
# the runoff as SPH water; writes build/demo/rain.png. Other arguments go to the demo script.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PARAFLUID_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
mkdir -p "$build/demo"
cd "$build/demo"
with_display=()
[ -n "${DISPLAY:-}" ] || with_display=(bash "$root/scripts/with-xvfb.sh")
if [ "${1:-}" = "--scene" ] && [ "${2:-}" = "rain" ]; then
  shift 2
  exec "${with_display[@]}" pvpython "$root/scripts/demo_rain.py" \
    --plugin "$build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so" --png "$build/demo/rain.png" "$@"
fi
"${with_display[@]}" pvpython "$root/scripts/demo.py" \
  --plugin "$build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so" \
  --data "$root/Data/dam_break.h5part" \
  --result "$build/demo/dam_break_result.h5part" --png "$build/demo/dam_break.png" "$@"
