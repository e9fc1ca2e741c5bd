#!/usr/bin/python3
"""Where the largest interface speeds are in a 3D levelsinter VTU: the nodes
of interface cells with the largest |velocity| (and its parts), with the
gap to the nearest and second-nearest spheres of the particle file.
usage: maxspeed_where.py FIELDS.vtu PARTICLES.csv h"""
import sys, numpy as np, xml.etree.ElementTree as ET
sys.path.insert(0, '/work/main/scripts')
import plot_field as pf
path, particles, h = sys.argv[1], sys.argv[2], float(sys.argv[3])
root = ET.parse(path).getroot()
compressed = root.get("compressor") == "vtkZLibDataCompressor"
P, C, F, off = [], [], {}, 0
for piece in root.iter("Piece"):
    pts = pf.vtu_array(piece.find("Points/DataArray"), compressed)
    cells = {a.get("Name"): pf.vtu_array(a, compressed).ravel() for a in piece.find("Cells")}
    C.append(cells["connectivity"].reshape(-1, 8) + off); P.append(pts); off += len(pts)
    for a in piece.find("PointData"):
        F.setdefault(a.get("Name"), []).append(pf.vtu_array(a, compressed))
P = np.vstack(P); C = np.vstack(C); F = {k: np.vstack(v) for k, v in F.items()}
print("fields:", {k: v.shape[1] for k, v in F.items()})
alpha = F["alpha"][:, 0]
a = alpha[C]
iface = (a.min(1) <= 0) & (a.max(1) > 0)
nodes = np.unique(C[iface].ravel())
sph = []
for line in open(particles):
    line = line.strip()
    if not line or line[0] == '#' or line[0].isalpha(): continue
    sph.append([float(v) for v in line.split(',')[:4]])
sph = np.array(sph)
for name in [k for k in F if 'velocity' in k and F[k].shape[1] >= 3]:
    s = np.linalg.norm(F[name][nodes, :3], axis=1)
    top = nodes[np.argsort(s)[-8:]][::-1]
    print(name, "max", s.max())
    for n in top:
        d = np.sort(np.linalg.norm(P[n] - sph[:, :3], axis=1) - sph[:, 3])
        print(f"   |v| {np.linalg.norm(F[name][n,:3]):8.3f} at {np.round(P[n],4)}  alpha {alpha[n]:+.4f}  gaps to spheres {d[0]/h:+.2f} h, {d[1]/h:+.2f} h")
