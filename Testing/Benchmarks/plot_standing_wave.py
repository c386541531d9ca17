#!/usr/bin/env python3
"""Draws standing-wave runs of ParaFluidSPHValidation (standingwave_curves.csv: solver, across, t,
centre of mass - L/2) against linear theory, the centre of mass going as -A' sin(omega t) with
omega^2 = g k tanh(k h), and the drift of each run's phase from it.
Usage: plot_standing_wave.py <label>=<curves.csv> [...] [--across 20] --png standing_wave.png"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

G, LENGTH, DEPTH = 9.81, 1.0, 0.5  # the scene's tank (Testing/SPH/Validation/AnalyticFlows.cxx)


def read(path, across):
    t, c = [], []
    with open(path) as f:
        for row in csv.reader(f):
            if len(row) == 4 and row[1] == str(across):
                t.append(float(row[2]))
                c.append(float(row[3]))
    return t, c


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runs", nargs="+", help="label=curves.csv")
    parser.add_argument("--across", type=int, default=20)
    parser.add_argument("--png", default="standing_wave.png")
    args = parser.parse_args()
    k = math.pi / LENGTH
    omega = math.sqrt(G * k * math.tanh(k * DEPTH))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    amplitude = 0.0
    colours = ["tab:gray", "tab:red", "tab:blue", "tab:green"]
    for n, run in enumerate(args.runs):
        label, path = run.split("=", 1)
        t, c = read(path, args.across)
        amplitude = max(amplitude, max(abs(v) for v in c))
        top.plot([v * omega / (2 * math.pi) for v in t], [v * 1000 for v in c], color=colours[n % 4], label=label)
        # Zero crossings (the scene's read-out) against theory's, in degrees of phase.
        crossings = [t[i] + (t[i + 1] - t[i]) * c[i] / (c[i] - c[i + 1]) for i in range(len(c) - 1)
                     if (c[i] > 0) != (c[i + 1] > 0) and abs(c[i] - c[i + 1]) > 0]
        bottom.plot([x * omega / (2 * math.pi) for x in crossings],
                    [(x * omega / math.pi - (m + 1)) * 180.0 for m, x in enumerate(crossings)], "o-",
                    color=colours[n % 4], label=label)
    theory_t = [i * 0.005 for i in range(int(2.5 * 2 * math.pi / omega / 0.005) + 1)]
    top.plot([v * omega / (2 * math.pi) for v in theory_t],
             [-amplitude * math.sin(omega * v) * 1000 for v in theory_t], "k--", label="linear theory")
    top.set_ylabel("centre of mass - L/2 [mm]")
    top.set_title(f"Standing wave, {args.across} particles across the depth")
    top.legend(fontsize=8)
    bottom.axhline(0.0, color="k", linestyle="--")
    bottom.set_ylabel("phase of the zero crossing\nagainst theory [degrees]")
    bottom.set_xlabel("t / period (linear theory)")
    bottom.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
