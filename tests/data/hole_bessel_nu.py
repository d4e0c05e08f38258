#!/usr/bin/env python3
"""Reference values of the normalised Bessel function of complex order
Lambda_nu(x) = Gamma(nu+1) (x/2)^(-nu) J_nu(x) = 0F1(; nu+1; -x^2/4) and of ln Gamma(z), for
tests/hankel/hole_corner.rs.

Source: mpmath (hyp0f1, besselj, loggamma at 40 digits), independent of boltzone's series /
Miller / Hankel-expansion implementation. The orders are the corner exponents lambda_1, lambda_2,
lambda_4 of the 90-degree free-free wedge and lambda + 1 (the shear load's order), computed here
by mpmath's findroot. Run: python3 hole_bessel_nu.py > hole_bessel_nu.csv
"""
import mpmath as mp

mp.mp.dps = 40


def root(sign, guess):
    # sin(lambda pi / 2) = sign * lambda
    return mp.findroot(lambda l: mp.sin(l * mp.pi / 2) - sign * l, mp.mpc(*guess))


lam = [root(-1, (2.74, 1.12)), root(1, (4.81, 1.46)), root(-1, (6.85, 1.68)), root(1, (8.87, 1.84))]
print("# kind,re_nu,im_nu,x,re,im  (kind L: Lambda_nu(x); kind G: Gamma(nu) with x unused; kind R: corner root)")
print("kind,re_nu,im_nu,x,re,im")
for l in lam:
    print(",".join(["R"] + [mp.nstr(v, 20) for v in (l.real, l.imag, 0, 0, 0)]))
orders = [lam[0], lam[0] + 1, lam[1], lam[1] + 1, lam[3] + 1, mp.mpc(0.5, 0)]
xs = [0, 0.37, 1.9, 2.1, 3.3, 4.5, 6.6, 9.0, 12.5, 17.3, 20.0, 24.9, 25.1, 30.0, 33.9, 34.3, 40.0, 71.0, 99.0,
      101.0, 350.0, 1.0e4, 1.0e6]
for nu in orders:
    nu = mp.mpc(float(nu.real), float(nu.imag))
    for x in xs:
        v = mp.hyp0f1(nu + 1, -mp.mpf(x) ** 2 / 4)
        print(",".join(["L"] + [mp.nstr(t, 20) for t in (nu.real, nu.imag, x, v.real, v.imag)]))
for z in [mp.mpc(0.3, 0.2), mp.mpc(2.7395934, 1.1190245), mp.mpc(-0.5, 0), mp.mpc(-1.7395934, -1.1190245),
          mp.mpc(12.3, -4.0), mp.mpc(40.0, 3.0)]:
    v = mp.loggamma(z)
    # compare exp(ln Gamma): print Gamma itself
    g = mp.gamma(z)
    print(",".join(["G"] + [mp.nstr(t, 20) for t in (z.real, z.imag, 0, g.real, g.imag)]))
# kind E: generalised exponential integral E_p(w) = w^(p-1) Gamma(1-p, w) (mpmath expint), with
# p in the re_nu, im_nu columns and w = x + i*(value in the re column of a preceding W row)
for p in [mp.mpc(2.7395934, 1.1190245), mp.mpc(6.7395934, 1.1190245), mp.mpc(21.7395934, 1.1190245)]:
    for w in [mp.mpc(0.3, 0), mp.mpc(0.9, -0.2), mp.mpc(4.0, 0), mp.mpc(0, 30.0), mp.mpc(0, -30.0), mp.mpc(0.05, 70.0),
              mp.mpc(25.0, -3.0), mp.mpc(2.0, 12.0)]:
        v = mp.expint(p, w)
        print(",".join(["W"] + [mp.nstr(t, 20) for t in (w.real, w.imag, 0, 0, 0)]))
        print(",".join(["E"] + [mp.nstr(t, 20) for t in (p.real, p.imag, 0, v.real, v.imag)]))
