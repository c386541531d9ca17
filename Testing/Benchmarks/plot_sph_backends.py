#!/usr/bin/env python3
"""Draws ParaFluidSPHBackendBenchmark's output: steps per second and particle-steps per second
against the particle count, one line per solver and backend (CPU, CUDA), on log axes.
Usage: plot_sph_backends.py <benchmark.csv> --png sph_backends.png (lines starting with # are skipped)"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("csv")
    parser.add_argument("--png", default="sph_backends.png")
    args = parser.parse_args()
    runs = {}
    title = ""
    with open(args.csv) as f:
        lines = []
        for line in f:
            if line.startswith("#"):
                title = title or line[1:].strip()
            else:
                lines.append(line)
    for row in csv.DictReader(lines):
        # One line per solver and backend (older files have no solver column: δ-SPH).
        label = row["backend"] if "solver" not in row else row["solver"] + " " + row["backend"]
        runs.setdefault(label, []).append(
            (int(row["particles"]), float(row["steps_per_s"]), float(row["particle_steps_per_s"])))
    fig, (steps, throughput) = plt.subplots(1, 2, figsize=(10, 4))
    for backend, points in sorted(runs.items()):
        points.sort()
        n = [p[0] for p in points]
        steps.plot(n, [p[1] for p in points], "o-", label=backend)
        throughput.plot(n, [p[2] for p in points], "o-", label=backend)
    for ax, label in ((steps, "steps per second"), (throughput, "particle-steps per second")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("particles")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    if title:
        fig.suptitle(title, fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=100)


if __name__ == "__main__":
    main()
