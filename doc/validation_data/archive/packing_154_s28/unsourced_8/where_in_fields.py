#!/usr/bin/python3
"""Where things lie in a 3D levelsinter VTU of a packing (issue 26,
session 28; doc/validation.md, "Packings: interface cells without a xi
source").

usage: where_in_fields.py unsourced|speed FIELDS.vtu PARTICLES.csv h

unsourced: the interface cells (alpha changes sign over the vertices)
whose xi is 0 at a vertex, against all interface cells: the distance from
the cell centre to the second-nearest sphere's surface, and the cell sizes
met going inward towards the nearest sphere's centre at depths 1..7 h.
speed: the interface nodes with the largest |velocity| (and each of its
parts), with their gaps to the two nearest spheres' surfaces."""
import sys
from collections import Counter
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, '/work/main/scripts')
import plot_field as pf


def read_hexes(path):
    """Points, hexahedra (point indices) and point fields of every piece."""
    root = ET.parse(path).getroot()
    compressed = root.get("compressor") == "vtkZLibDataCompressor"
    points, cells, fields, offset = [], [], {}, 0
    for piece in root.iter("Piece"):
        p = pf.vtu_array(piece.find("Points/DataArray"), compressed)
        c = {a.get("Name"): pf.vtu_array(a, compressed).ravel()
             for a in piece.find("Cells")}
        cells.append(c["connectivity"].reshape(-1, 8) + offset)
        points.append(p)
        offset += len(p)
        for a in piece.find("PointData"):
            fields.setdefault(a.get("Name"), []).append(
                pf.vtu_array(a, compressed))
    return (np.vstack(points), np.vstack(cells),
            {k: np.vstack(v) for k, v in fields.items()})


def read_spheres(path):
    rows = []
    for line in open(path):
        line = line.strip()
        if not line or line[0] == '#' or line[0].isalpha():
            continue
        rows.append([float(v) for v in line.split(',')[:4]])
    return np.array(rows)


def gaps(points, spheres):
    """Distances to the spheres' surfaces, nearest first, per point."""
    d = np.linalg.norm(points[:, None, :] - spheres[None, :, :3], axis=2)
    return np.sort(d - spheres[None, :, 3], axis=1)


def main():
    what, path, particles, h = sys.argv[1], sys.argv[2], sys.argv[3], float(
        sys.argv[4])
    P, C, F = read_hexes(path)
    spheres = read_spheres(particles)
    a = F["alpha"][:, 0][C]
    interface = (a.min(1) <= 0) & (a.max(1) > 0)

    if what == "unsourced":
        unsourced = interface & (np.abs(F["volume_diffusion_xi"][:, 0][C]).min(1)
                                 == 0)
        centre = P[C].mean(1)
        size = P[C][:, :, 0].max(1) - P[C][:, :, 0].min(1)
        order = np.argsort(centre[:, 0])

        def containing(p):
            lo = np.searchsorted(centre[order, 0], p[0] - 8.4 * h)
            hi = np.searchsorted(centre[order, 0], p[0] + 8.4 * h)
            idx = order[lo:hi]
            inside = np.all(np.abs(centre[idx] - p) <= size[idx, None] / 2 + 1e-9,
                            axis=1)
            return idx[inside][0] if inside.any() else -1

        print(f"interface cells {interface.sum()}, unsourced {unsourced.sum()}")
        for name, mask in (("unsourced", unsourced), ("all interface", interface)):
            second = gaps(centre[mask], spheres)[:, 1]
            print(name, "cell sizes / h:",
                  np.unique(np.round(size[mask] / h, 2), return_counts=True))
            for limit in (1, 2, 3, 4, 6, 100):
                print(f"  second sphere within {limit} h of the centre: "
                      f"{np.mean(second < limit * h) * 100:.0f} %")
        for name, mask in (("unsourced", unsourced),
                           ("sourced interface", interface & ~unsourced)):
            print(name)
            rows = Counter()
            for cell in np.flatnonzero(mask)[:300]:
                c = centre[cell]
                nearest = spheres[np.argmin(np.linalg.norm(c - spheres[:, :3],
                                                           axis=1) - spheres[:, 3])]
                n = (nearest[:3] - c) / np.linalg.norm(nearest[:3] - c)
                sizes = []
                for k in range(1, 8):
                    j = containing(c + k * h * n)
                    sizes.append(round(size[j] / h) if j >= 0 else -1)
                rows[tuple(sizes)] += 1
            for sizes, count in rows.most_common(6):
                print("  sizes/h at depth 1..7 h:", sizes, count)
    elif what == "speed":
        nodes = np.unique(C[interface].ravel())
        for name in [k for k in F if 'velocity' in k and F[k].shape[1] >= 3]:
            speed = np.linalg.norm(F[name][nodes, :3], axis=1)
            print(name, "max", speed.max())
            for n in nodes[np.argsort(speed)[-8:]][::-1]:
                d = gaps(P[n][None, :], spheres)[0]
                print(f"   |v| {np.linalg.norm(F[name][n, :3]):8.3f} at "
                      f"{np.round(P[n], 4)}  alpha {F['alpha'][n, 0]:+.4f}  gaps "
                      f"to spheres {d[0] / h:+.2f} h, {d[1] / h:+.2f} h")
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
