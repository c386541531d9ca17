#!/usr/bin/env python3
"""Draws sensor 1 of Lobovsky et al.'s (2014) dam break as ParaFluid and pysph read it, beside the
experiment (pysph's db_exp_data.py, so Debian's python3-pysph must be installed, as for the peer):
ParaFluidSPHValidation's lobovsky_curves.csv (solver, across, t*, p*) and the
pysph_lobovsky_<across>.csv files of pysph_lobovsky_peer.py (t*, p*).
Usage: plot_lobovsky_peer.py <validation-csv-directory> <pysph csv> [<pysph csv> ...] --png out.png"""
import argparse
import csv
import os
import re

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from pysph.examples import db_exp_data  # the experiment's curve, as the peer script scores it

LOBOVSKY_T, _, _, LOBOVSKY_P, _, _ = db_exp_data.get_lobovsky_data()
parser = argparse.ArgumentParser()
parser.add_argument("validation")
parser.add_argument("pysph", nargs="+")
parser.add_argument("--png", required=True)
args = parser.parse_args()

WINDOW = (2.5, 3.2)  # t*: after the first peak, up to where both runs reach


def mean_departure(t, p):
    """Mean |p - p_experiment| over WINDOW at the run's own samples (unfiltered)."""
    t, p = np.asarray(t), np.asarray(p)
    inside = (t >= WINDOW[0]) & (t <= WINDOW[1])
    return float(np.mean(np.abs(p[inside] - np.interp(t[inside], LOBOVSKY_T, LOBOVSKY_P))))


fig, (whole, impact) = plt.subplots(1, 2, figsize=(12, 4.5))
shades = ["tab:red", "darkred", "salmon"]
with open(os.path.join(args.validation, "lobovsky_curves.csv")) as f:
    rows = [r for r in csv.reader(f) if r and r[0] != "solver"]
runs = sorted({(r[0], int(r[1])) for r in rows})
for k, (solver, across) in enumerate(runs):
    t = [float(r[2]) for r in rows if (r[0], int(r[1])) == (solver, across)]
    p = [float(r[3]) for r in rows if (r[0], int(r[1])) == (solver, across)]
    print("ParaFluid %s, %d across: mean |p* - experiment| over t* %.1f-%.1f = %.2f" % (
        solver, across, WINDOW[0], WINDOW[1], mean_departure(t, p)))
    for ax in (whole, impact):
        ax.plot(t, p, "-", color=shades[k % len(shades)], lw=1, label="ParaFluid %s, %d across" % (solver, across))
blues = ["tab:blue", "navy", "lightblue"]
for k, path in enumerate(args.pysph):
    with open(path) as f:
        pts = [(float(r[0]), float(r[1])) for r in csv.reader(f) if r and r[0] != "t_star"]
    t, p = [q[0] for q in pts], [q[1] for q in pts]
    across = re.search(r"(\d+)", os.path.basename(path)).group(1)
    print("pysph WCSPH, %s across: mean |p* - experiment| over t* %.1f-%.1f = %.2f" % (
        across, WINDOW[0], WINDOW[1], mean_departure(t, p)))
    for ax in (whole, impact):
        ax.plot(t, p, "-", color=blues[k % len(blues)], lw=1, label="pysph WCSPH, %s across" % across)
for ax in (whole, impact):
    ax.plot(LOBOVSKY_T, LOBOVSKY_P, "k^-", label="Lobovsky et al. (2014), sensor 1")
    ax.set_xlabel("t sqrt(g / H)")
    ax.set_ylabel("p / (rho g H)")
whole.set_yscale("symlog", linthresh=1.0)
whole.set_xlim(0.0, 3.6)
whole.set_title("Wall pressure 3 mm above the floor")
impact.set_xlim(2.3, 3.2)
impact.set_title("The impact (linear scale)")
whole.legend(fontsize=7)
fig.tight_layout()
fig.savefig(args.png, dpi=110)
print("wrote", args.png)
