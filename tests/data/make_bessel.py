#!/usr/bin/env python3
"""Reference values of J0, J1 and Ji0(x) = integral of J0 over [0, x] for tests/numerics/bessel_j.rs.

Independent high-precision source: mpmath (arbitrary precision, 50 significant digits here).
Points: 400 log-spaced x in [1e-6, 1e4] plus the first 40 zeros of J0 and J1 (where only the
absolute error means anything) and a few large arguments. Each x is first rounded to the
nearest double, so the reference is J(x) at exactly the double the test passes to libm.
Ji0 uses the Struve-function identity Ji0(x) = x J0(x) + (pi x/2)[J1(x) H0(x) - J0(x) H1(x)]
(Abramowitz & Stegun 11.1.7), evaluated by mpmath.struveh.
Run: python3 tests/data/make_bessel.py > tests/data/bessel_j.csv
"""
import mpmath as mp

mp.mp.dps = 50
xs = [float(mp.mpf(10) ** (mp.mpf(-6) + 10 * mp.mpf(k) / 399)) for k in range(400)]
xs += [float(mp.besseljzero(0, k)) for k in range(1, 41)]
xs += [float(mp.besseljzero(1, k)) for k in range(1, 41)]
xs += [1e5, 1e6, 123456.789]
print("# x, J0(x), J1(x), Ji0(x) by mpmath %s at %d digits; x is the double given (17 significant digits)" % (mp.__version__, mp.mp.dps))
print("x,j0,j1,ij0")
for x in sorted(set(xs)):
    xm = mp.mpf(x)
    j0, j1 = mp.besselj(0, xm), mp.besselj(1, xm)
    ij0 = xm * j0 + mp.pi * xm / 2 * (j1 * mp.struveh(0, xm) - j0 * mp.struveh(1, xm))
    print("%.17e,%s,%s,%s" % (x, mp.nstr(j0, 20, min_fixed=-1, max_fixed=-1), mp.nstr(j1, 20, min_fixed=-1, max_fixed=-1), mp.nstr(ij0, 20, min_fixed=-1, max_fixed=-1)))
