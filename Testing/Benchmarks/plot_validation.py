#!/usr/bin/env python3
"""Draws the CSVs of ParaFluidSPHValidation (run_validation.sh) into one PNG: error against run time
on the hydrostatic column, the dam-break front and column height against Martin & Moyce (1952), the
wall pressure against Lobovsky et al. (2014), the Taylor-Green energy decay, the Poiseuille profile
and the standing wave.
Usage: plot_validation.py <csv-directory> [<csv-directory> ...] --png validation.png
(every directory's CSVs are merged, so runs split by scene or solver plot together)."""
import argparse
import csv
import glob
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

STYLE = {"WCSPH": ("tab:gray", "x"), "DFSPH": ("tab:blue", "o"), "DeltaSPH": ("tab:red", "s")}
# Martin & Moyce (1952), n^2 = 2 (Testing/SPH/Validation/ExperimentalData.h).
FRONT_T = [0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98]
FRONT_Z = [1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67]
HEIGHT_TAU = [0.56, 0.77, 0.93, 1.08, 1.28, 1.46, 1.66, 1.84, 2.00]  # Table 6
HEIGHT = [0.94, 0.89, 0.83, 0.78, 0.72, 0.67, 0.61, 0.56, 0.50]
LOBOVSKY_T = [2.066, 2.232, 2.382, 2.427, 2.435, 2.450, 2.498, 2.564, 2.630, 2.675, 2.758, 2.829, 2.924, 3.089,
              3.170, 3.255, 3.420]
LOBOVSKY_P = [0.012, 0.015, 0.004, 0.173, 1.973, 2.843, 2.040, 1.953, 1.725, 1.551, 1.335, 1.202, 1.062, 0.883,
              0.832, 0.775, 0.718]


def files(directories, name):
    out = []
    for d in directories:
        out.extend(glob.glob(os.path.join(d, "**", name), recursive=True))
    return sorted(set(out))


def summary(directories, scene):
    rows = []
    for path in files(directories, scene + ".csv"):
        with open(path) as f:
            rows.extend(r for r in csv.DictReader(f) if r.get("wall_s") not in (None, "", "stopped"))
    return rows


def curves(directories, scene):
    rows = []
    for path in files(directories, scene + "_curves.csv"):
        with open(path) as f:
            rows.extend(r for r in csv.reader(f) if len(r) >= 4)
    return rows


def finest(rows, solver, scene):
    """The finest resolution of a solver whose run finished (it has a summary row)."""
    done = {int(r["particles_across"]) for r in summary(dirs, scene) if r["solver"] == solver}
    sizes = sorted({int(r[1]) for r in rows if r[0] == solver} & done)
    return sizes[-1] if sizes else None


parser = argparse.ArgumentParser()
parser.add_argument("directories", nargs="+")
parser.add_argument("--png", default="validation.png")
args = parser.parse_args()
dirs = args.directories

fig, axes = plt.subplots(2, 3, figsize=(16, 9))
(cost_ax, front_ax, lobovsky_ax), (tg_ax, poiseuille_ax, wave_ax) = axes

for solver, (colour, marker) in STYLE.items():
    runs = sorted((r for r in summary(dirs, "hydrostatic") if r["solver"] == solver),
                  key=lambda r: int(r["particles_across"]))
    if runs:
        cost_ax.loglog([float(r["wall_s"]) for r in runs], [float(r["relative_l2_error"]) for r in runs],
                       "-" + marker, color=colour, label=solver)
        for r in runs:
            cost_ax.annotate(r["particles_across"], (float(r["wall_s"]), float(r["relative_l2_error"])))
cost_ax.axhline(0.01, color="k", linestyle=":", label="1 % target")
cost_ax.set_xlabel("wall time [s] (2 threads; labels: particles across)")
cost_ax.set_ylabel("relative L2 pressure error")
cost_ax.set_title("Hydrostatic column: error against run time")
cost_ax.legend()

dam = curves(dirs, "dambreak")
for solver, (colour, _) in STYLE.items():
    n = finest(dam, solver, "dambreak")
    pts = [r for r in dam if r[0] == solver and int(r[1]) == n]
    if pts:
        front_ax.plot([float(r[2]) for r in pts], [float(r[3]) for r in pts], "-", color=colour,
                      label="%s front, %d across" % (solver, n))
        front_ax.plot([float(r[2]) for r in pts], [float(r[4]) for r in pts], "--", color=colour)
front_ax.plot(FRONT_T, FRONT_Z, "k^", label="Martin & Moyce front Z")
front_ax.plot([t * math.sqrt(2) for t in HEIGHT_TAU], HEIGHT, "kv", label="M & M height (dashed: SPH)")
front_ax.set_xlabel("T = t sqrt(2 g / a)")
front_ax.set_ylabel("Z = x / a;  h / 2a")
front_ax.set_xlim(0, 3.1)
front_ax.set_title("Dam break, water's viscosity")
front_ax.legend(fontsize=7)

lob = curves(dirs, "lobovsky")
for solver, (colour, _) in STYLE.items():
    n = finest(lob, solver, "lobovsky")
    pts = [r for r in lob if r[0] == solver and int(r[1]) == n and 2.0 <= float(r[2]) <= 3.5]
    if pts:
        lobovsky_ax.plot([float(r[2]) for r in pts], [float(r[3]) for r in pts], "-", color=colour,
                         label="%s, %d across" % (solver, n))
lobovsky_ax.plot(LOBOVSKY_T, LOBOVSKY_P, "k^-", label="Lobovsky et al., sensor 1")
lobovsky_ax.set_yscale("symlog", linthresh=1.0)
lobovsky_ax.set_xlabel("t sqrt(g / H)")
lobovsky_ax.set_ylabel("p / (rho g H)")
lobovsky_ax.set_title("Wall pressure, 3 mm above the floor")
lobovsky_ax.legend(fontsize=7)

tg = curves(dirs, "taylorgreen")
exact_drawn = False
for solver, (colour, _) in STYLE.items():
    done = {int(r["particles_across"]) for r in summary(dirs, "taylorgreen") if r["solver"] == solver}
    for n in sorted({int(r[1]) for r in tg if r[0] == solver} & done):
        pts = [r for r in tg if r[0] == solver and int(r[1]) == n]
        tg_ax.plot([float(r[2]) for r in pts], [float(r[3]) for r in pts], "-", color=colour,
                   alpha=0.4 + 0.6 * n / 100.0, label="%s, %d across" % (solver, n))
        if not exact_drawn:
            tg_ax.plot([float(r[2]) for r in pts], [float(r[4]) for r in pts], "k--", label="exp(-16 pi^2 nu t)")
            exact_drawn = True
tg_ax.set_xlabel("t [s]")
tg_ax.set_ylabel("E / E0")
tg_ax.set_title("Taylor-Green vortex, Re = 100")
tg_ax.legend(fontsize=7)

po = curves(dirs, "poiseuille")
exact_drawn = False
for solver, (colour, marker) in STYLE.items():
    n = finest(po, solver, "poiseuille")
    pts = sorted((r for r in po if r[0] == solver and int(r[1]) == n), key=lambda r: float(r[2]))
    if pts:
        poiseuille_ax.plot([float(r[3]) for r in pts], [float(r[2]) for r in pts], marker, color=colour,
                           markersize=3, label="%s, %d across" % (solver, n))
        if not exact_drawn:
            poiseuille_ax.plot([float(r[4]) for r in pts], [float(r[2]) for r in pts], "k-", label="parabola")
            exact_drawn = True
poiseuille_ax.set_xlabel("u [m/s]")
poiseuille_ax.set_ylabel("z [m]")
poiseuille_ax.set_title("Poiseuille flow between no-slip plates")
poiseuille_ax.legend(fontsize=7)

wave = curves(dirs, "standingwave")
for solver, (colour, _) in STYLE.items():
    n = finest(wave, solver, "standingwave")
    pts = [r for r in wave if r[0] == solver and int(r[1]) == n]
    if pts:
        wave_ax.plot([float(r[2]) for r in pts], [1000 * float(r[3]) for r in pts], "-", color=colour,
                     label="%s, %d across" % (solver, n))
omega = math.sqrt(9.81 * math.pi * math.tanh(math.pi * 0.5))
ts = [k * 0.01 for k in range(300)]
amplitude = max((abs(1000 * float(r[3])) for r in wave), default=1.0)
wave_ax.plot(ts, [-amplitude * math.sin(omega * t) for t in ts], "k--", label="linear theory's frequency")
wave_ax.set_xlabel("t [s]")
wave_ax.set_ylabel("centre of mass - L/2 [mm]")
wave_ax.set_title("Standing wave, h = 0.5 m")
wave_ax.legend(fontsize=7)

fig.tight_layout()
fig.savefig(args.png, dpi=90)
print("wrote", args.png)
