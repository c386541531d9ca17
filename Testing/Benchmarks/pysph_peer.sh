#!/usr/bin/env bash
# Runs the peer, Debian python3-pysph's dam_break_3d example (WCSPH, Wendland quintic, OpenMP), for
# the same simulated time as ParaFluidSphericDamBreak, and prints its steps and particle-steps per
# second. A benchmark-only helper: nothing of pysph is built into ParaFluid.
# Usage: Testing/Benchmarks/pysph_peer.sh [spacing=0.02] [simulated seconds=0.01] [threads=2]
set -euo pipefail
dx="${1:-0.02}"; tf="${2:-0.01}"; threads="${3:-2}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
OMP_NUM_THREADS="$threads" /usr/bin/python3 /usr/lib/python3/dist-packages/pysph/examples/dam_break_3d.py \
  --openmp --tf "$tf" --dx "$dx" -d "$out" --pfreq 100000000 >"$out/run.txt" 2>&1
/usr/bin/python3 - "$out" <<'PY'
import glob, json, sys
from pysph.solver.utils import load
out = sys.argv[1]
info = json.load(open(out + "/dam_break_3d.info"))
last = load(sorted(glob.glob(out + "/dam_break_3d_*.hdf5"))[-1])
steps = last["solver_data"]["count"]
fluid = last["arrays"]["fluid"].get_number_of_particles()
wall = info["cpu_time"]
print("pysph    %d fluid particles, %d steps over %.3f s simulated in %.2f s: %.0f fluid particle-steps/s, "
      "%.2e simulated s per s" % (fluid, steps, last["solver_data"]["t"], wall, fluid * steps / wall,
                                  last["solver_data"]["t"] / wall))
PY
