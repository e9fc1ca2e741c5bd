#!/usr/bin/python3
"""Relative neck error against time for Hopper's two cylinders, from the
neck histories the hopper driver writes (viscous_validation hopper ...
--csv FILE gives FILE.levelN.csv: t gamma/(eta R), neck / R, exact / R).
Usage: plot_hopper_error.py OUT.png LABEL=FILE.levelN.csv ...
A dashed line marks the 0.5 % target."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(6.5, 4))
for argument in sys.argv[2:]:
    label, _, name = argument.rpartition("=")
    rows = list(csv.DictReader(open(name)))
    tau = [float(r["t_gamma_over_eta_R"]) for r in rows]
    error = [abs(float(r["neck_over_R"]) / float(r["exact_neck_over_R"]) - 1)
             for r in rows]
    # The exact start has no error at t = 0: leave it off the log axis.
    points = [(t, e) for t, e in zip(tau, error) if e > 0]
    ax.plot([p[0] for p in points], [p[1] for p in points],
            label=label or name)
ax.axhline(0.005, color="k", linestyle="--", linewidth=0.8,
           label="0.5 % target")
ax.set_yscale("log")
ax.set_xlabel("t gamma / (eta R)")
ax.set_ylabel("|neck / Hopper's - 1|")
ax.legend(fontsize=7)
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=120)
