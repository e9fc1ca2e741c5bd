#!/usr/bin/python3
"""Render a 2D levelsinter field file (fields_NNNNN.h5) as a PNG: the mesh,
alpha in colour and its zero contour (the interface) in black.

usage: plot_field.py FIELDS.h5 OUT.png [xmin xmax ymin ymax]
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np

f = h5py.File(sys.argv[1], "r")
nodes = np.asarray(f["nodes"])
cells = np.asarray(f["cells"])
alpha = np.asarray(f["alpha"])[:, 0]
if nodes.shape[1] != 2:
    sys.exit("plot_field.py draws 2D fields only")
# deal.II writes quads in lexicographic-then-reversed order (0,1,3,2);
# split each into two triangles.
tris = np.vstack([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]])
tri = mtri.Triangulation(nodes[:, 0], nodes[:, 1], tris)
fig, ax = plt.subplots(figsize=(7, 7))
ax.tripcolor(tri, alpha, shading="gouraud", cmap="coolwarm")
for quad in cells:
    xy = nodes[np.append(quad, quad[0])]
    ax.plot(xy[:, 0], xy[:, 1], color="0.6", lw=0.2)
ax.tricontour(tri, alpha, levels=[0.0], colors="k", linewidths=1.2)
ax.set_aspect("equal")
if len(sys.argv) == 7:
    ax.set_xlim(float(sys.argv[3]), float(sys.argv[4]))
    ax.set_ylim(float(sys.argv[5]), float(sys.argv[6]))
fig.savefig(sys.argv[2], dpi=110, bbox_inches="tight")
