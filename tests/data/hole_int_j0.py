#!/usr/bin/env python3
"""Reference values of F(x) = ∫_0^x J0(t) dt for tests/hole_transform.rs.

Source: mpmath quadosc / quad at 40 digits (independent of boltzone's Chebyshev table and
Struve asymptotics). Run: python3 hole_int_j0.py > hole_int_j0.csv
"""
import mpmath as mp

mp.mp.dps = 40
xs = [0.0, 1e-3, 0.1, 0.5, 1.0, 2.0, 3.3, 5.0, 7.7, 10.0, 15.0, 19.99, 24.0, 31.4, 39.9, 40.1, 55.0,
      100.0, 333.3, 1000.0, 1e4, 1e5]
print("# F(x) = integral of J0 from 0 to x, mpmath 40 digits (x J0 + (pi x/2)(J1 H0 - J0 H1), DLMF 10.22.2)")
print("x,f")
for x in xs:
    x = mp.mpf(x)
    f = x * mp.besselj(0, x) + mp.pi * x / 2 * (mp.besselj(1, x) * mp.struveh(0, x) - mp.besselj(0, x) * mp.struveh(1, x)) if x > 0 else mp.mpf(0)
    # cross-check by direct quadrature for moderate x
    if 0 < x <= 100:
        g = mp.quad(lambda t: mp.besselj(0, t), mp.linspace(0, x, int(x) + 2))
        assert abs(f - g) < mp.mpf(10) ** -30, (x, f, g)
    print(f"{mp.nstr(x, 20)},{mp.nstr(f, 20)}")
