#!/usr/bin/python3
"""The densification curve of a grain-boundary run (doc/validation.md,
"Grain boundaries and densification").

usage: plot_densification.py RUN_DIRECTORY OUT.png --csv OUT.csv [LABEL=RUN ...]

Reads RUN_DIRECTORY/metrics.csv (a scene with `Grain boundaries`), writes
OUT.csv with the columns time, grain_relative_density (where the grain
centres span a box), shrinkage_x/_y/_z (those present),
grain_boundary_radius_mean, grain_volume_change_max, volume_change,
grain_boundaries and the packing analysis' relative_density,
open_porosity, closed_porosity and closed_pores (where present), and
OUT.png: the relative density, the shrinkage and the volume per grain
(grain_volume_change_max, the largest |V_i / V_i(0) - 1|, with the
solid's |volume_change|) against time. Further LABEL=RUN pairs add those
runs' shrinkage (e.g. rows of 2 and 4 grains).
A file in doc/validation_data with more rows is not replaced
(scripts/validation_data.py).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_data

if len(sys.argv) < 5 or sys.argv[3] != "--csv":
    sys.exit(__doc__)
run, out_png, _, out_csv = sys.argv[1:5]
extra = [item.split("=", 1) for item in sys.argv[5:]]


def read(directory):
    with open(os.path.join(directory, "metrics.csv")) as f:
        return list(csv.DictReader(f))


rows = read(run)
columns = ["time"] + [c for c in ("grain_relative_density", "shrinkage_x",
                                  "shrinkage_y", "shrinkage_z",
                                  "grain_boundary_radius_mean",
                                  "grain_volume_change_max", "volume_change",
                                  "grain_boundaries", "relative_density",
                                  "open_porosity", "closed_porosity",
                                  "closed_pores")
                      if c in rows[0]]
validation_data.refuse_shorter(out_csv, rows)
with open(out_csv, "w", newline="") as f:
    writer = csv.writer(f)
    writer.writerow(columns)
    for r in rows:
        writer.writerow([r[c] for c in columns])

density = "grain_relative_density" in rows[0]
panels = 3 if density else 2
fig, axes = plt.subplots(1, panels, figsize=(4.8 * panels, 4))
axes = list(axes)
t = [float(r["time"]) for r in rows]
if density:
    axes[0].plot(t, [float(r["grain_relative_density"]) for r in rows], "k-")
    axes[0].set_xlabel("t")
    axes[0].set_ylabel("relative density (box of the grain centres)")
    axes[0].grid(True, alpha=0.3)
ax = axes[-2]
for axis in "xyz":
    if "shrinkage_" + axis in rows[0]:
        ax.plot(t, [float(r["shrinkage_" + axis]) for r in rows],
                label=f"shrinkage {axis}")
for label, directory in extra:
    other = read(directory)
    ax.plot([float(r["time"]) for r in other],
            [float(r["shrinkage_x"]) for r in other], "--", label=label)
ax.set_xlabel("t")
ax.set_ylabel("1 - L / L0 (grain centres)")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
ax = axes[-1]
for column, label in (("grain_volume_change_max", "largest grain |V / V0 - 1|"),
                      ("volume_change", "solid |V / V0 - 1|")):
    values = [(time, abs(float(r[column]))) for time, r in zip(t, rows)
              if float(r[column]) != 0]
    ax.semilogy([v[0] for v in values], [v[1] for v in values], label=label)
ax.set_xlabel("t")
ax.set_ylabel("volume change")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out_png, dpi=110)
