#!/usr/bin/env python3
"""Decay rates of small shape modes of a viscous cylinder and sphere.

A Newtonian body (viscosity eta, surface tension gamma, radius R) in an
atmosphere of negligible viscosity, its boundary r = R + zeta perturbed by
one mode (cylinder: zeta ~ cos(n theta); sphere: zeta ~ P_l(cos theta)).
Inside, the Stokes flow regular at the centre is Lamb's solution of degree
n built from two solid harmonics, the pressure p_n and a potential Phi_n:

    u = grad Phi_n + ((n + 3) r^2 grad p_n - 2 n x p_n)
                     / (2 eta (n + 1) (2 n + 3))          (sphere, 3D)

and in 2D the same with the 2D constants (found here by requiring
eta lap u = grad p, div u = 0). Linearised at r = R: no tangential
stress, sigma_rr = -gamma kappa with kappa = kappa_0 + c_n zeta / R^2
(c_n = n^2 - 1 for the cylinder, (l - 1)(l + 2) for the sphere), and
R d(zeta)/dt = u_r(R). The script checks the Stokes equations, solves the
two boundary conditions and prints s_n (zeta ~ exp(-s_n t)) in units of
gamma / (eta R), next to the closed forms it confirms: cylinder
n / 2 (doc/numerics.md), sphere l (l + 2) (2 l + 1) / (2 (2 l^2 + 4 l + 3))
(20/19 for l = 2: the inviscid-matrix limit of the drop relaxation time
(2 lam + 3)(19 lam + 16) eta_m R / (40 (lam + 1) gamma) -> 19 eta R /
(20 gamma), Rallison 1984). Mode n = 1 is a translation (the derivation
divides by the curvature factor c_n = 0 there).

With an atmosphere of viscosity lam eta (exterior stream function
(C r^-n + D r^(2-n)) sin(n theta), velocity and shear stress continuous,
the normal stress jumping by the Laplace term) the cylinder's rate is
n gamma / (2 eta R (1 + lam)) for every n (cylinder_rate_with_atmosphere):
the scenes' lam = 1e-3 lowers the exact rate by 0.1 %.
"""
import sympy as sp

eta, gamma, R, delta = sp.symbols("eta gamma R delta", positive=True)
A, B = sp.symbols("A B")


def rate(dim, n):
    if dim == 2:
        x, y = sp.symbols("x y", real=True)
        X = [x, y]
        r2 = x**2 + y**2
        harmonic = sp.re(sp.expand((x + sp.I * y) ** n))  # r^n cos(n theta)
        # u = grad Phi + a r^2 grad p + b x p with constants a, b fixed by
        # Stokes (found below).
    else:
        x, y, z = sp.symbols("x y z", real=True)
        X = [x, y, z]
        r2 = x**2 + y**2 + z**2
        rr = sp.sqrt(r2)
        harmonic = sp.simplify(sp.expand(rr**n * sp.legendre(n, z / rr)))
    a, b = sp.symbols("a b")
    p = B * harmonic
    Phi = A * harmonic
    u = [sp.diff(Phi, xi) + a * r2 * sp.diff(p, xi) + b * xi * p for xi in X]
    div = sp.expand(sum(sp.diff(u[i], X[i]) for i in range(dim)))
    lap = [sp.expand(eta * sum(sp.diff(u[i], xj, 2) for xj in X) -
                     sp.diff(p, X[i])) for i in range(dim)]
    # Coefficients of the polynomials must vanish.
    eqs = set()
    for e in [div] + lap:
        eqs |= set(sp.Poly(e, *X).coeffs())
    sol = sp.solve(list(eqs), [a, b], dict=True)[0]
    u = [sp.simplify(ui.subs(sol)) for ui in u]
    grad_u = sp.Matrix(dim, dim, lambda i, j: sp.diff(u[i], X[j]))
    sigma = -p * sp.eye(dim) + eta * (grad_u + grad_u.T)
    # Evaluate on the ray theta = 0 (along x for 2D, along z for 3D) for
    # normal quantities, and at a generic angle for the tangential one.
    if dim == 2:
        t = sp.symbols("t")
        point = {x: R * sp.cos(t), y: R * sp.sin(t)}
        er = sp.Matrix([sp.cos(t), sp.sin(t)])
        et = sp.Matrix([-sp.sin(t), sp.cos(t)])
        shape = sp.cos(n * t)
        c = n**2 - 1
    else:
        t = sp.symbols("t")
        point = {x: R * sp.sin(t), y: 0, z: R * sp.cos(t)}
        er = sp.Matrix([sp.sin(t), 0, sp.cos(t)])
        et = sp.Matrix([sp.cos(t), 0, -sp.sin(t)])
        shape = sp.legendre(n, sp.cos(t))
        c = (n - 1) * (n + 2)
    S = sigma.subs(point)
    ur = (sp.Matrix(u).subs(point).T * er)[0]
    srt = sp.simplify((et.T * S * er)[0])
    srr = sp.simplify((er.T * S * er)[0])
    # sigma_rt = 0 for all t; sigma_rr = -gamma c delta R / R^2 * shape
    # (zeta = delta R shape; the constant part balances the base pressure).
    t0 = sp.Rational(3, 10)
    eqs = [sp.simplify(srt.subs(t, t0)),
           sp.simplify(srr.subs(t, t0) + gamma * c * delta / R *
                       shape.subs(t, t0))]
    sol = sp.solve(eqs, [A, B], dict=True)[0]
    # R d(delta)/dt shape = u_r => s = -u_r / (R delta shape)
    s = sp.simplify(-(ur.subs(sol) / (R * delta * shape)).subs(t, t0))
    return sp.simplify(s * eta * R / gamma)


def cylinder_rate_with_atmosphere(n):
    """s_n eta R / gamma of a cylinder in an atmosphere of viscosity lam eta,
    in polar coordinates (u_r = psi_theta / r, u_theta = -psi_r)."""
    r, th = sp.symbols("r theta", positive=True)
    lam = sp.symbols("lam", positive=True)
    C, D = sp.symbols("C D")

    def fields(psi, visc):
        ur = sp.diff(psi, th) / r
        ut = -sp.diff(psi, r)
        lap = lambda f: (sp.diff(r * sp.diff(f, r), r) / r +
                         sp.diff(f, th, 2) / r**2)
        # theta-momentum: (1/r) dp/dtheta = visc (lap u)_theta, p ~ cos.
        lap_t = lap(ut) - ut / r**2 + 2 / r**2 * sp.diff(ur, th)
        p = sp.simplify(r * visc * lap_t / (-n * sp.sin(n * th))) * \
            sp.cos(n * th)
        srr = -p + 2 * visc * sp.diff(ur, r)
        srt = visc * (r * sp.diff(ut / r, r) + sp.diff(ur, th) / r)
        return ur, ut, srr, srt

    inner = fields((A * r**n + B * r**(n + 2)) * sp.sin(n * th), eta)
    outer = fields((C * r**(-n) + D * r**(2 - n)) * sp.sin(n * th), lam * eta)
    t0 = sp.Rational(3, 10)
    at = lambda e: sp.simplify(e.subs({r: R, th: t0}))
    eqs = [at(inner[0] - outer[0]), at(inner[1] - outer[1]),
           at(inner[3] - outer[3]),
           at(inner[2] - outer[2] +
              gamma * (n**2 - 1) * delta / R * sp.cos(n * th))]
    sol = sp.solve(eqs, [A, B, C, D], dict=True)[0]
    s = -at(inner[0].subs(sol)) / (R * delta * sp.cos(n * t0))
    return sp.factor(sp.simplify(s * eta * R / gamma))


if __name__ == "__main__":
    print("mode, body, s_n eta R / gamma, closed form")
    for n in (2, 3, 4):
        s = rate(2, n)
        print(n, "cylinder", float(s), "closed form:", sp.Rational(n, 2))
    for l in (2, 3, 4):
        s = rate(3, l)
        closed = sp.Rational(l * (l + 2) * (2 * l + 1),
                             2 * (2 * l * l + 4 * l + 3))
        print(l, "sphere", float(s), "closed form:", closed)
    for n in (2, 3, 4):
        print(n, "cylinder in an atmosphere of viscosity lam eta:",
              cylinder_rate_with_atmosphere(n))
