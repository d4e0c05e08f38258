//! The slab's shear-load kernels (boltzone::hankel::kernel_shear): against an independent
//! symbolic derivation (sympy, tests/data/shear_kernels.py), the face conditions, the face
//! remainders, the half-space limits, and equilibrium and Hooke's law by finite differences.

use boltzone::hankel::kernel_shear::{shear_face_remainders, ShearKernels};

fn arr(k: &ShearKernels) -> [f64; 6] {
    [k.z, k.tau, k.r, k.m, k.n, k.w]
}

#[test]
fn kernels_match_the_symbolic_derivation() {
    let text = include_str!("../data/shear_kernels.csv");
    let mut rows = 0;
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('t'))
    {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let k = arr(&ShearKernels::at(v[0], v[1], v[2]));
        let scale = v[3..].iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for (got, want) in k.iter().zip(&v[3..]) {
            // a few ε of the largest kernel: the scaled form loses nothing but rounding (the
            // L ~ 1/t kernels at t = 0.01 cancel O(1/t) terms to O(t))
            assert!(
                (got - want).abs() < 20.0 * f64::EPSILON * scale,
                "{line}: {k:?}"
            );
        }
        rows += 1;
    }
    assert_eq!(rows, 24);
}

#[test]
fn faces_remainders_and_half_space_limits() {
    for t in [1e-8, 0.01, 0.7, 3.0, 40.0, 700.0] {
        for nu in [0.0, 0.3, 0.5] {
            let k = ShearKernels::at(t, t, nu);
            assert!(
                k.z.abs() < 1e-15 && (k.tau - 1.0).abs() < 1e-15,
                "{t} {k:?}"
            );
            let rem = shear_face_remainders(t, nu);
            let lim = [2.0, 2.0 * (1.0 - nu), 2.0 * nu, 1.0 - 2.0 * nu];
            for ((got, l), rm) in [k.r, k.m, k.n, k.w]
                .iter()
                .zip(lim)
                .zip([rem.r, rem.m, rem.n, rem.w])
            {
                // the remainders are O(t e^(−2t)); near t = 0 the kernels ~ 1/t carry ε/t, at
                // large t the O(t) terms t S_t C_s − s C_t S_s cancel, leaving ~ε·t
                let tol = 1e-14 * (1.0 + 1.0 / t) + 8.0 * f64::EPSILON * t;
                assert!((got - l - rm).abs() < tol, "{t} {nu}: {got} {l} {rm}");
            }
        }
    }
    // deep in a thick slab: the half-space kernels (α + βu)e^(−u), up to O(t e^(−2t))
    let nu = 0.3;
    for u in [0.0, 0.4, 2.5, 9.0] {
        let k = arr(&ShearKernels::at(60.0, 60.0 - u, nu));
        let lim = [
            (0.0, 1.0),
            (1.0, -1.0),
            (2.0, -1.0),
            (2.0 * (1.0 - nu), -1.0),
            (2.0 * nu, 0.0),
            (1.0 - 2.0 * nu, 1.0),
        ];
        for (got, (al, be)) in k.iter().zip(lim) {
            assert!(
                (got - (al + be * u) * (-u).exp()).abs() < 1e-14,
                "u {u}: {k:?}"
            );
        }
    }
}

#[test]
fn equilibrium_and_hookes_law_by_differences() {
    // One Hankel component ξ (s̄ = δ): σ_z = ξ L_z J₀(ξr), τ = ξ L_τ J₁, σ_r = ξ[L_r J₀ − L_m J₁/(ξr)],
    // σ_θ = ξ[L_n J₀ + L_m J₁/(ξr)], 2G u = L_m J₁, 2G w = L_w J₀ must be an elastic state.
    let (d, nu, g) = (0.8, 0.3, 1.0);
    for xi in [0.3, 2.0, 7.0] {
        let field = |r: f64, z: f64| {
            let k = ShearKernels::at(xi * d, xi * z, nu);
            let (j0, j1) = (libm::j0(xi * r), libm::j1(xi * r));
            let j1x = j1 / (xi * r);
            [
                xi * (k.r * j0 - k.m * j1x), // σ_r
                xi * (k.n * j0 + k.m * j1x), // σ_θ
                xi * k.z * j0,               // σ_z
                xi * k.tau * j1,             // τ
                k.m * j1 / (2.0 * g),        // u
                k.w * j0 / (2.0 * g),        // w
            ]
        };
        let h = 1e-3 / xi.max(1.0);
        // 4th-order central differences: truncation (ξh)⁴/30 ~ 3e-14, rounding ε/h ~ 2e-13
        let dd = |f: &dyn Fn(f64) -> [f64; 6], x: f64| -> [f64; 6] {
            let (a, b, c, e) = (f(x - 2.0 * h), f(x - h), f(x + h), f(x + 2.0 * h));
            std::array::from_fn(|i| (a[i] - 8.0 * b[i] + 8.0 * c[i] - e[i]) / (12.0 * h))
        };
        for (r, z) in [(0.5, 0.3), (1.3, 0.05), (0.9, 0.75)] {
            let f = field(r, z);
            let fr = dd(&|x| field(x, z), r);
            let fz = dd(&|y| field(r, y), z);
            let size = f.iter().map(|v| v.abs()).fold(0.0, f64::max) * xi.max(1.0);
            let eq_r = fr[0] + fz[3] + (f[0] - f[1]) / r;
            let eq_z = fr[3] + fz[2] + f[3] / r;
            assert!(
                eq_r.abs() < 1e-9 * size && eq_z.abs() < 1e-9 * size,
                "ξ {xi} ({r},{z}): {eq_r:e} {eq_z:e}"
            );
            // Hooke: σ = 2G[ε + ν/(1−2ν) tr ε], τ = G γ
            let (er, et, ez) = (fr[4], f[4] / r, fz[5]);
            let tr = er + et + ez;
            let lam = nu / (1.0 - 2.0 * nu);
            let hooke = [
                2.0 * g * (er + lam * tr) - f[0],
                2.0 * g * (et + lam * tr) - f[1],
                2.0 * g * (ez + lam * tr) - f[2],
                g * (fz[4] + fr[5]) - f[3],
            ];
            for v in hooke {
                assert!(v.abs() < 1e-9 * size, "ξ {xi} ({r},{z}): Hooke {hooke:?}");
            }
        }
    }
}
