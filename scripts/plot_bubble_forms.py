#!/usr/bin/python3
"""Static bubble, one line per surface-tension form: the mean-pressure
error, the core pressure-jump error and C = v_max eta / gamma against h
(left to right), and the mean-pressure error against CPU time.

usage: plot_bubble_forms.py OUT.png FILE.csv [LABEL_SUFFIX=FILE.csv ...]

Each CSV is written by `levelsinter_viscous_validation bubble ... --csv`
(columns level, h, form, cpu_time, pressure_error, core_error, C, ...;
form 0 csf, 1 sharp, 2 csf-curvature, 3 csf-curvature with kappa = 1/R).
The paper's values at h = 1/256 (mean pressure 1.72e-2, C 3.7e-3) are
drawn as stars.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

names = {0: "csf tensorial", 1: "sharp tensorial", 2: "csf-curvature",
         3: "csf-curvature, exact kappa"}
fig, axes = plt.subplots(1, 4, figsize=(16, 4))
for argument in sys.argv[2:]:
    suffix, _, name = argument.rpartition("=")
    rows = list(csv.DictReader(open(name)))
    for form in sorted({int(float(r["form"])) for r in rows}):
        mine = [r for r in rows if int(float(r["form"])) == form]
        h = [float(r["h"]) for r in mine]
        label = names[form] + (" " + suffix if suffix else "")
        for ax, column in zip(axes[:3], ["pressure_error", "core_error", "C"]):
            ax.loglog(h, [max(float(r[column]), 1e-16) for r in mine], "o-",
                      label=label)
        axes[3].loglog([float(r["cpu_time"]) for r in mine],
                       [float(r["pressure_error"]) for r in mine], "o-",
                       label=label)
axes[0].plot([1 / 256], [1.72e-2], "k*", markersize=12, label="paper (ASGS)")
axes[2].plot([1 / 256], [3.7e-3], "k*", markersize=12, label="paper")
for ax, title in zip(axes, ["mean-pressure error", "core pressure-jump error",
                            "C = v_max eta / gamma",
                            "mean-pressure error vs CPU time"]):
    ax.set_title(title)
    ax.grid(alpha=0.3, which="both")
for ax in axes[:3]:
    ax.set_xlabel("h")
axes[3].set_xlabel("CPU time of the solve (s)")
axes[2].legend(fontsize=7)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=100)
