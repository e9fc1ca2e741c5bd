#!/usr/bin/python3
"""How well the initial level set of the two grains' neck scenes is a distance.

A Python copy of ImplicitSurfaceDistance::value (scene/solid_geometry.cc:
Newton projection onto {phi = 0}, tangential steps, and the fallback
phi / |grad phi| when the projection fails), united with the two circles'
exact distance as SolidMinusHoles does, against the exact distance to the
union's boundary (sampled densely) at 1500 random points of the unit box;
the points outside the solid are compared (inside, the union of signed
distances is not exact anyway). Prints, per implicit function, how many
points are off by more than 1e-6, the largest error, and the points off
within --near (the filter thickness) of the surface.
"""
import argparse

import numpy as np

R, SCALE = 0.2, 0.25  # grain radius, the coarse cell (the length scale)
BLEND = dict(d=0.2225, xt=0.0573914128, x0=0.06, c2=16, c4=1034.693762,
             c6=-309449.5091)
FILLET = dict(d=0.2124853, xt=0.0287142, rho=0.03125, yc=0.09125)


def blend_f(X, clamp):
    b = BLEND
    if clamp:
        X = np.minimum(abs(X), b["xt"])
    return b["x0"] + b["c2"] * X**2 + b["c4"] * X**4 + b["c6"] * X**6


def phi_blend(p, clamp):
    X, Y = p[0] - 0.5, p[1] - 0.5
    return max(abs(X) - BLEND["xt"], abs(Y) - blend_f(X, clamp))


def phi_fillet(p):
    f = FILLET
    X, Y = p[0] - 0.5, p[1] - 0.5
    return max(abs(X) - f["xt"],
               abs(Y) - f["yc"] + np.sqrt(max(f["rho"]**2 - X**2, 0)))


def grad(phi, x):
    h, g = 1e-6 * SCALE, np.zeros(2)
    for k in range(2):
        e = np.zeros(2)
        e[k] = h
        g[k] = (phi(x + e) - phi(x - e)) / (2 * h)
    return g


def project(phi, x):
    for _ in range(50):
        g = grad(phi, x)
        if np.linalg.norm(g) == 0:
            return x, False
        step = phi(x) / g.dot(g) * g
        x = x - step
        if np.linalg.norm(step) <= 1e-12 * SCALE:
            return x, True
    return x, False


def value(phi, q):
    pq = phi(q)
    if pq == 0:
        return 0.
    x, ok = project(phi, q.copy())
    if not ok:
        g = np.linalg.norm(grad(phi, q))
        return pq / g if g > 0 else pq
    for _ in range(200):
        g = grad(phi, x)
        n = g / np.linalg.norm(g)
        r = q - x
        t = r - r.dot(n) * n
        if np.linalg.norm(t) <= 1e-12 * SCALE:
            break
        factor, closer = 1., False
        while factor > 1e-6 and not closer:
            y, ok = project(phi, x + factor * t)
            if ok and np.linalg.norm(q - y) < np.linalg.norm(q - x):
                x, closer = y, True
            factor /= 2
        if not closer:
            break
    return np.sign(pq) * np.linalg.norm(q - x)


def boundary(d, xt, upper):
    X = np.linspace(-xt, xt, 4001)
    parts = [np.c_[0.5 + X, 0.5 + upper(X)], np.c_[0.5 + X, 0.5 - upper(X)]]
    th = np.linspace(0, 2 * np.pi, 40001)
    for cx in (0.5 - d, 0.5 + d):
        P = np.c_[cx + R * np.cos(th), 0.5 + R * np.sin(th)]
        parts.append(P[abs(P[:, 0] - 0.5) >= xt])
    return np.vstack(parts)


def check(name, phi, d, B, near):
    rng = np.random.default_rng(1)
    errors = []
    for q in rng.random((1500, 2)):
        circles = min(np.hypot(q[0] - 0.5 + d, q[1] - 0.5),
                      np.hypot(q[0] - 0.5 - d, q[1] - 0.5)) - R
        level_set = min(circles, value(phi, q))
        if level_set < 0:
            continue
        exact = np.min(np.hypot(B[:, 0] - q[0], B[:, 1] - q[1]))
        errors.append((abs(level_set - exact), level_set, exact, q))
    bad = [e for e in errors if e[0] > 1e-6]
    print(f"{name}: {len(bad)} of {len(errors)} points outside off by "
          f"> 1e-6, at most {max(e[0] for e in errors):.3g}")
    for e in sorted(bad, key=lambda e: e[1]):
        if e[1] < near:
            print(f"  at {e[3].round(4)}: {e[1]:.4g}, exact {e[2]:.4g}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--near", type=float, default=0.045)
    args = parser.parse_args()
    b, f = BLEND, FILLET
    B = boundary(b["d"], b["xt"], lambda X: blend_f(X, True))
    for clamp in (False, True):
        check(f"blend, f {'held beyond xt' if clamp else 'unclamped'}",
              lambda p: phi_blend(p, clamp), b["d"], B, args.near)
    B = boundary(f["d"], f["xt"],
                 lambda X: f["yc"] - np.sqrt(f["rho"]**2 - X**2))
    check("circular fillet", phi_fillet, f["d"], B, args.near)


if __name__ == "__main__":
    main()
