#!/usr/bin/env python3
"""The 8 spheres like the 154 at h and h / 2, xi's extension linear or
limited: metrics at fixed times from the runs' metrics CSVs (in this
directory, as written by run8.sh / h2_c2.sh, and session 29's), and their deviation
from the finest run of the same extrapolation. Prints Markdown tables.

  table_h_h2.py [DIR]
"""
import csv
import os
import sys

DIR = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(__file__)
RUNS = [  # label, file, reference label
    # Session 29's run of the scene (its build with the bound off).
    ("h, linear (the scene)", "../session29/speed_rise_8_xib_none",
     "h / 2, linear"),
    ("h, limited", "h_lim", "h / 2, limited"),
    ("h, limited, dt <= 5e-4 s", "h_lim_dt05", "h / 2, limited"),
    ("h / 2, linear", "h2_lin", None),
    ("h / 2, limited", "h2_lim", None),
]
TIMES = [0.0025, 0.005, 0.0075, 0.01, 0.0125, 0.015]
COLUMNS = [("relative_density", "density"), ("neck_mean", "mean neck")]


def load(name):
    path = os.path.join(DIR, name + "_metrics.csv")
    if not os.path.exists(path):
        return None
    return list(csv.DictReader(open(path)))


def at(rows, t, column):
    """Linear interpolation in time; None beyond the run's end."""
    for a, b in zip(rows, rows[1:]):
        ta, tb = float(a["time"]), float(b["time"])
        if ta <= t + 1e-12 and t <= tb + 1e-12:
            w = 0 if tb == ta else (t - ta) / (tb - ta)
            return (1 - w) * float(a[column]) + w * float(b[column])
    return None


data = {label: load(name) for label, name, _ in RUNS}
for column, title in COLUMNS:
    print(f"\n{title} (deviation from h / 2 of the same extrapolation)\n")
    print("| run | steps | " + " | ".join(f"t = {t:g} s" for t in TIMES) + " |")
    print("|---|---|" + "---|" * len(TIMES))
    for label, name, reference in RUNS:
        rows = data[label]
        if rows is None:
            continue
        cells = []
        for t in TIMES:
            v = at(rows, t, column)
            if v is None:
                cells.append("-")
                continue
            text = f"{v:.5f}" if column == "neck_mean" else f"{v:.4f}"
            ref = data.get(reference) if reference else None
            r = at(ref, t, column) if ref else None
            if r is not None:
                text += f" ({100 * (v - r) / r:+.2f} %)"
            cells.append(text)
        steps = len(rows) - 1
        print(f"| {label} | {steps} | " + " | ".join(cells) + " |")
print("\nstep and largest speed\n")
print("| run | steps | shortest step from step 2 (s) | largest speed from "
      "t = 0.009 s (um/s) |")
print("|---|---|---|---|")
for label, name, _ in RUNS:
    rows = data[label]
    if rows is None:
        continue
    # Step 1 is held by the speed at t = 0 (the contacts' corners).
    dts = [float(r["dt"]) for r in rows[2:]]
    late = [float(r["max_velocity"]) for r in rows if float(r["time"]) >= 0.009]
    print(f"| {label} | {len(rows) - 1} | {min(dts):.2e} | "
          f"{min(late):.1f}-{max(late):.1f} |")
print("\niterations, mean (range) over the steps\n")
print("| run | DoFs | transport | curvature / v_s | elastic | xi |")
print("|---|---|---|---|---|---|")
for label, name, _ in RUNS:
    rows = data[label]
    if rows is None:
        continue
    cells = []
    for column in ["transport_iterations", "surface_diffusion_iterations",
                   "volume_diffusion_mechanics_iterations",
                   "volume_diffusion_xi_iterations"]:
        v = [float(r[column]) for r in rows[1:]]
        cells.append(f"{sum(v) / len(v):.1f} ({min(v):.0f}-{max(v):.0f})")
    print(f"| {label} | {rows[-1]['dofs']} | " + " | ".join(cells) + " |")
