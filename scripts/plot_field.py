#!/usr/bin/python3
"""Render a 2D levelsinter field file (fields_NNNNN.h5) as a PNG: the mesh,
alpha (or --field NAME) in colour and its zero contour (the interface) in
black.

usage: plot_field.py FIELDS.h5 OUT.png [xmin xmax ymin ymax]
                     [--field NAME] [--contours LABEL=FILE.h5,...]
                     [--label LABEL]

--field colours by another field of the file (e.g.
volume_diffusion_pressure, with a colour bar); --contours adds the zero
contours of alpha from earlier field files (dashed, labelled), so that
shapes at several times can be compared; --label names the main contour.
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np

args = sys.argv[1:]


def option(name, default):
    if name in args:
        i = args.index(name)
        value = args[i + 1]
        del args[i : i + 2]
        return value
    return default


field = option("--field", "alpha")
contours = option("--contours", "")
label = option("--label", None)
if len(args) not in (2, 6):
    sys.exit(__doc__)


def read(path):
    """Triangulation (each quad split in two) and the file's datasets."""
    f = h5py.File(path, "r")
    nodes = np.asarray(f["nodes"])
    cells = np.asarray(f["cells"])
    if nodes.shape[1] != 2:
        sys.exit("plot_field.py draws 2D fields only")
    # deal.II writes quads in lexicographic-then-reversed order (0,1,3,2);
    # split each into two triangles.
    tris = np.vstack([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]])
    return f, nodes, cells, mtri.Triangulation(nodes[:, 0], nodes[:, 1], tris)


f, nodes, cells, tri = read(args[0])
values = np.asarray(f[field])[:, 0]
alpha = np.asarray(f["alpha"])[:, 0]
fig, ax = plt.subplots(figsize=(7, 7))
colours = ax.tripcolor(tri, values, shading="gouraud", cmap="coolwarm")
if field != "alpha":
    fig.colorbar(colours, ax=ax, shrink=0.7, label=field)
for quad in cells:
    xy = nodes[np.append(quad, quad[0])]
    ax.plot(xy[:, 0], xy[:, 1], color="0.6", lw=0.2)
ax.tricontour(tri, alpha, levels=[0.0], colors="k", linewidths=1.2)
handles = [plt.Line2D([], [], color="k", lw=1.2, label=label)] if label else []
for i, item in enumerate(c for c in contours.split(",") if c):
    name, path = item.rsplit("=", 1)
    colour = f"C{i + 2}"
    earlier_file, _, _, earlier = read(path)
    ax.tricontour(earlier, np.asarray(earlier_file["alpha"])[:, 0],
                  levels=[0.0], colors=colour, linewidths=1.0,
                  linestyles="--")
    handles.append(plt.Line2D([], [], color=colour, ls="--", label=name))
if handles:
    ax.legend(handles=handles, loc="upper left", fontsize=8)
ax.set_aspect("equal")
if len(args) == 6:
    ax.set_xlim(float(args[2]), float(args[3]))
    ax.set_ylim(float(args[4]), float(args[5]))
fig.savefig(args[1], dpi=110, bbox_inches="tight")
