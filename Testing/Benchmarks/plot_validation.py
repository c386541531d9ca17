#!/usr/bin/env python3
"""Draws the validation CSVs of ParaFluidSPHValidation into one PNG: the hydrostatic pressure
profile and its error against run time, and the dam-break surge front against Martin & Moyce (1952).
Usage: plot_validation.py <csv-directory> [<csv-directory> ...] --png validation.png
(the CSVs of several runs, e.g. one per solver, are merged)."""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

# Martin & Moyce (1952), a = 2.25 in, n^2 = 2: T = t sqrt(2 g / a), Z = x / a.
EXPERIMENT_T = [0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98, 3.11, 3.33]
EXPERIMENT_Z = [1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67, 3.89, 4.11]


def rows(directories, name):
    out = []
    for d in directories:
        path = os.path.join(d, name)
        if os.path.exists(path):
            with open(path) as f:
                out.extend(csv.DictReader(f))
    return out


parser = argparse.ArgumentParser()
parser.add_argument("directories", nargs="+")
parser.add_argument("--png", default="validation.png")
args = parser.parse_args()

fig, (profile_ax, cost_ax, front_ax) = plt.subplots(1, 3, figsize=(15, 4.5))
profile = rows(args.directories, "hydrostatic_profile.csv")
for solver, marker in (("WCSPH", "x"), ("DFSPH", ".")):
    points = [r for r in profile if r["solver"] == solver and r["particles_across"] == "20"]
    if points:
        profile_ax.plot([float(r["pressure"]) for r in points], [float(r["z"]) for r in points], marker,
                        markersize=2, label="%s, 20 across" % solver)
profile_ax.plot([0, 1000 * 9.81 * 0.2], [0.2, 0], "k-", label="rho0 g depth")
profile_ax.set_xlabel("pressure [Pa]")
profile_ax.set_ylabel("z [m]")
profile_ax.set_title("Hydrostatic column")
profile_ax.legend()

for solver, marker in (("WCSPH", "s-"), ("DFSPH", "o-")):
    runs = [r for r in rows(args.directories, "hydrostatic.csv") if r["solver"] == solver]
    if runs:
        cost_ax.loglog([float(r["wall_s"]) for r in runs], [float(r["relative_l2_error"]) for r in runs], marker,
                       label=solver)
        for r in runs:
            cost_ax.annotate(r["particles_across"], (float(r["wall_s"]), float(r["relative_l2_error"])))
cost_ax.set_xlabel("wall time [s] (2 threads)")
cost_ax.set_ylabel("relative L2 pressure error")
cost_ax.set_title("Hydrostatic: error against run time")
cost_ax.legend()

front = rows(args.directories, "dambreak_front.csv")
for solver, style in (("WCSPH", "--"), ("DFSPH", "-")):
    for across in sorted({r["particles_across"] for r in front if r["solver"] == solver}, key=int):
        curve = [r for r in front if r["solver"] == solver and r["particles_across"] == across]
        front_ax.plot([float(r["T"]) for r in curve], [float(r["Z"]) for r in curve], style,
                      label="%s, a/d = %s" % (solver, across))
front_ax.plot(EXPERIMENT_T, EXPERIMENT_Z, "ko", label="Martin & Moyce 1952")
front_ax.set_xlim(0, 3)
front_ax.set_xlabel("T = t sqrt(2g/a)")
front_ax.set_ylabel("Z = x/a")
front_ax.set_title("Dam break surge front")
front_ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(args.png, dpi=80)
print("wrote", args.png)
