#!/usr/bin/env python3
"""Reference values of the exponentially scaled modified Bessel functions of complex argument,
e^z K0(z) and e^z K1(z), for tests/numerics/bessel_ik.rs.

Source: mpmath (arbitrary precision, 40 significant digits), independent of boltzone's
trapezoid-rule / asymptotic-series implementation. Run: python3 hole_bessel_k.py > hole_bessel_k.csv
"""
import mpmath as mp

mp.mp.dps = 40
moduli = [0.05, 0.2, 0.5, 1.0, 2.0, 3.7, 7.0, 12.0, 19.9, 20.1, 35.0, 100.0, 1000.0, 1.0e5]
args = [0.0, 0.15, 0.3, 0.49, 0.7, 0.9, 1.1]
print("# e^z K0(z), e^z K1(z) by mpmath at 40 digits; columns: re_z, im_z, re_k0e, im_k0e, re_k1e, im_k1e")
print("re_z,im_z,re_k0e,im_k0e,re_k1e,im_k1e")
for m in moduli:
    for a in args:
        for s in (1, -1) if a else (1,):
            z = mp.mpc(mp.mpf(m) * mp.cos(a), s * mp.mpf(m) * mp.sin(a))
            # Round z to a double first so the reference is for the exact f64 argument.
            z = mp.mpc(float(z.real), float(z.imag))
            k0 = mp.exp(z) * mp.besselk(0, z)
            k1 = mp.exp(z) * mp.besselk(1, z)
            print(",".join(mp.nstr(v, 20) for v in (z.real, z.imag, k0.real, k0.imag, k1.real, k1.imag)))
