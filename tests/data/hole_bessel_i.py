#!/usr/bin/env python3
"""Reference values of the exponentially scaled modified Bessel functions of the first kind of
complex argument, e^-z I0(z) and e^-z I1(z), for tests/numerics/bessel_ik.rs.

Source: mpmath (arbitrary precision, 40 significant digits), independent of boltzone's
power-series / asymptotic-series implementation. Run: python3 hole_bessel_i.py > hole_bessel_i.csv
"""
import mpmath as mp

mp.mp.dps = 40
moduli = [0.05, 0.2, 0.5, 1.0, 2.0, 3.7, 7.0, 12.0, 19.9, 20.1, 35.0, 100.0, 1000.0, 1.0e5]
args = [0.0, 0.15, 0.3, 0.49, 0.7, 0.9, 1.1]
print("# e^-z I0(z), e^-z I1(z) by mpmath at 40 digits; columns: re_z, im_z, re_i0e, im_i0e, re_i1e, im_i1e")
print("re_z,im_z,re_i0e,im_i0e,re_i1e,im_i1e")
for m in moduli:
    for a in args:
        for s in (1, -1) if a else (1,):
            z = mp.mpc(mp.mpf(m) * mp.cos(a), s * mp.mpf(m) * mp.sin(a))
            z = mp.mpc(float(z.real), float(z.imag))
            i0 = mp.exp(-z) * mp.besseli(0, z)
            i1 = mp.exp(-z) * mp.besseli(1, z)
            print(",".join(mp.nstr(v, 20) for v in (z.real, z.imag, i0.real, i0.imag, i1.real, i1.imag)))
