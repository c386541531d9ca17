#!/usr/bin/python3
"""The peer on Lobovsky et al.'s (2014) 3-D dam break: Debian python3-pysph's own example of it
(pysph/examples/dam_break/dam_break_3d_lobovsky.py: WCSPH, Wendland quintic, h = 1.3 dx, EPEC
integrator, OpenMP), read out at the downstream wall's sensor 1 exactly as ParaFluid's validation
scene reads its own particles (Testing/SPH/Validation/DamBreak.cxx), and scored against the same
experimental curve (pysph's db_exp_data.py, which ParaFluid's ExperimentalData.h copies).

A benchmark-only helper: nothing of pysph is built into ParaFluid. What is set here and not in the
example: the experiment's own scale, H = 0.3 m (the example scales it to H = 1 m), and the sound
speed the example's comment intends, 10 times the largest speed sqrt(2 g H) (its code takes the
0.55 m column of the SPHERIC example it was copied from). Everything else is the example's.

Usage: /usr/bin/python3 Testing/Benchmarks/pysph_lobovsky_peer.py [across=30] [t_end*=3.2] [threads=2]
  across: particles across the column's height H (dx = H / across); t_end*: end time in t sqrt(g/H).
Prints one summary line and writes pysph_lobovsky_<across>.csv (t*, p / (rho g H)) here.
"""
import os
import shutil
import sys
import tempfile

import numpy as np

across = int(sys.argv[1]) if len(sys.argv) > 1 else 30
end_star = float(sys.argv[2]) if len(sys.argv) > 2 else 3.2
threads = sys.argv[3] if len(sys.argv) > 3 else "2"
os.environ["OMP_NUM_THREADS"] = threads

from pysph_peer_common import StepClock, load_example  # noqa: E402  (after OMP_NUM_THREADS)
from pysph.examples import db_exp_data  # noqa: E402

H = 0.3  # [m] Lobovsky et al.'s column height (the tank: 1.61 m long, the column 0.6 m)
G = 9.81
RHO0 = 1000.0
SAMPLE = 0.0005  # [s] between the curve's rows, as ParaFluid's scene writes them (0.0029 in t*)

example = load_example("dam_break/dam_break_3d_lobovsky.py", "dam_break_3d_lobovsky")
example.H = H
example.c0 = 10.0 * np.sqrt(2.0 * G * H)


class Peer(StepClock, example.DamBreak3D):
    """The example, with ParaFluid's sensor read after every step (scored, as ParaFluid's scene scores
    its readings) and kept every SAMPLE seconds for the curve."""

    def post_step(self, solver):
        self.clock_step(solver)
        fluid = self.fluid
        # ParaFluid's read-out: the kernel-weighted (poly6, radius 2 dx) mean of the fluid particles'
        # pressures around the sensor, by distance in x and z (the flow is uniform across the tank).
        wall = self.geom.container_length
        d2 = (fluid.x - wall) ** 2 + (fluid.z - 0.003) ** 2
        radius2 = (2.0 * self.dx) ** 2
        weight = np.clip(radius2 - d2, 0.0, None) ** 3
        total = weight.sum()
        reading = float((weight * fluid.p).sum() / total) / (RHO0 * G * H) if total > 0.0 else 0.0
        self.readings.append((solver.t * np.sqrt(G / H), reading))
        if solver.t + 1e-12 >= self.next_sample:
            self.next_sample += SAMPLE
            self.curve.append(self.readings[-1])


def score(t, p):
    """Arrival (first reading over 0.1) and the first peak (the largest within 0.3 t* after it), as
    ParaFluid's scene scores its own curve."""
    t, p = np.asarray(t), np.asarray(p)
    over = np.nonzero(p > 0.1)[0]
    if over.size == 0:
        return None, None, None
    arrival = t[over[0]]
    window = (t >= arrival) & (t < arrival + 0.3)
    k = np.argmax(np.where(window, p, -np.inf))
    return arrival, t[k], p[k]


out = tempfile.mkdtemp(prefix="pysph_lobovsky_")
app = Peer(fname="dam_break_3d_lobovsky")
app.next_sample = SAMPLE
app.curve = []
app.readings = []
dx = H / across
app.run(["--openmp", "--dx", repr(dx), "--tf", repr(end_star / np.sqrt(G / H)), "-d", out, "--pfreq", "100000000",
         "--disable-output", "-q"])
shutil.rmtree(out, ignore_errors=True)  # the run's log and info files: nothing read from them

fluid = app.fluid.get_number_of_particles()
boundary = sum(pa.get_number_of_particles() for pa in app.particles if pa.name != "fluid")
wall_seconds = app.wall_seconds()
simulated = app.solver.t
t_exp, _, _, p_exp, _, _ = db_exp_data.get_lobovsky_data()
arrival_exp, peak_time_exp, peak_exp = score(t_exp, p_exp)
arrival, peak_time, peak = score(*zip(*app.readings))
with open("pysph_lobovsky_%d.csv" % across, "w") as f:
    f.write("t_star,p_star\n")
    for t, p in app.curve:
        f.write("%.5f,%.5f\n" % (t, p))


def error(value, reference):
    return "no arrival" if value is None else "%.1f %%" % (100.0 * abs(value - reference) / reference)


print("pysph WCSPH, Lobovsky H = %.2f m, %d across (dx = %.4f m): %d fluid + %d boundary particles, %d steps to "
      "t* = %.2f in %.1f s on %s threads: %.0f fluid particle-steps/s, %.2e simulated s per s; sensor 1: arrival "
      "%.3f (%s), first peak %.3f at %.3f (%s; time %s), experiment %.3f at %.3f"
      % (H, across, dx, fluid, boundary, app.steps, simulated * np.sqrt(G / H), wall_seconds, threads,
         fluid * app.steps / wall_seconds, simulated / wall_seconds, arrival or 0.0, error(arrival, arrival_exp),
         peak or 0.0, peak_time or 0.0, error(peak, peak_exp), error(peak_time, peak_time_exp), peak_exp,
         peak_time_exp))
