#!/usr/bin/python3
"""Render a 2D levelsinter field file as a PNG: the mesh, alpha (or --field
NAME) in colour and its zero contour (the interface) in black.

usage: plot_field.py FIELDS OUT.png [xmin xmax ymin ymax]
                     [--field NAME] [--contours LABEL=FIELDS,...]
                     [--label LABEL] [--list]

FIELDS is a file the run wrote in Output/Directory: fields_NNNNN.h5
(XDMF/HDF5), fields_NNNNN.pvtu or the VTU file it names (every rank's
piece). --field colours by another field of the file (e.g.
volume_diffusion_pressure, with a colour bar; the first component of a
vector); --contours adds the zero contours of alpha from earlier field
files (dashed, labelled), so that shapes at several times can be
compared; --label names the main contour; --list prints the fields of
FIELDS and stops.
"""
import argparse
import base64
import pathlib
import struct
import xml.etree.ElementTree as ElementTree
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
from matplotlib.collections import LineCollection
import numpy as np

VTK_TYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4",
             "Int64": "<i8", "UInt8": "u1", "UInt32": "<u4", "UInt64": "<u8"}
VTK_QUAD = 9


def vtu_array(element, compressed):
    """The values of a VTU DataArray (ascii, or base64 binary as deal.II
    writes it: zlib blocks after a UInt32 header, or one raw block)."""
    dtype = np.dtype(VTK_TYPES[element.get("type")])
    text = "".join((element.text or "").split())
    components = int(element.get("NumberOfComponents", "1"))
    if element.get("format") == "ascii":
        values = np.array(text.split(), dtype=dtype)
    elif compressed:
        # Header: number of blocks, block size, last block size, the
        # compressed size of each block; base64 on its own, then the data.
        blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
        header_length = 4 * ((4 * (3 + blocks) + 2) // 3)
        header = struct.unpack(f"<{3 + blocks}I",
                               base64.b64decode(text[:header_length]))
        data = base64.b64decode(text[header_length:])
        raw, start = b"", 0
        for size in header[3:]:
            raw += zlib.decompress(data[start:start + size])
            start += size
        values = np.frombuffer(raw, dtype=dtype)
    else:
        raw = base64.b64decode(text)
        size = struct.unpack("<I", raw[:4])[0]
        values = np.frombuffer(raw[4:4 + size], dtype=dtype)
    return values.reshape(-1, components)


def join(pieces):
    """Nodes, quads and fields of several (points, quads, fields) pieces."""
    nodes, quads, fields, offset = [], [], {}, 0
    for points, cells, values in pieces:
        nodes.append(points)
        quads.append(cells + offset)
        offset += len(points)
        for name, array in values.items():
            fields.setdefault(name, []).append(array)
    return (np.vstack(nodes), np.vstack(quads),
            {name: np.vstack(arrays) for name, arrays in fields.items()})


def vtu_pieces(path):
    """Points, quads (point indices) and point fields of each piece of a VTU
    file (deal.II writes one piece per rank into a single file)."""
    root = ElementTree.parse(path).getroot()
    compressed = root.get("compressor") == "vtkZLibDataCompressor"
    for piece in root.iter("Piece"):
        points = vtu_array(piece.find("Points/DataArray"), compressed)
        cells = {a.get("Name"): vtu_array(a, compressed).ravel()
                 for a in piece.find("Cells")}
        if np.any(cells["types"] != VTK_QUAD):
            raise SystemExit(f"{path}: plot_field.py draws 2D fields of "
                             "quadrilaterals only")
        fields = {a.get("Name"): vtu_array(a, compressed)
                  for a in piece.find("PointData")}
        yield points[:, :2], cells["connectivity"].reshape(-1, 4), fields


def read_vtu(path):
    return join(vtu_pieces(path))


def read_pvtu(path):
    """The pieces of the VTU files a PVTU record names."""
    root = ElementTree.parse(path).getroot()
    return join(piece for source in root.iter("Piece")
                for piece in vtu_pieces(path.parent / source.get("Source")))


def read_h5(path):
    import h5py
    with h5py.File(path, "r") as f:
        nodes = np.asarray(f["nodes"])
        if nodes.shape[1] != 2:
            raise SystemExit(f"{path}: plot_field.py draws 2D fields only")
        return nodes, np.asarray(f["cells"]), {
            name: np.asarray(f[name]) for name in f
            if name not in ("nodes", "cells")}


def read(path):
    """Nodes, quads, fields (name -> first component per node) and the
    triangulation (each quad split in two) of a field file."""
    path = pathlib.Path(path)
    readers = {".h5": read_h5, ".vtu": read_vtu, ".pvtu": read_pvtu}
    if path.suffix not in readers:
        raise SystemExit(f"{path}: not a field file (.h5, .vtu or .pvtu)")
    nodes, quads, fields = readers[path.suffix](path)
    # A VTU piece repeats a vertex for each cell around it: one node each.
    nodes, index = np.unique(nodes, axis=0, return_inverse=True)
    index = index.ravel()
    quads = index[quads]
    first = np.zeros(len(nodes), dtype=int)
    first[index[::-1]] = np.arange(len(index))[::-1]
    fields = {name: values[first, 0] for name, values in fields.items()}
    # Quads in cyclic order (deal.II's VTU order; its HDF5 cells alike).
    tris = np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    return nodes, quads, fields, mtri.Triangulation(nodes[:, 0], nodes[:, 1],
                                                    tris)


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("fields")
    parser.add_argument("out", nargs="?")
    parser.add_argument("limits", nargs="*", type=float)
    parser.add_argument("--field", default="alpha")
    parser.add_argument("--contours", default="")
    parser.add_argument("--label")
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    if len(args.limits) not in (0, 4):
        parser.error("give all four of xmin xmax ymin ymax, or none")

    nodes, quads, fields, tri = read(args.fields)
    if args.list:
        print("\n".join(sorted(fields)))
        return
    if args.out is None:
        parser.error("give the PNG to write")
    if args.field not in fields:
        parser.error(f"{args.fields} has no field {args.field}; it has "
                     + ", ".join(sorted(fields)))
    fig, ax = plt.subplots(figsize=(7, 7))
    colours = ax.tripcolor(tri, fields[args.field], shading="gouraud",
                           cmap="coolwarm")
    if args.field != "alpha":
        fig.colorbar(colours, ax=ax, shrink=0.7, label=args.field)
    ax.add_collection(LineCollection(nodes[np.hstack([quads, quads[:, :1]])],
                                     colors="0.6", linewidths=0.2))
    ax.tricontour(tri, fields["alpha"], levels=[0.0], colors="k",
                  linewidths=1.2)
    handles = ([plt.Line2D([], [], color="k", lw=1.2, label=args.label)]
               if args.label else [])
    for i, item in enumerate(c for c in args.contours.split(",") if c):
        name, path = item.rsplit("=", 1)
        colour = f"C{i + 2}"
        _, _, earlier_fields, earlier = read(path)
        ax.tricontour(earlier, earlier_fields["alpha"], levels=[0.0],
                      colors=colour, linewidths=1.0, linestyles="--")
        handles.append(plt.Line2D([], [], color=colour, ls="--", label=name))
    if handles:
        ax.legend(handles=handles, loc="upper left", fontsize=8)
    ax.set_aspect("equal")
    if args.limits:
        ax.set_xlim(*args.limits[:2])
        ax.set_ylim(*args.limits[2:])
    fig.savefig(args.out, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
