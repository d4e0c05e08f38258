#!/usr/bin/env python3
"""Reference values of the slab's shear-load kernels (boltzone::hankel::kernel_shear) for
tests/hankel/shear_kernels.rs, derived independently of the hand derivation in the module docs.

Love's strain function phi = (a sinh(xi z) + b xi z cosh(xi z)) J0(xi r) is differentiated by sympy
(Love's formulas: sigma_z = d/dz[(2-nu) lap phi - phi_zz], tau_rz = d/dr[(1-nu) lap phi - phi_zz],
sigma_r = d/dz[nu lap phi - phi_rr], sigma_theta = d/dz[nu lap phi - phi_r/r],
2G u = -phi_rz, 2G w = 2(1-nu) lap phi - phi_zz), the two face conditions sigma_z(r, D) = 0,
tau_rz(r, D) = xi sbar J1(xi r) are solved for a and b symbolically, and every kernel is the field
divided by its Bessel factor (and by xi sbar, or by sbar for displacements), evaluated at exact
rational t = xi D, s = xi z, nu with 30 digits and printed rounded to doubles. Run: python3 shear_kernels.py > shear_kernels.csv
"""
import sympy as sp

r, z, xi, D, nu, a, b, sb = sp.symbols("r z xi D nu a b sbar", positive=True)
phi = (a * sp.sinh(xi * z) + b * xi * z * sp.cosh(xi * z)) * sp.besselj(0, xi * r)
lap = lambda f: sp.diff(f, r, 2) + sp.diff(f, r) / r + sp.diff(f, z, 2)
L = lap(phi)
sz = sp.diff((2 - nu) * L - sp.diff(phi, z, 2), z)
tau = sp.diff((1 - nu) * L - sp.diff(phi, z, 2), r)
sr = sp.diff(nu * L - sp.diff(phi, r, 2), z)
st = sp.diff(nu * L - sp.diff(phi, r) / r, z)
u2g = -sp.diff(phi, r, z)
w2g = 2 * (1 - nu) * L - sp.diff(phi, z, 2)
J0, J1 = sp.besselj(0, xi * r), sp.besselj(1, xi * r)
# face conditions (the Bessel factor divides out)
c1 = sp.simplify(sz.subs(z, D) / J0)
c2 = sp.simplify(tau.subs(z, D) / J1 - xi * sb)
sol = sp.solve([c1, c2], [a, b], dict=True)[0]
print("# shear-load kernels by sympy from Love's function; columns: t, s, nu, L_z, L_tau, L_r, L_m, L_n, L_w")
print("t,s,nu,lz,ltau,lr,lm,ln,lw")
# sigma_r = xi sbar [L_r J0 - L_m J1/(xi r)], sigma_theta = xi sbar [L_n J0 + L_m J1/(xi r)]:
# split sigma_r into its J0 and J1 parts by evaluating the coefficient structure at two radii is
# awkward; instead use u: 2G u = sbar L_m J1 gives L_m, then L_r from sigma_r + L_m J1/(xi r).
pts = [(sp.Rational(1, 100), sp.Rational(1, 200)), (sp.Rational(1, 2), sp.Rational(1, 3)), (1, 0), (1, 1),
       (3, 2), (sp.Rational(7, 2), sp.Rational(7, 2)), (8, 5), (12, 11)]
for t, s in pts:
    for nuv in (sp.Rational(3, 10), sp.Rational(1, 2), 0):
        # choose D = 1, xi = t, z = s / t, r = 1 (any r: the Bessel factors divide out)
        subs = {D: 1, xi: t, z: sp.Rational(s) / t, nu: nuv, sb: 1, r: sp.Rational(7, 10)}
        f = lambda e: e.subs(sol).subs(subs)
        j0 = sp.besselj(0, t * sp.Rational(7, 10))
        j1 = sp.besselj(1, t * sp.Rational(7, 10))
        xr = t * sp.Rational(7, 10)
        lz = f(sz) / (t * j0)
        lt = f(tau) / (t * j1)
        lm = f(u2g) / j1
        lr = (f(sr) / t + lm * j1 / xr) / j0
        ln = (f(st) / t - lm * j1 / xr) / j0
        lw = f(w2g) / j0
        vals = [sp.N(v, 30) for v in (lz, lt, lr, lm, ln, lw)]
        print(",".join(format(float(v), ".17e") for v in [t, s, nuv] + vals))
