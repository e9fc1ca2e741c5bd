#!/usr/bin/env python3
"""The 8 spheres like the 154 (Extrapolation = limited) at h, h / 2 and at
h with curvature refinement at the necks: relative density and mean neck
at fixed times, and their deviation from h / 2. Reads session 30's
h_lim / h2_lim metrics and this session's runs (run8.sh). Prints Markdown.

  table_curvature.py
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "..", "scripts"))
from packing_convergence import at  # noqa: E402  (rows, column, t)

HERE = os.path.dirname(os.path.abspath(__file__))
S30 = os.path.join(HERE, "..", "session30")
RUNS = [  # label, path
    ("h (the scene)", os.path.join(S30, "h_lim_metrics.csv")),
    ("h / 2 (reference)", os.path.join(S30, "h2_lim_metrics.csv")),
]
for name, label in [
    ("curv1_offset6", "h, 1 curvature level, offset 6"),
    ("curv1_offset5", "h, 1 curvature level, offset 5"),
    ("curv1_cpr2", "h, 1 curvature level, 2 cells per radius, offset 5"),
]:
    path = os.path.join(HERE, name + "_metrics.csv")
    if os.path.exists(path):
        RUNS.append((label, path))
TIMES = [0.0025, 0.005, 0.0075, 0.01, 0.0125, 0.015]
COLUMNS = [("relative_density", "density"), ("neck_mean", "mean neck")]


data = [(label, list(csv.DictReader(open(path)))) for label, path in RUNS]
reference = data[1][1]
for column, title in COLUMNS:
    print(f"\n{title} (deviation from h / 2)\n")
    print("| run | " + " | ".join(f"t = {t:g} s" for t in TIMES) + " |")
    print("|---|" + "---|" * len(TIMES))
    for label, rows in data:
        cells = []
        for t in TIMES:
            v, r = at(rows, column, t), at(reference, column, t)
            if math.isnan(v):
                cells.append("-")
                continue
            text = f"{v:.5f}" if column == "neck_mean" else f"{v:.4f}"
            if rows is not reference:
                text += f" ({100 * (v - r) / r:+.2f} %)"
            cells.append(text)
        print(f"| {label} | " + " | ".join(cells) + " |")
print("\ndensity gained since t = 0 (deviation from h / 2's gain; the "
      "density at t = 0 differs by the start's discretisation and the "
      "control volume counted in whole cells)\n")
print("| run | density at t = 0 | " +
      " | ".join(f"t = {t:g} s" for t in TIMES) + " |")
print("|---|---|" + "---|" * len(TIMES))
for label, rows in data:
    c = "relative_density"
    v0, r0 = float(rows[0][c]), float(reference[0][c])
    cells = []
    for t in TIMES:
        v, r = at(rows, c, t), at(reference, c, t)
        if math.isnan(v):
            cells.append("-")
            continue
        text = f"{v - v0:.4f}"
        if rows is not reference:
            text += f" ({100 * ((v - v0) - (r - r0)) / (r - r0):+.1f} %)"
        cells.append(text)
    print(f"| {label} | {v0:.4f} | " + " | ".join(cells) + " |")
print("\ncost\n")
print("| run | steps | level-set DoFs at t = 0 / largest / at the end | "
      "wall of the run (s) | shortest step from step 2 (s) |")
print("|---|---|---|---|---|")
for label, rows in data:
    dofs = [int(r["dofs"]) for r in rows]
    dts = [float(r["dt"]) for r in rows[2:]]
    print(f"| {label} | {len(rows) - 1} | {dofs[0]} / {max(dofs)} / "
          f"{dofs[-1]} | {float(rows[-1]['wall_time']):.0f} | "
          f"{min(dts):.2e} |")
