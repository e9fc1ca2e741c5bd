#!/usr/bin/python3
"""The curvature-continuous neck of two_grains_blended_volume_diffusion_2d.prm.

Two circles of radius R, centres (+-d, 0) (relative to the neck's middle),
are joined for |X| < xt by the even polynomial
    f(X) = x0 + c2 X^2 + c4 X^4 + c6 X^6
(the neck's upper surface Y = f(X), mirrored below). x0 sets the neck's
half-width, c2 = kappa0 / 2 its curvature in the middle; c4, c6 and the
join xt are fixed by f = g, f' = g', f'' = g'' at X = xt, g the circle's
upper arc: the surface and its curvature are continuous at the join.
Prints the constants of the parameter file and checks that the curvature
falls monotonically from the middle to the join (no extra inflection) and
that the circle does not poke out above the blend inside the join.
With --csv FILE it writes the curvature along the upper-right quarter of
the surface, this start and the circular fillet's
(two_grains_filleted_volume_diffusion_2d.prm), against X.
"""
import argparse

import numpy as np
from scipy.optimize import brentq

R, x0, d, kappa0 = 0.2, 0.06, 0.2225, 32.0


def circle(X):
    g = np.sqrt(R**2 - (X - d)**2)
    return g, -(X - d) / g, -R**2 / g**3


def coefficients(xt):
    """c4, c6 from the slope and the curvature at the join."""
    _, g1, g2 = circle(xt)
    c2 = kappa0 / 2
    A = np.array([[4 * xt**3, 6 * xt**5], [12 * xt**2, 30 * xt**4]])
    c4, c6 = np.linalg.solve(A, [g1 - 2 * c2 * xt, g2 - 2 * c2])
    return c2, c4, c6


def blend(X, xt):
    c2, c4, c6 = coefficients(xt)
    f = x0 + c2 * X**2 + c4 * X**4 + c6 * X**6
    f1 = 2 * c2 * X + 4 * c4 * X**3 + 6 * c6 * X**5
    f2 = 2 * c2 + 12 * c4 * X**2 + 30 * c6 * X**4
    return f, f1, f2


def curvature(f1, f2):
    # of the graph Y = f(X), positive where the solid below it is concave
    return f2 / (1 + f1**2)**1.5


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv")
    args = parser.parse_args()
    # the join where the value matches too
    xt = brentq(lambda xt: blend(xt, xt)[0] - circle(xt)[0],
                d - R + 1e-6, 0.1)
    c2, c4, c6 = coefficients(xt)
    X = np.linspace(0, xt, 2001)
    f, f1, f2 = blend(X, xt)
    k = curvature(f1, f2)
    inside = X > d - R
    assert np.all(np.diff(k) < 0), "the curvature is not monotone"
    assert np.all(f[inside] >= circle(X[inside])[0] - 1e-12)
    _, g1, g2 = circle(xt)
    print(f"d = {d}, particles at 0.5 -+ d = {0.5 - d:.7g}, {0.5 + d:.7g}")
    print(f"xt = {xt:.10g}, x0 = {x0}, c2 = {c2:.10g}, c4 = {c4:.10g}, "
          f"c6 = {c6:.10g}")
    print(f"curvature: middle {k[0]:.6g}, join {k[-1]:.6g} "
          f"(circle {curvature(g1, g2):.6g})")
    if args.csv:
        rows = []
        Xc = np.linspace(xt, d, 400)[1:]
        g, g1, g2 = circle(Xc)
        for Xi, fi, ki in zip(X[::10], f[::10], k[::10]):
            rows.append(("blend", Xi, fi, ki))
        for Xi, gi, ki in zip(Xc, g, curvature(g1, g2)):
            rows.append(("blend", Xi, gi, ki))
        # the circular fillet: rounding radius rho, centres 2 d0 apart
        rho, d0, xt0, yc = 0.03125, 0.2124853, 0.0287142, 0.09125
        Xf = np.linspace(0, xt0, 101)
        for Xi in Xf:
            rows.append(("fillet", Xi, yc - np.sqrt(rho**2 - Xi**2),
                         1 / rho))
        Xc = np.linspace(xt0, d0, 400)[1:]
        for Xi in Xc:
            rows.append(("fillet", Xi, np.sqrt(R**2 - (Xi - d0)**2),
                         -1 / R))
        with open(args.csv, "w") as out:
            out.write("start,X,Y,curvature\n")
            for r in rows:
                out.write(f"{r[0]},{r[1]:.8g},{r[2]:.8g},{r[3]:.8g}\n")


if __name__ == "__main__":
    main()
