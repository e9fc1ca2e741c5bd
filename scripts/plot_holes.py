#!/usr/bin/python3
"""Holes closing by viscous flow: each hole's area against time, one
panel per series file, with the concentric annulus of the same areas
(exact, doc/numerics.md "Hollow cylinder") dashed.

usage: plot_holes.py OUT.png TITLE=SERIES.csv[:b] [TITLE=SERIES.csv[:b] ...]

SERIES.csv is a `shapes holes ... --csv FILE` series FILE.levelN.csv
(columns time, area_change, area_k, roundness_k); b (default 0.3) is the
cylinder's radius for the annulus curves (gamma = eta_s = 1). The solid's
relative area change is drawn on a second axis (grey).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def annulus_area(b, a0, t):
    """Hole area of the concentric annulus b, a0 at t (gamma = eta = 1)."""
    w = b - a0 + t / 2
    a = ((b * b - a0 * a0) / w - w) / 2
    return math.pi * max(a, 0) ** 2


panels = sys.argv[2:]
fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 4),
                         squeeze=False)
for ax, argument in zip(axes[0], panels):
    title, _, rest = argument.rpartition("=")
    name, _, b = rest.partition(":")
    b = float(b) if b else 0.3
    rows = list(csv.DictReader(open(name)))
    t = [float(r["time"]) for r in rows]
    k = 1
    while f"area_{k}" in rows[0]:
        area = [float(r[f"area_{k}"]) for r in rows]
        line, = ax.plot(t, area, label=f"hole {k}")
        a0 = math.sqrt(area[0] / math.pi)
        ax.plot(t, [annulus_area(b, a0, s) for s in t], "--",
                color=line.get_color(), alpha=0.7,
                label=f"annulus b = {b}, a0 = {a0:.3f}")
        k += 1
    ax.set_xlabel("t gamma / (eta_s * length unit)")
    ax.set_ylabel("hole area")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    drift = ax.twinx()
    drift.plot(t, [float(r["area_change"]) for r in rows], color="grey",
               alpha=0.5)
    drift.set_ylabel("solid area change (relative)", color="grey")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=100)
