#!/usr/bin/python3
"""A field at a neck of a 2D run, read from its XDMF/HDF5 field files: on
the line x = X (a symmetry plane through the neck), the first crossing of
the interface above y = Y0 (a point inside the neck), and the field one
finest cell H inside the solid from there, interpolated linearly between
the nodes on the line. The application measures this
(neck_viscoelastic_trace_c) for a pair of equal particles only; this
reads it for any neck that a symmetry plane cuts, e.g. the ring's
(doc/validation.md, "Viscoelastic melts past topology change and in a
3D packing").

usage: neck_field_2d.py RUN_DIR --csv OUT.csv --y0 Y0 --h H [--x X]
                        [--field NAME]

RUN_DIR holds fields.xdmf and its fields_NNNNN.h5 (Output/Field formats
= xdmf); NAME defaults to viscoelastic_trace_c, X to 0. OUT.csv: time,
the crossing's y and the field there, one row per field file; printed:
the field's largest value and when.
"""
import argparse
import csv
import os
import re

import h5py
import numpy as np

parser = argparse.ArgumentParser(usage=__doc__)
parser.add_argument("run")
parser.add_argument("--csv", required=True)
parser.add_argument("--y0", type=float, required=True)
parser.add_argument("--h", type=float, required=True)
parser.add_argument("--x", type=float, default=0.0)
parser.add_argument("--field", default="viscoelastic_trace_c")
args = parser.parse_args()

# Each <Grid> of the temporal collection: its time, then its HDF5 file.
xdmf = open(os.path.join(args.run, "fields.xdmf")).read()
steps = re.findall(r'<Time Value="([^"]+)"/>.*?(fields_\d+\.h5):/nodes', xdmf,
                   re.S)

rows = []
for time, name in steps:
    f = h5py.File(os.path.join(args.run, name), "r")
    if args.field not in f:
        continue  # the conformation is written from the first step on
    nodes = np.asarray(f["nodes"])
    on_line = np.abs(nodes[:, 0] - args.x) < 1e-9
    y = nodes[on_line, 1]
    order = np.argsort(y)
    y = y[order]
    alpha = np.asarray(f["alpha"])[on_line, 0][order]
    field = np.asarray(f[args.field])[on_line, 0][order]
    crossing = float("nan")
    for i in range(1, len(y)):
        if y[i - 1] >= args.y0 and alpha[i - 1] < 0 <= alpha[i]:
            s = alpha[i - 1] / (alpha[i - 1] - alpha[i])
            crossing = y[i - 1] + s * (y[i] - y[i - 1])
            break
    value = float(np.interp(crossing - args.h, y, field))
    rows.append((float(time), crossing, value))

with open(args.csv, "w", newline="") as out:
    writer = csv.writer(out)
    writer.writerow(["time", "neck_surface_y", f"neck_{args.field}"])
    for row in rows:
        writer.writerow([f"{v:.8g}" for v in row])
largest = max(rows, key=lambda r: r[2])
print(f"largest {args.field} at the neck: {largest[2]:.6g} at t = "
      f"{largest[0]:.6g} ({len(rows)} field files)")
