#!/usr/bin/python3
"""Where the interface cells without a xi source lie (a 3D levelsinter VTU):
interface cells (alpha changes sign over the vertices) whose xi is 0 at a
vertex, classified by the nearest grains of the particle file: the gap to
the second-nearest sphere at the cell centre (a neck or a near contact when
small) and the depth below the nearest sphere's surface.
usage: unsourced_where.py FIELDS.vtu PARTICLES.csv h"""
import sys, numpy as np, xml.etree.ElementTree as ET
sys.path.insert(0, '/work/main/scripts')
import plot_field as pf
path, particles, h = sys.argv[1], sys.argv[2], float(sys.argv[3])
root = ET.parse(path).getroot()
compressed = root.get("compressor") == "vtkZLibDataCompressor"
P, C, F = [], [], {}
off = 0
for piece in root.iter("Piece"):
    pts = pf.vtu_array(piece.find("Points/DataArray"), compressed)
    cells = {a.get("Name"): pf.vtu_array(a, compressed).ravel() for a in piece.find("Cells")}
    conn = cells["connectivity"].reshape(-1, 8)
    P.append(pts); C.append(conn + off); off += len(pts)
    for a in piece.find("PointData"):
        F.setdefault(a.get("Name"), []).append(pf.vtu_array(a, compressed))
P = np.vstack(P); C = np.vstack(C); F = {k: np.vstack(v) for k, v in F.items()}
alpha = F["alpha"][:, 0]; xi = F["volume_diffusion_xi"][:, 0]
a = alpha[C]; x = xi[C]
iface = (a.min(1) <= 0) & (a.max(1) > 0)
uns = iface & (np.abs(x).min(1) == 0)
sph = []
for line in open(particles):
    line = line.strip()
    if not line or line[0] == '#' or line[0].isalpha(): continue
    sph.append([float(v) for v in line.split(',')[:4]])
sph = np.array(sph)
cent = P[C].mean(1)
size = P[C][:, :, 0].max(1) - P[C][:, :, 0].min(1)
def classify(mask):
    c = cent[mask]
    d = np.linalg.norm(c[:, None, :] - sph[None, :, :3], axis=2) - sph[None, :, 3]
    ds = np.sort(d, axis=1)
    return ds[:, 0], ds[:, 1], size[mask]
print(f"interface cells {iface.sum()}, unsourced {uns.sum()}")
for name, m in (("unsourced", uns), ("all interface", iface)):
    d0, d1, s = classify(m)
    print(name, "cell sizes / h:", np.unique(np.round(s / h, 2), return_counts=True))
    for lim in (1, 2, 3, 4, 6, 100):
        print(f"  second sphere within {lim} h of the centre: {np.mean(d1 < lim*h)*100:.0f} %")

# Cell sizes met going inward from the cell centre towards the nearest
# sphere's centre, at depths k h (k = 1..7): the refined band's inner edge.
from collections import Counter
order = np.argsort(cent[:, 0])
def containing(p):
    lo = np.searchsorted(cent[order, 0], p[0] - 2.1 * h * 4)
    hi = np.searchsorted(cent[order, 0], p[0] + 2.1 * h * 4)
    idx = order[lo:hi]
    inside = np.all(np.abs(cent[idx] - p) <= size[idx, None] / 2 + 1e-9, axis=1)
    return idx[inside][0] if inside.any() else -1
def profile(mask, limit=300):
    rows = Counter()
    for ci in np.flatnonzero(mask)[:limit]:
        c = cent[ci]
        d = np.linalg.norm(c - sph[:, :3], axis=1) - sph[:, 3]
        s = sph[np.argmin(d)]
        n = (s[:3] - c) / np.linalg.norm(s[:3] - c)
        sizes = []
        for k in range(1, 8):
            j = containing(c + k * h * n)
            sizes.append(round(size[j] / h) if j >= 0 else -1)
        rows[tuple(sizes)] += 1
    return rows
for name, m in (("unsourced", uns), ("sourced interface", iface & ~uns)):
    print(name)
    for k, v in profile(m).most_common(6):
        print("  sizes/h at depth 1..7 h:", k, v)
