#!/usr/bin/env python3
"""Draws the resting column's output pressure layer by layer (ParaFluidSPHValidation's
hydrostatic_curves.csv): each layer's mean departure from rho0 g depth, with the scatter of its
particles about that mean as a bar, one panel per solver, one line per run.
Usage: plot_hydrostatic_layers.py "label=dir" ["label=dir" ...] [--across 20] --png hydrostatic_layers.png"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

WIDTH = 0.2  # the column's width and height [m] (Testing/SPH/Validation/Hydrostatic.cxx)
NAMES = {"WCSPH": "WCSPH (Müller)", "DFSPH": "DFSPH", "DeltaSPH": "δ-SPH (default)"}


def layers(path, solver, across):
    """Per layer one spacing thick: (mean height, mean departure, scatter) [m, Pa, Pa]."""
    spacing = WIDTH / across
    groups = {}
    with open(path) as f:
        for row in csv.reader(f):
            if len(row) < 5 or row[0] != solver or int(row[1]) != across:
                continue
            z, p, ref = float(row[2]), float(row[3]), float(row[4])
            groups.setdefault(math.floor(z / spacing), []).append((z, p - ref))
    out = []
    for key in sorted(groups):
        values = groups[key]
        mean = sum(e for _, e in values) / len(values)
        scatter = math.sqrt(sum((e - mean) ** 2 for _, e in values) / len(values))
        out.append((sum(z for z, _ in values) / len(values), mean, scatter))
    return out


parser = argparse.ArgumentParser()
parser.add_argument("runs", nargs="+", help="label=directory holding hydrostatic_curves.csv")
parser.add_argument("--across", type=int, default=20)
parser.add_argument("--png", default="hydrostatic_layers.png")
args = parser.parse_args()
runs = [r.split("=", 1) for r in args.runs]
solvers = ["WCSPH", "DFSPH", "DeltaSPH"]
fig, axes = plt.subplots(1, len(solvers), figsize=(4.2 * len(solvers), 4.2), sharey=True)
for ax, solver in zip(axes, solvers):
    for label, directory in runs:
        rows = layers(os.path.join(directory, "hydrostatic_curves.csv"), solver, args.across)
        if rows:
            ax.errorbar([m for _, m, _ in rows], [z for z, _, _ in rows], xerr=[s for _, _, s in rows], marker="o",
                        markersize=3, capsize=2, label=label)
    ax.axvline(0.0, color="k", linewidth=0.6)
    ax.set_title("%s, %d across" % (NAMES[solver], args.across))
    ax.set_xlabel("output pressure − ρ0 g depth [Pa]")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("height of the layer [m] (surface at 0.2)")
axes[0].legend(fontsize=8)
fig.suptitle("Resting column, layer by layer: mean departure (bar: the scatter of the layer's particles)", fontsize=10)
fig.tight_layout()
fig.savefig(args.png, dpi=110)
print("wrote", args.png)
