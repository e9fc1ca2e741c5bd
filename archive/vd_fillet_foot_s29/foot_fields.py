#!/usr/bin/python3
"""The filleted two grains' neck at one field file (session 29, issue 27):
xi and the solid's pressure along the upper neck surface, and the pressure
on the symmetry line x = 0.5 below the foot.

usage: foot_fields.py profile|column FIELDS.h5 LABEL X0 X1 >> OUT.csv

profile: per grid column x in [X0, X1] the first crossing of alpha = 0
above y = 0.5, xi there (linear between the crossing's two nodes), and xi
and p at the inner and the outer node. column: p and xi at every node on
x = 0.5 with X0 <= y <= X1. LABEL (e.g. "51.2,session-28") starts each
row; no header is written (doc/validation_data/archive/vd_fillet_foot_*.csv
have theirs).
"""
import sys

import h5py
import numpy as np

mode, path, label = sys.argv[1:4]
lo, hi = map(float, sys.argv[4:6])
f = h5py.File(path, "r")
nodes = np.asarray(f["nodes"])
alpha = np.asarray(f["alpha"])[:, 0]
xi = np.asarray(f["volume_diffusion_xi"])[:, 0]
p = np.asarray(f["volume_diffusion_pressure"])[:, 0]


def column(x):
    k = np.where((np.abs(nodes[:, 0] - x) < 1e-6) & (nodes[:, 1] > 0.5))[0]
    return k[np.argsort(nodes[k, 1])]


if mode == "column":
    for k in column(0.5):
        if lo <= nodes[k, 1] <= hi:
            print(f"{label},{nodes[k, 1]:.7f},{alpha[k]:.6g},{p[k]:.6g},"
                  f"{xi[k]:.6g}")
    sys.exit()
sel = (nodes[:, 0] >= lo - 1e-9) & (nodes[:, 0] <= hi + 1e-9)
for x in np.unique(np.round(nodes[sel, 0], 7)):
    k = column(x)
    for a, b in zip(k[:-1], k[1:]):
        if alpha[a] < 0 <= alpha[b]:
            s = alpha[a] / (alpha[a] - alpha[b])
            y = nodes[a, 1] + s * (nodes[b, 1] - nodes[a, 1])
            print(f"{label},{x:.7f},{y:.7f},{xi[a] + s * (xi[b] - xi[a]):.6g},"
                  f"{xi[a]:.6g},{xi[b]:.6g},{p[a]:.6g},{p[b]:.6g}")
            break
