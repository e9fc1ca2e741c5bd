#!/usr/bin/env python3
"""The closing law of a concentric hole in a viscous cylinder (and a sphere).

doc/numerics.md, "Hollow cylinder: the closing law from the dissipation
balance". A Newtonian annulus a < r < b (viscosity eta, surface tension
gamma on both circles, per unit length), no inertia, the atmosphere's
viscosity and pressure neglected. Incompressible radial flow u = C / r (2D)
or C / r^2 (3D, a spherical shell). The free energy gamma * (surface) falls
at the rate the flow dissipates, dE/dt = -Phi, which fixes C. The script
checks the flow, solves the balance, compares with the stress balance of
doc/numerics.md ("Hollow cylinder: exact Stokes solution"), integrates the
closing time, and evaluates the small-pore law dr/dt = -gamma / (2 eta) of
the small-pore rule (SmallPoreClosure) against the exact annulus below a
radius r_on: the time the law adds, per start radius a0 / h and r_on / h.

Run: python3 scripts/hollow_cylinder_closing.py (sympy).
"""
import sympy as sp

r, a, b, eta, gamma, C, t = sp.symbols("r a b eta gamma C t", positive=True)
C = sp.Symbol("C")

# --- 2D: the annulus --------------------------------------------------------
u = C / r
assert sp.simplify(sp.diff(r * u, r) / r) == 0  # div v = 0
e_rr, e_tt = sp.diff(u, r), u / r  # strain rates; e_rt = 0
Phi = sp.integrate(2 * eta * (e_rr**2 + e_tt**2) * 2 * sp.pi * r, (r, a, b))
E_dot = 2 * sp.pi * gamma * (C / a + C / b)  # d/dt of gamma 2 pi (a + b)
C_2d = [s for s in sp.solve(sp.Eq(E_dot, -Phi), C) if s != 0][0]
C_2d = sp.factor(C_2d)
print("2D dissipation balance: C =", C_2d)
# Stress balance: sigma_rr = -p - 2 eta C / r^2, sigma_rr(b) = -gamma / b,
# sigma_rr(a) = +gamma / a.
p = sp.Symbol("p")
stress = sp.solve([sp.Eq(-p - 2 * eta * C / b**2, -gamma / b),
                   sp.Eq(-p - 2 * eta * C / a**2, gamma / a)], [p, C], dict=True)[0]
assert sp.simplify(stress[C] - C_2d) == 0
print("   stress balance agrees; solid pressure p =", sp.factor(stress[p]))
a_dot, b_dot = C_2d / a, C_2d / b
print("   da/dt =", sp.factor(a_dot), "; d(b - a)/dt =", sp.simplify(b_dot - a_dot),
      "; d(b^2 - a^2)/dt =", sp.simplify(2 * b * b_dot - 2 * a * a_dot))
# The small-pore form: da/dt = -(gamma + p a) / (2 eta) with that p.
assert sp.simplify(a_dot + (gamma + stress[p] * a) / (2 * eta)) == 0
print("   da/dt = -(gamma + p a) / (2 eta): checked")

# Closing time: w = b - a = w0 + gamma t / (2 eta), k^2 = b^2 - a^2 fixed,
# a = (k^2 / w - w) / 2 = 0 at w = k.
a0, b0 = sp.symbols("a0 b0", positive=True)
k = sp.sqrt(b0**2 - a0**2)
t_c = 2 * eta / gamma * (k - (b0 - a0))
w = b0 - a0 + gamma * t / (2 * eta)
a_t = (k**2 / w - w) / 2
b_t = (k**2 / w + w) / 2
assert sp.simplify(sp.diff(a_t, t) - a_dot.subs({a: a_t, b: b_t})) == 0
print("   a(t) = (k^2 / w - w) / 2 solves da/dt; t_c =", t_c)
values = {a0: sp.Rational(15, 100), b0: sp.Rational(3, 10), eta: 1, gamma: 1}
print("   hollow_cylinder_2d.prm (a0 = 0.15, b0 = 0.3, gamma = eta = 1): t_c =",
      sp.N(t_c.subs(values), 6))

# --- 3D: a spherical shell --------------------------------------------------
u3 = C / r**2
assert sp.simplify(sp.diff(r**2 * u3, r) / r**2) == 0
e_rr, e_tt = sp.diff(u3, r), u3 / r  # e_tt = e_pp
Phi3 = sp.integrate(2 * eta * (e_rr**2 + 2 * e_tt**2) * 4 * sp.pi * r**2,
                    (r, a, b))
E3_dot = 8 * sp.pi * gamma * (a * C / a**2 + b * C / b**2)
C_3d = sp.factor([s for s in sp.solve(sp.Eq(E3_dot, -Phi3), C) if s != 0][0])
print("3D dissipation balance: C =", C_3d)
print("   da/dt as b -> oo:", sp.limit(C_3d / a**2, b, sp.oo),
      "(the 2D limit:", sp.limit(a_dot, b, sp.oo), ")")

# --- The small-pore rule against the annulus --------------------------------
# Below r_on the rule closes the pore at gamma / (2 eta): it adds
# 2 eta r_on / gamma - (exact time from r_on to 0) to the closing time
# (the neglected p a term).
print("\nthe rule's added closing time (fraction of t_c), b0 = 2 a0:")
print("   a0/h   r_on/h   added / t_c")
for a0_over_h in (4, 8, 16):
    for r_on_over_h in (1, 1.5, 2):
        a_on = sp.Rational(15, 100) * sp.nsimplify(r_on_over_h) / a0_over_h
        kk = k.subs(values)
        w_on = -a_on + sp.sqrt(a_on**2 + kk**2)  # w at a = a_on
        exact_left = 2 * (kk - w_on)  # (2 eta / gamma)(k - w_on)
        added = 2 * a_on - exact_left
        print(f"   {a0_over_h:4d}   {r_on_over_h:6.1f}   "
              f"{float(added / t_c.subs(values)):+.4f}")
