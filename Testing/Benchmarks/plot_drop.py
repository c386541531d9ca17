#!/usr/bin/env python3
"""Draws the oscillating drop of ParaFluidSPHValidation (--scene drop): the elongation
(<x^2> - <y^2>) / (<x^2> + <y^2>) against time for each solver and resolution, beside an undamped
oscillation at Rayleigh's period for the same drop (omega^2 = 8 sigma / (rho R^3), 32.7 ms).
Usage: plot_drop.py <csv-directory> --png drop_oscillation.png"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

RAYLEIGH_PERIOD = 0.03268  # [s]: R = 2.5 mm, sigma = 0.0728 N/m, rho = 1000 kg/m^3
COLOURS = ["tab:red", "tab:orange", "tab:purple", "tab:blue", "tab:green", "tab:gray"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory")
    parser.add_argument("--png", default="drop_oscillation.png")
    args = parser.parse_args()
    runs = {}
    with open(os.path.join(args.directory, "drop_curves.csv")) as f:
        for solver, across, t, e in csv.reader(f):
            runs.setdefault((solver, int(across)), []).append((float(t), float(e)))
    periods = {}
    summary = os.path.join(args.directory, "drop.csv")
    if os.path.exists(summary):
        with open(summary) as f:
            for row in csv.DictReader(f):
                if row.get("period") not in (None, "", "stopped"):
                    periods[(row["solver"], int(row["particles_across"]))] = float(row["period"])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    start = None
    for k, ((solver, across), points) in enumerate(sorted(runs.items())):
        ts = [0.0] + [p[0] * 1e3 for p in points]
        es = [None] + [p[1] for p in points]
        es[0] = es[1]
        start = start if start is not None else es[0]
        label = "%s, %d particles over the radius" % (solver, across)
        if (solver, across) in periods:
            label += ": period %.1f ms" % (periods[(solver, across)] * 1e3)
        ax.plot(ts, es, color=COLOURS[k % len(COLOURS)], label=label)
    if start is not None:
        end = max(p[0] for points in runs.values() for p in points)
        ts = [end * 1e3 * i / 400 for i in range(401)]
        ax.plot(ts, [start * math.cos(2 * math.pi * t * 1e-3 / RAYLEIGH_PERIOD) for t in ts], "k--",
                label="Rayleigh's period, %.1f ms (undamped)" % (RAYLEIGH_PERIOD * 1e3))
    ax.axhline(0.0, color="0.8", lw=0.8)
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("elongation (<x²> − <y²>) / (<x²> + <y²>)")
    ax.set_title("Weightless water drop, R = 2.5 mm, Akinci surface tension σ = 0.0728 N/m")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
