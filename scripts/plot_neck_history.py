#!/usr/bin/python3
"""Neck radius, neck curvature and tr c at the neck against time for the
two-particle runs of `levelsinter_viscous_validation neck-history` (its
FILE.levelN.csv: time, neck_radius, neck_curvature, neck_trace_c,
max_trace_c), one curve per file, in three panels (the viscoelastic seed's
Figs. 10, 11 and 13).
Usage: plot_neck_history.py OUT.png [--t-max T] LABEL=FILE.levelN.csv ...
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

arguments = sys.argv[2:]
t_max = math.inf
if "--t-max" in arguments:
    i = arguments.index("--t-max")
    t_max = float(arguments[i + 1])
    del arguments[i : i + 2]

PANELS = [
    ("neck_radius", "neck half-width y"),
    ("neck_curvature", "neck curvature (seed's sign, Eq. 45)"),
    ("neck_trace_c", "tr c at the neck"),
]
fig, axes = plt.subplots(1, 3, figsize=(14, 4))
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for n, argument in enumerate(arguments):
    label, _, name = argument.rpartition("=")
    reader = csv.DictReader(open(name))
    rows = [r for r in reader if float(r["time"]) <= t_max]
    t = [float(r["time"]) for r in rows]
    for ax, (column, _) in zip(axes, PANELS):
        values = [float(r[column]) for r in rows]
        if all(math.isnan(v) for v in values):
            continue
        # One colour per file in every panel (a Newtonian run has no tr c).
        ax.plot(t, values, label=label or name, color=colours[n % len(colours)])
for ax, (_, title) in zip(axes, PANELS):
    ax.set_xlabel("t gamma / (eta_0 R)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
axes[0].legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=120)
