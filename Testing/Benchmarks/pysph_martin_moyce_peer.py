#!/usr/bin/python3
"""The peer on Martin & Moyce's (1952) dam break: Debian python3-pysph's own 2-D example of it
(pysph/examples/dam_break_2d.py: a column 1 wide and 2 high, n^2 = 2 as in the validation, in a 4 x 4
tank, inviscid, artificial viscosity alpha = 0.1, OpenMP), its surge front scored against the same
Table 2 points and by the same rule as ParaFluid's validation scene (Testing/SPH/Validation/DamBreak.cxx):
the mean over the points to T = 3 of |Z - Z_exp| / Z_exp, Z interpolated in T = t sqrt(2 g / a).

A benchmark-only helper: nothing of pysph is built into ParaFluid. The example runs as shipped, with
the scheme picked by its own --scheme (wcsph: Monaghan's WCSPH; edac: the entropically damped
artificial compressibility scheme; aha: Adami, Hu & Adams' transport-velocity scheme), except that
its particles' mass and smoothing length follow --dx: it computes both once, from its default
spacing 0.03, when it is imported (at dx = 0.015 as shipped it went NaN by t = 0.04 s). The front is
the largest x of any fluid particle after every step. The example's wall particles stand at x = 0
and its fluid's columns at dx, 2 dx, ..., 1 + dx: with the wall's face and the fluid's edges half a
spacing from the particles, the column is a = 1 + dx wide (its height 2 + dx), and Z = x_max / a with
T = t sqrt(2 g / a) for that a (ParaFluid: Z = (x_max + d / 2) / a, its wall at x = 0).

Usage: /usr/bin/python3 Testing/Benchmarks/pysph_martin_moyce_peer.py [dx=0.03] [scheme=wcsph] [threads=2] [nnps=sh]
  dx: particle spacing in units of a (1 / dx particles across the column's width). nnps: pysph's
  neighbour search ('sh', spatial hashing: its default linked list crashed at dx = 0.015 here).
Prints one summary line and the front at each experimental point.
"""
import os
import re
import shutil
import sys
import tempfile

import numpy as np

dx = float(sys.argv[1]) if len(sys.argv) > 1 else 0.03
scheme = sys.argv[2] if len(sys.argv) > 2 else "wcsph"
threads = sys.argv[3] if len(sys.argv) > 3 else "2"
nnps = sys.argv[4] if len(sys.argv) > 4 else "sh"
os.environ["OMP_NUM_THREADS"] = threads

from pysph_peer_common import StepClock, load_example  # noqa: E402  (after OMP_NUM_THREADS)

G = 9.81
A = 1.0 + dx  # the example's column width [m], its particles' shares of volume included (see above)
T_SCALE = np.sqrt(2.0 * G / A)
END_T = 3.1  # as the validation scene runs


def table_two():
    """Martin & Moyce's Table 2 as ParaFluid's validation reads it (ExperimentalData.h), points to T = 3."""
    header = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "SPH", "Validation", "ExperimentalData.h")
    text = open(header).read()

    def array(name):
        body = re.search(r"%s\[\]\s*=\s*\{([^}]*)\}" % name, text).group(1)
        return np.array([float(v) for v in body.split(",")])

    t, z = array("kFrontT"), array("kFrontZ")
    keep = t <= 3.0
    return t[keep], z[keep]


example = load_example("dam_break_2d.py", "dam_break_2d")
example.dx = dx
example.h = example.hdx * dx
example.m = dx * dx * example.ro


class Peer(StepClock, example.DamBreak2D):
    """The example, with the front recorded after every step."""

    def post_step(self, solver):
        self.clock_step(solver)
        if self.broke is not None:
            return
        x = self.fluid.x
        if not np.isfinite(x).all():
            self.broke = solver.t * T_SCALE  # scored only up to here
            return
        self.front.append((solver.t * T_SCALE, float(x.max()) / A))


out = tempfile.mkdtemp(prefix="pysph_martin_moyce_")
app = Peer(fname="dam_break_2d")
app.front = []
app.broke = None
app.run(["--openmp", "--scheme", scheme, "--dx", repr(dx), "--nnps", nnps, "--tf", repr(END_T / T_SCALE), "-d", out,
         "--pfreq", "100000000", "--disable-output", "-q"])
shutil.rmtree(out, ignore_errors=True)  # the run's log and info files: nothing read from them

t_exp, z_exp = table_two()
T, Z = (np.array(v) for v in zip(*app.front))
reached = t_exp <= T[-1]
t_exp, z_exp = t_exp[reached], z_exp[reached]
z_sim = np.interp(t_exp, T, Z)
errors = np.abs(z_sim - z_exp) / z_exp
wall_seconds = app.wall_seconds()
fluid = app.fluid.get_number_of_particles()
print("pysph %s, Martin & Moyce n^2 = 2, dx = a / %.0f: %d fluid particles, %d steps to T = %.2f in %.1f s on %s "
      "threads; front against Table 2 (%d points to T = %.2f): mean %.1f %%, largest %.1f %% (%s)%s"
      % (scheme, 1.0 / dx, fluid, app.steps, T[-1], wall_seconds, threads, len(t_exp), t_exp[-1],
         100.0 * errors.mean(), 100.0 * errors.max(), "ahead" if np.mean(z_sim - z_exp) > 0.0 else "behind",
         "" if app.broke is None else "; a particle's position went non-finite at T = %.2f" % app.broke))
print("T    " + " ".join("%5.2f" % t for t in t_exp))
print("Z    " + " ".join("%5.2f" % z for z in z_sim))
print("exp. " + " ".join("%5.2f" % z for z in z_exp))
