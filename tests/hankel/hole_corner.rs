//! The corner enrichment of the hole correction: complex-order Bessel Λ_ν and Γ against mpmath,
//! the Williams exponents, the load transforms against brute-force quadrature, the fields' face
//! conditions (Hankel inversion), their closed-form face value, equilibrium by differences, and
//! the corner exponent of their traction on the hole.

use boltzone::hankel::hole::corner::{corner_exponents, CornerLoads, FieldComponent};
use boltzone::hankel::hole::corner_quad::{expint, expint_sequence};
use boltzone::hankel::kernel::face_remainders;
use boltzone::hankel::kernel_shear::shear_face_remainders;
use boltzone::numerics::bessel_nu::{gamma, NormalBessel};
use boltzone::numerics::quadrature::{integrate_oscillatory, QuadParams};
use boltzone::numerics::tanh_sinh::tanh_sinh;
use num_complex::Complex64;

fn reference() -> Vec<(String, Complex64, f64, Complex64)> {
    let text = include_str!("../data/hole_bessel_nu.csv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("kind"))
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let v = |i: usize| f[i].parse::<f64>().unwrap();
            (
                f[0].to_string(),
                Complex64::new(v(1), v(2)),
                v(3),
                Complex64::new(v(4), v(5)),
            )
        })
        .collect()
}

#[test]
fn normal_bessel_gamma_and_roots_match_mpmath() {
    let lam = corner_exponents(4);
    let mut worst: f64 = 0.0;
    let mut k = 0;
    let (mut w, mut e_rows) = (Complex64::new(0.0, 0.0), 0);
    for (kind, nu, x, v) in reference() {
        match kind.as_str() {
            "R" => {
                // Newton converged to 1e-15 relative; the reference carries 20 digits
                assert!(
                    (lam[k] - nu).norm() < 1e-14 * nu.norm(),
                    "{k}: {} vs {nu}",
                    lam[k]
                );
                k += 1;
            }
            "L" => {
                let got = NormalBessel::new(nu).eval(x);
                let err = (got - v).norm() / v.norm();
                worst = worst.max(err);
                // Λ has no real zeros for Im ν ≠ 0: relative error is meaningful. Miller and the
                // Hankel sums lose a few ε per term: 1e-13.
                assert!(err < 1e-13, "Λ_{nu}({x}) = {got} vs {v}: {err:e}");
                if nu.re > 1.0 {
                    // the pair (Λ_(ν−1), Λ_ν) from one recurrence (the corner loads' use)
                    let lower = NormalBessel::new(nu - 1.0);
                    let (_, pair) = lower.eval_pair(&NormalBessel::new(nu), x);
                    let err = (pair - v).norm() / v.norm();
                    assert!(err < 1e-13, "pair Λ_{nu}({x}) = {pair} vs {v}: {err:e}");
                }
                // and as the top of a family ν − j … ν from one recurrence at ν − j (the
                // corner transforms' use, families of λ_k + 0…3)
                for j in 1..=3 {
                    if nu.re > j as f64 {
                        let family: Vec<NormalBessel> = (0..=j)
                            .map(|i| NormalBessel::new(nu - (j - i) as f64))
                            .collect();
                        let top = NormalBessel::eval_family(&family, x)[j];
                        let err = (top - v).norm() / v.norm();
                        assert!(err < 1e-13, "family Λ_{nu}({x}) from ν − {j}: {err:e}");
                    }
                }
            }
            "G" => {
                let got = gamma(nu);
                assert!(
                    (got - v).norm() < 1e-13 * v.norm(),
                    "Γ({nu}) = {got} vs {v}"
                );
            }
            "W" => w = nu,
            "E" => {
                // E_p(w) for the tails: direct, and inside a recurrence sequence from 3 below
                let got = expint(nu, w);
                assert!(
                    (got - v).norm() < 1e-13 * v.norm(),
                    "E_{nu}({w}) = {got} vs {v}"
                );
                let seq = expint_sequence(nu - 3.0, 6, w);
                let err = (seq[3] - v).norm() / v.norm();
                assert!(err < 1e-13, "sequence E_{nu}({w}) = {} vs {v}", seq[3]);
                e_rows += 1;
            }
            _ => unreachable!(),
        }
    }
    assert_eq!((k, e_rows), (4, 24));
    eprintln!("worst relative error of Λ: {worst:e}");
}

#[test]
fn transforms_match_brute_force_quadrature() {
    // q̄(ξ) = ∫₀^A (1 − r²/A²)^(λ−1) J₀(ξr) r dr and s̄(ξ) = ∫₀^A (r/A)(…) J₁(ξr) r dr by tanh–sinh
    // (which integrates the endpoint power to full precision) against the Sonine closed forms.
    let a = 0.1;
    let loads = CornerLoads::new(a, 0.2, 0.3, 1.0, 3);
    for k in 0..3 {
        for xi in [0.0, 7.0, 41.0, 230.0, 1500.0] {
            let (qn, qs) = loads.transforms(k, xi);
            let part = |shear: bool, imag: bool| {
                tanh_sinh(0.0, a, 1e-15, |r| {
                    let (q, s) = loads.loads(k, r);
                    let (v, j) = if shear {
                        (s, libm::j1(xi * r))
                    } else {
                        (q, libm::j0(xi * r))
                    };
                    (if imag { v.im } else { v.re }) * j * r
                })
                .0
            };
            let bn = Complex64::new(part(false, false), part(false, true));
            let bs = Complex64::new(part(true, false), part(true, true));
            // relative to the transform's size at ξ = 0 (the integrands oscillate at large ξ)
            let scale = a * a / 2.0;
            assert!(
                (qn - bn).norm() < 1e-13 * scale,
                "k {k} ξ {xi}: {qn} vs {bn}"
            );
            assert!(
                (qs - bs).norm() < 1e-13 * scale,
                "k {k} ξ {xi}: {qs} vs {bs}"
            );
        }
    }
}

#[test]
fn faces_carry_exactly_the_loads() {
    // σ_z(r, D) of the pressure load = −q(r), τ_rz(r, D) of the shear load = s(r) (Hankel
    // inversion through the quadrature and the closed-form tail, which on the face r = A is the
    // non-oscillating E_p(0) case), the other face traction 0; on both faces and for r > A zero.
    let (a, d) = (0.1, 0.2);
    let loads = CornerLoads::new(a, d, 0.3, 1.0, 3);
    for r in [0.05, 0.09, 0.0999, 0.1, 0.1001, 0.13, 0.3] {
        for z in [d, -d] {
            let f = loads.fields(r, &[z], &[FieldComponent::SigmaZ, FieldComponent::TauRz]);
            for (k, c) in f[0].iter().enumerate() {
                let (q, s) = loads.loads(k, r);
                let sign = z.signum();
                // rounding of O(1) transforms summed over ~500 nodes: 1e-14 of the load's size 1
                let errs = [
                    (c[0][0] + q).norm(),
                    c[1][0].norm(),
                    c[0][1].norm(),
                    (c[1][1] - sign * s).norm(),
                ];
                assert!(
                    errs.iter().all(|e| *e < 1e-14),
                    "r {r} z {z} k {k}: {errs:?}"
                );
            }
        }
    }
}

#[test]
fn face_value_at_the_corner_matches_weber_schafheitlin() {
    // σ_r(A, D) on the corner itself, where the ξ-integrand decays only like ξ^(−Re λ) without
    // oscillating: the half-space part in closed form (pressure: −q(A) + (1−2ν)q̄(0)/A²; shear:
    // 2H − 2(1−ν)G with H = ∫ξs̄J₀(ξA)dξ = −Γ(λ)Γ(λ−1)/(4Γ(λ+½)²), G = ∫s̄J₁(ξA)dξ/A =
    // Γ(λ)²/(4Γ(λ+½)Γ(λ+3/2)) by Weber–Schafheitlin, DLMF 10.22.57) plus the face remainders
    // (decaying like e^(−2ξD)) by partition–extrapolation: a route sharing neither the tail
    // expansion nor the finite-part rule.
    let (a, d, nu) = (0.1, 0.1, 0.3);
    let loads = CornerLoads::new(a, d, nu, 1.0, 2);
    let f = loads.fields(a, &[d], &[FieldComponent::SigmaR]);
    let q = QuadParams {
        rel_tol: 1e-14,
        abs_tol: 1e-16,
        ..QuadParams::default()
    };
    for (k, &l) in loads.exponents().iter().enumerate() {
        let rem = |shear: bool, imag: bool| {
            integrate_oscillatory(
                |xi| {
                    let (qn, qs) = loads.transforms(k, xi);
                    let x = xi * a;
                    let (j0, j1x) = (libm::j0(x), if x > 0.0 { libm::j1(x) / x } else { 0.5 });
                    let v = if shear {
                        let r = shear_face_remainders(xi * d, nu);
                        xi * qs * (r.r * j0 - r.m * j1x)
                    } else {
                        let r = face_remainders(xi * d, nu);
                        -xi * qn * (r.r * j0 - r.m * j1x)
                    };
                    if imag {
                        v.im
                    } else {
                        v.re
                    }
                },
                2.0 * a,
                1.0 / d,
                &q,
            )
            .value
        };
        let h = -gamma(l) * gamma(l - 1.0) / (4.0 * gamma(l + 0.5) * gamma(l + 0.5));
        let gg = gamma(l) * gamma(l) / (4.0 * gamma(l + 0.5) * gamma(l + 1.5));
        let shear =
            2.0 * h - 2.0 * (1.0 - nu) * gg + Complex64::new(rem(true, false), rem(true, true));
        let pressure =
            (1.0 - 2.0 * nu) / (2.0 * l) + Complex64::new(rem(false, false), rem(false, true));
        let got = f[0][k][0];
        // both routes are accurate to ~1e-15 of O(0.1) values
        assert!(
            (got[0] - pressure).norm() < 1e-13,
            "k {k}: {} vs {pressure}",
            got[0]
        );
        assert!(
            (got[1] - shear).norm() < 1e-13,
            "k {k}: {} vs {shear}",
            got[1]
        );
    }
}

type Fields = Vec<Vec<[Complex64; 2]>>;

#[test]
fn fields_are_in_equilibrium_and_obey_hookes_law() {
    use FieldComponent::*;
    let (a, d, nu, g) = (0.1, 0.2, 0.3, 1.0);
    let loads = CornerLoads::new(a, d, nu, g, 2);
    let comps = [SigmaR, SigmaTheta, SigmaZ, TauRz, U, W];
    let h = 2e-5;
    // 4th-order differences: truncation (h/ρ)⁴/30 ≤ 1e-12 at a distance ρ ≥ 0.005 from the
    // corner, rounding ~ε|f|/h: far below 1e-8 of the derivatives' size
    for (r, z) in [(0.105, 0.19), (0.13, 0.1), (0.2, 0.17), (0.101, -0.05)] {
        let at = |r: f64, z: f64| -> Fields { loads.fields(r, &[z], &comps)[0].clone() };
        let f = at(r, z);
        let rs = [
            at(r - 2.0 * h, z),
            at(r - h, z),
            at(r + h, z),
            at(r + 2.0 * h, z),
        ];
        let zs = [
            at(r, z - 2.0 * h),
            at(r, z - h),
            at(r, z + h),
            at(r, z + 2.0 * h),
        ];
        for k in 0..2 {
            for kind in 0..2 {
                let v = |x: &Fields, c: usize| x[k][c][kind];
                let diff = |s: &[Fields; 4], c: usize| {
                    (v(&s[0], c) - 8.0 * v(&s[1], c) + 8.0 * v(&s[2], c) - v(&s[3], c)) / (12.0 * h)
                };
                let (dr, dz) = (|c| diff(&rs, c), |c| diff(&zs, c));
                let (sr, st, sz, tau, u) = (v(&f, 0), v(&f, 1), v(&f, 2), v(&f, 3), v(&f, 4));
                let size = (0..4).map(|c| dr(c).norm() + dz(c).norm()).sum::<f64>();
                let eq_r = dr(0) + dz(3) + (sr - st) / r;
                let eq_z = dr(3) + dz(2) + tau / r;
                assert!(
                    eq_r.norm() < 1e-8 * size && eq_z.norm() < 1e-8 * size,
                    "({r},{z}) {k} {kind}: {eq_r} {eq_z}"
                );
                let (er, et, ez) = (dr(4), u / r, dz(5));
                let lam = nu / (1.0 - 2.0 * nu);
                let tr = er + et + ez;
                let hooke = [
                    2.0 * g * (er + lam * tr) - sr,
                    2.0 * g * (et + lam * tr) - st,
                    2.0 * g * (ez + lam * tr) - sz,
                    g * (dz(4) + dr(5)) - tau,
                ];
                let ssize = sr.norm() + st.norm() + sz.norm() + tau.norm();
                assert!(
                    hooke.iter().all(|x| x.norm() < 1e-8 * ssize),
                    "({r},{z}) {k} {kind}: {hooke:?}"
                );
            }
        }
    }
}

#[test]
fn traction_on_the_hole_has_the_corner_exponent() {
    // Near the corner each complex field is smooth + K·y^(λ−1) + O(y^λ), y = D − z: its third
    // derivative ~ y^(λ−4). With the difference step ∝ y (h = y/4) a pure power's difference
    // quotient is exactly ∝ y^(λ−4), so the log–log slope of the third difference measures
    // Re λ − 4 directly (the smooth part adds a constant, the next term a relative O(y)).
    let (a, d) = (0.1, 0.1);
    let loads = CornerLoads::new(a, d, 0.3, 1.0, 1);
    let l = loads.exponents()[0];
    let ys: Vec<f64> = (0..6)
        .map(|i| d * 10f64.powf(-5.5 + 0.5 * i as f64))
        .collect();
    for col in 0..4 {
        let pts: Vec<(f64, f64)> = ys
            .iter()
            .map(|&y| {
                let hh = y / 4.0;
                let zs: Vec<f64> = [-2.0, -1.0, 1.0, 2.0]
                    .iter()
                    .map(|s| d - y - s * hh)
                    .collect();
                let t = loads.tractions(a, &zs);
                let v: Vec<Complex64> = t.iter().map(|h| h[0][col]).collect();
                let d3 = (-v[0] + 2.0 * v[1] - 2.0 * v[2] + v[3]) / (2.0 * hh * hh * hh);
                (y.ln(), d3.norm().ln())
            })
            .collect();
        let slope = boltzone::numerics::convergence::slope(&pts);
        eprintln!(
            "column {col}: slope {slope:.4} (Re λ − 4 = {:.4})",
            l.re - 4.0
        );
        assert!(
            (slope - (l.re - 4.0)).abs() < 0.02,
            "column {col}: slope {slope}"
        );
    }
}

#[test]
fn fields_do_not_depend_on_where_the_tail_starts() {
    // The finite Gauss–Legendre part and the closed-form tail (Hankel expansions, E_p) must add
    // up to the same integral wherever the split lies: moving it from the default (ξA ≈ 34) to
    // 2× and 4× (panels and tail terms change completely) may change nothing but rounding.
    use FieldComponent::*;
    let (a, d) = (0.1, 0.1);
    let base = CornerLoads::new(a, d, 0.3, 1.0, 3);
    let x0 = base.tail_start();
    let zs = [0.0, 0.05, 0.09, 0.099, 0.09999, 0.1, -0.07];
    let comps = [SigmaR, SigmaTheta, SigmaZ, TauRz, U, W];
    for r in [a, 0.13] {
        let f0 = base.fields(r, &zs, &comps);
        for factor in [2.0, 4.0] {
            let moved = CornerLoads::new(a, d, 0.3, 1.0, 3).with_tail_start(factor * x0);
            let f1 = moved.fields(r, &zs, &comps);
            for (h0, h1) in f0.iter().zip(&f1) {
                for (k0, k1) in h0.iter().zip(h1) {
                    for (c0, c1) in k0.iter().zip(k1) {
                        for kind in 0..2 {
                            // O(0.1–1) values, rounding over ~10³ nodes: 1e-14
                            assert!(
                                (c0[kind] - c1[kind]).norm() < 1e-14 * (1.0 + c0[kind].norm()),
                                "r {r} ×{factor}: {} vs {}",
                                c0[kind],
                                c1[kind]
                            );
                        }
                    }
                }
            }
        }
    }
}
