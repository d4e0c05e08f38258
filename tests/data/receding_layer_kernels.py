#!/usr/bin/env python3
"""Reference values of the layer kernels M_q, M_p of src/hankel/receding/layer.rs, computed
independently of that module's symmetric/antisymmetric split: the general four-constant
Love-function solution of a layer 0 <= z <= D (Timoshenko & Goodier, sec. 130-131),
    phi = (A + B xi z) e^(-xi z) + (C + E xi (D - z)) e^(-xi (D - z)),
with sigma_z = d/dz[(2-nu) lap - d2/dz2] phi, tau_rz ~ d/dr[(1-nu) lap - d2/dz2] phi,
2G w = [2(1-nu) lap - d2/dz2] phi, solved in exact rational arithmetic (sympy) for
sigma_z(0) = -q, sigma_z(D) = -p, tau_rz(0) = tau_rz(D) = 0, then
    M_q = xi * 2G w(0)|_{q=1,p=0} / (2(1-nu)),  M_p = -xi * 2G w(0)|_{q=0,p=1} / (2(1-nu)).
Run: python3 tests/data/receding_layer_kernels.py > tests/data/receding_layer_kernels.csv
(sympy 1.14; about a minute)."""
import sympy as sp

z = sp.symbols('z')
A, B, C, E = sp.symbols('A B C E')


def bottom_w(xi, D, nu, p, q):
    G = (A + B * xi * z) * sp.exp(-xi * z) + (C + E * xi * (D - z)) * sp.exp(-xi * (D - z))
    d = lambda f, n=1: sp.diff(f, z, n)
    lap = d(G, 2) - xi**2 * G
    S = d((2 - nu) * lap - d(G, 2))
    T = (1 - nu) * lap - d(G, 2)
    W = 2 * (1 - nu) * lap - d(G, 2)
    sol = sp.solve([S.subs(z, 0) + q, T.subs(z, 0), S.subs(z, D) + p, T.subs(z, D)], [A, B, C, E])
    return W.subs(z, 0).subs(sol)


print("# layer kernels by the general Love solution (tests/data/receding_layer_kernels.py)")
print("# x = xi*D, nu, M_q, M_p (30 significant digits)")
print("x,nu,m_q,m_p")
xs = [sp.Rational(1, 1000), sp.Rational(1, 100), sp.Rational(1, 10), sp.Rational(1, 2), 1, 2, 5, 10, 20, 40]
for nu in [sp.Rational(3, 10), sp.Integer(0)]:
    for x in xs:
        x = sp.Integer(x) if not isinstance(x, sp.Rational) else x
        wq = bottom_w(x, sp.Integer(1), nu, 0, 1)
        wp = bottom_w(x, sp.Integer(1), nu, 1, 0)
        mq = sp.N(wq * x / (2 * (1 - nu)), 30)
        mp = sp.N(-wp * x / (2 * (1 - nu)), 30)
        print(f"{sp.N(x, 17)},{sp.N(nu, 3)},{mq},{mp}")
