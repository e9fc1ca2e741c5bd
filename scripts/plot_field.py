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
import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np

parser = argparse.ArgumentParser(usage=__doc__)
parser.add_argument("fields")
parser.add_argument("out")
parser.add_argument("limits", nargs="*", type=float)
parser.add_argument("--field", default="alpha")
parser.add_argument("--contours", default="")
parser.add_argument("--label")
args = parser.parse_args()
if len(args.limits) not in (0, 4):
    parser.error("give all four of xmin xmax ymin ymax, or none")


def read(path):
    """Triangulation (each quad split in two) and the file's datasets."""
    f = h5py.File(path, "r")
    nodes = np.asarray(f["nodes"])
    cells = np.asarray(f["cells"])
    if nodes.shape[1] != 2:
        parser.error("plot_field.py draws 2D fields only")
    # deal.II writes quads in lexicographic-then-reversed order (0,1,3,2);
    # split each into two triangles.
    tris = np.vstack([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]])
    return f, nodes, cells, mtri.Triangulation(nodes[:, 0], nodes[:, 1], tris)


f, nodes, cells, tri = read(args.fields)
values = np.asarray(f[args.field])[:, 0]
alpha = np.asarray(f["alpha"])[:, 0]
fig, ax = plt.subplots(figsize=(7, 7))
colours = ax.tripcolor(tri, values, shading="gouraud", cmap="coolwarm")
if args.field != "alpha":
    fig.colorbar(colours, ax=ax, shrink=0.7, label=args.field)
for quad in cells:
    xy = nodes[np.append(quad, quad[0])]
    ax.plot(xy[:, 0], xy[:, 1], color="0.6", lw=0.2)
ax.tricontour(tri, alpha, levels=[0.0], colors="k", linewidths=1.2)
handles = ([plt.Line2D([], [], color="k", lw=1.2, label=args.label)]
           if args.label else [])
for i, item in enumerate(c for c in args.contours.split(",") if c):
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
if args.limits:
    ax.set_xlim(*args.limits[:2])
    ax.set_ylim(*args.limits[2:])
fig.savefig(args.out, dpi=110, bbox_inches="tight")
