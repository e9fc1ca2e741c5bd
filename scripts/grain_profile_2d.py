#!/usr/bin/python3
"""The surface of one grain of a settled 2D pair (grains_equilibrium_2d.prm)
against the circle fitted to its far part, from the run's last XDMF/HDF5
field file: where the shape departs from a circle, and by how much.

usage: grain_profile_2d.py RUN_DIR --kernel L [--plane X] [--axis Y]
                           [--window W] [--csv OUT.csv]

The grain boundary's plane is x = X (default 0.5), the line of centres y =
Y (default 0.5); the grain at x > X is read. The interface is alpha = 0
on the cells' edges (linear between the nodes). As the application's fit
(source/analysis/grain_measures.cc) the far circle is fitted (Kasa) to the
points beyond 1.5 L from the plane (L the triple line's kernel
half-width, Deposition width x h_min) and at least half the neck's
radius from the line of centres. Printed:
- the far circle: radius R_f, its centre's distance from the plane (d / 2)
  and the angle 2 acos(d / 2 R_f) at which it meets the plane;
- the curvature along the grain: circles fitted to windows of W degrees
  (default 12) of the polar angle about the far centre, and the nodal
  curvature of the kappa system (surface_diffusion_curvature) at the
  interface, both against 1 / R_f, band by band from the pole;
- the distance r - R_f of the interface from the far circle in bands of
  zeta, the distance from the plane (a groove near the triple line shows
  as r < R_f at small zeta);
- the area between the far circle and the interface from the points
  nearest the plane to zeta = 1.5 L (the solid the far circle counts and
  the shape does not), per triple line, and where the far circle meets
  the plane (against the rays' a of grain_boundaries.csv).
OUT.csv: per interface point zeta, rho, the polar angle about the far
centre (degrees from the line of centres), r - R_f and the nodal
curvature.
"""
import argparse
import math
import os
import re

import h5py
import numpy as np

parser = argparse.ArgumentParser(usage=__doc__)
parser.add_argument("run")
parser.add_argument("--kernel", type=float, required=True)
parser.add_argument("--plane", type=float, default=0.5)
parser.add_argument("--axis", type=float, default=0.5)
parser.add_argument("--window", type=float, default=12.0)
parser.add_argument("--csv")
args = parser.parse_args()

xdmf = open(os.path.join(args.run, "fields.xdmf")).read()
name = re.findall(r"(fields_\d+\.h5):/nodes", xdmf)[-1]
time = re.findall(r'<Time Value="([^"]+)"/>', xdmf)[-1]
f = h5py.File(os.path.join(args.run, name), "r")
nodes = np.asarray(f["nodes"])[:, :2]
alpha = np.asarray(f["alpha"])[:, 0]
kappa = np.asarray(f["surface_diffusion_curvature"])[:, 0]
cells = np.asarray(f["cells"])

# Zero crossings of alpha on every cell edge (two vertices that differ in
# one coordinate; the diagonals differ in both).
points, curvature = [], []
for cell in cells:
    for m in range(4):
        for n in range(m + 1, 4):
            p, q = cell[m], cell[n]
            delta = np.abs(nodes[p] - nodes[q]) > 1e-12
            if delta.sum() != 1 or (alpha[p] < 0) == (alpha[q] < 0):
                continue
            s = alpha[p] / (alpha[p] - alpha[q])
            points.append(nodes[p] + s * (nodes[q] - nodes[p]))
            curvature.append(kappa[p] + s * (kappa[q] - kappa[p]))
points = np.unique(np.round(np.array(points), 12), axis=0, return_index=True)
curvature = np.array(curvature)[points[1]]
points = points[0]
zeta = points[:, 0] - args.plane
rho = np.abs(points[:, 1] - args.axis)
grain = zeta > 0
zeta, rho, curvature = zeta[grain], rho[grain], curvature[grain]

# The neck's radius: the interface's rho nearest the plane.
neck = rho[np.argmin(zeta)]
inner = 1.5 * args.kernel


def kasa(z, r):
    """Algebraic circle fit: (z_c, r_c, R)."""
    matrix = np.column_stack([z, r, np.ones_like(z)])
    b = z ** 2 + r ** 2
    c = np.linalg.lstsq(matrix, b, rcond=None)[0]
    zc, rc = c[0] / 2, c[1] / 2
    return zc, rc, math.sqrt(c[2] + zc ** 2 + rc ** 2)


# The far circle, free in (zeta, rho) as the application's.
far = (zeta > inner) & (rho > neck / 2)
zc, rc, radius = kasa(zeta[far], rho[far])
angle = 2 * math.degrees(math.acos(min(1, zc / radius)))
print("t = %s (%s), %d interface points on the grain, neck rho %.6g" %
      (time, name, len(zeta), neck))
print("far circle: R_f %.6g, centre %.6g from the plane (d = %.6g) and "
      "%.2g from the line of centres, meets the plane at %.3f degrees" %
      (radius, zc, 2 * zc, rc, angle))

# Polar angle about the far centre, from the line of centres pointing away
# from the plane (0 at the far pole, 180 - psi/2 at the plane).
theta = np.degrees(np.arctan2(rho - rc, zeta - zc))
distance = np.hypot(zeta - zc, rho - rc) - radius
order = np.argsort(theta)
theta, distance, zeta_s, rho_s, curvature_s = (theta[order], distance[order],
                                               zeta[order], rho[order],
                                               curvature[order])
theta_plane = math.degrees(math.atan2(neck - rc, -zc))
print("angle about the far centre: 0 at the pole, %.1f at the neck" %
      theta_plane)
print("band (degrees)  points  local R / R_f - 1  nodal kappa R_f - 1  "
      "(r - R_f) / h_min mean")
h_min = args.kernel / 6
edges = np.arange(0, theta_plane + args.window, args.window)
for low, high in zip(edges[:-1], edges[1:]):
    inside = (theta >= low) & (theta < high)
    if inside.sum() < 4:
        continue
    _, _, local = kasa(zeta_s[inside], rho_s[inside])
    print("%5.1f-%5.1f  %6d  %+9.4f  %+9.4f  %+8.4f" %
          (low, min(high, theta_plane), inside.sum(), local / radius - 1,
           np.mean(curvature_s[inside]) * radius - 1,
           np.mean(distance[inside]) / h_min))

print("zeta band (in L)  points  (r - R_f) / h_min mean, min")
for low, high in ((0, 0.25), (0.25, 0.5), (0.5, 1), (1, 1.5), (1.5, 2),
                  (2, 3), (3, 5)):
    inside = (zeta >= low * args.kernel) & (zeta < high * args.kernel) & \
        (rho > neck / 2)
    if inside.any():
        r = (np.hypot(zeta[inside] - zc, rho[inside] - rc) - radius) / h_min
        print("%4.2f-%4.2f  %6d  %+8.4f %+8.4f" %
              (low, high, inside.sum(), r.mean(), r.min()))

# The area between the far circle and the interface over the points
# nearest the plane to zeta = 1.5 L on one side of the line of centres
# (one triple line): the far circle's rho_f(zeta) less the interface's,
# integrated in zeta (positive: the far circle holds solid the shape
# does not). The points on the plane itself are the rays' a (the
# application's radius column), not read here.
near = (zeta < inner) & (rho > neck / 2)
z = np.sort(zeta[near])
r = rho[near][np.argsort(zeta[near])]
grid = np.linspace(z[0], inner, 200)
rho_f = rc + np.sqrt(np.maximum(radius ** 2 - (grid - zc) ** 2, 0))
deficit = np.trapz(rho_f - np.interp(grid, z, r), grid)
print("area between the far circle and the interface at %.3g L < zeta < "
      "1.5 L, per triple line: %.4g (%.4g h_min^2); the far circle meets "
      "the plane at rho = %.6g" % (z[0] / args.kernel, deficit,
                                   deficit / h_min ** 2,
                                   rc + math.sqrt(radius ** 2 - zc ** 2)))

if args.csv:
    with open(args.csv, "w") as out:
        out.write("zeta,rho,theta_degrees,distance_from_far_circle,"
                  "nodal_curvature\n")
        for row in zip(zeta_s, rho_s, theta, distance, curvature_s):
            out.write(",".join("%.8g" % v for v in row) + "\n")
