//! The Papkovich–Fadle modes and the Lamé field are homogeneous solutions of the traction-free
//! layer: roots of sin 2x + 2x = 0, free faces, equilibrium and Hooke's law by finite differences.

use boltzone::hankel::hole::eigen::{lame_field, symmetric_roots, Mode, ModeField};
use num_complex::Complex64;

const A: f64 = 0.1;
const D: f64 = 0.13;
const NU: f64 = 0.3;
const G: f64 = 0.4;

fn modes(n: usize) -> Vec<Mode> {
    symmetric_roots(n)
        .into_iter()
        .map(|x| Mode::new(x, A, D, NU, G))
        .collect()
}

fn scale(f: &ModeField<Complex64>) -> f64 {
    [f.sigma_r, f.sigma_theta, f.sigma_z, f.tau_rz]
        .iter()
        .map(|v| v.norm())
        .fold(0.0, f64::max)
}

#[test]
fn roots_solve_the_symmetric_fadle_equation() {
    let roots = symmetric_roots(200);
    // Published first root (Little & Childs 1967, Table 1): 2x₁ = 4.2124 + 2.2507i.
    assert!((roots[0] * 2.0 - Complex64::new(4.2124, 2.2507)).norm() < 1e-4);
    for (k, x) in roots.iter().enumerate() {
        let f = (*x * 2.0).sin() + *x * 2.0;
        // x itself is rounded to ε|x|, and the derivative 1 + cos 2x has size |sin 2x| ≈ |2x|:
        // the residual is ~ε·|2x|·|sin 2x|; allow 10 times that.
        let size = (*x * 2.0).sin().norm() * (*x * 2.0).norm();
        assert!(f.norm() < 10.0 * f64::EPSILON * size, "k = {k}: {f}");
        if k > 0 {
            let gap = x.re - roots[k - 1].re;
            // Consecutive roots are ≈ π apart (2x_k ≈ (2k − ½)π): none skipped, none repeated.
            assert!(
                (gap - std::f64::consts::PI).abs() < 0.2,
                "k = {k}: gap {gap}"
            );
        }
    }
}

#[test]
fn faces_are_traction_free() {
    for m in modes(40) {
        for r in [A, 0.12, 0.2, 0.5] {
            for z in [D, -D] {
                let f = m.field(r, z);
                let s = scale(&m.field(r, 0.5 * D)).max(scale(&f));
                // Two O(1) terms cancel (x sin x − x sin x): rounding ~ 10 ε relative to the field.
                assert!(f.sigma_z.norm() < 1e-13 * s, "r {r} σ_z {}", f.sigma_z);
                assert!(f.tau_rz.norm() < 1e-13 * s, "r {r} τ {}", f.tau_rz);
            }
        }
    }
}

/// Five-point central derivative of `f` at `x` with step `h`.
fn d5(f: impl Fn(f64) -> ModeField<Complex64>, x: f64, h: f64) -> ModeField<Complex64> {
    let (a, b, c, d) = (f(x - 2.0 * h), f(x - h), f(x + h), f(x + 2.0 * h));
    let g = |p: fn(&ModeField<Complex64>) -> Complex64| {
        (p(&a) - p(&b) * 8.0 + p(&c) * 8.0 - p(&d)) / (12.0 * h)
    };
    ModeField {
        sigma_r: g(|f| f.sigma_r),
        sigma_theta: g(|f| f.sigma_theta),
        sigma_z: g(|f| f.sigma_z),
        tau_rz: g(|f| f.tau_rz),
        u: g(|f| f.u),
        w: g(|f| f.w),
    }
}

#[test]
fn modes_satisfy_equilibrium_and_hookes_law() {
    let (lam_l, two_g) = (2.0 * G * NU / (1.0 - 2.0 * NU), 2.0 * G);
    for (k, m) in modes(20).into_iter().enumerate() {
        // Step 1e-2/|λ|: the 5-point rule's truncation (h|λ|)⁴/30 ≈ 3e-10, rounding ε/(h|λ|) ≈ 2e-14.
        let h = 1e-2 / m.lambda().norm();
        for (r, z) in [(0.11, 0.0), (0.13, 0.07), (0.2, -0.12), (0.105, 0.129)] {
            let f = m.field(r, z);
            let dr = d5(|x| m.field(x, z), r, h);
            let dz = d5(|y| m.field(r, y), z, h);
            let s = scale(&f).max(scale(&dr) * h * 100.0);
            let eq_r = dr.sigma_r + dz.tau_rz + (f.sigma_r - f.sigma_theta) / r;
            let eq_z = dr.tau_rz + dz.sigma_z + f.tau_rz / r;
            let tol = 1e-8 * s / (h * 100.0); // relative 1e-8 of the stress gradients' size
            assert!(eq_r.norm() < tol, "k {k} ({r},{z}) eq_r {eq_r} tol {tol}");
            assert!(eq_z.norm() < tol, "k {k} ({r},{z}) eq_z {eq_z}");
            // Hooke: σ = λ_L tr ε + 2G ε with ε_r = u_r, ε_θ = u/r, ε_z = w_z, γ = u_z + w_r.
            let tr = dr.u + f.u / r + dz.w;
            let checks = [
                (f.sigma_r, tr * lam_l + dr.u * two_g),
                (f.sigma_theta, tr * lam_l + f.u / r * two_g),
                (f.sigma_z, tr * lam_l + dz.w * two_g),
                (f.tau_rz, (dz.u + dr.w) * G),
            ];
            for (i, (s_mode, s_hooke)) in checks.into_iter().enumerate() {
                assert!(
                    (s_mode - s_hooke).norm() < 1e-8 * s,
                    "k {k} ({r},{z}) component {i}"
                );
            }
        }
    }
}

#[test]
fn lame_field_is_a_free_face_equilibrium_state() {
    let lam_l = 2.0 * G * NU / (1.0 - 2.0 * NU);
    for r in [A, 0.3, 10.0] {
        let f = lame_field(A, G, r);
        let h = 1e-4 * r;
        let du = (lame_field(A, G, r + h).u - lame_field(A, G, r - h).u) / (2.0 * h);
        let dsr = (lame_field(A, G, r + h).sigma_r - lame_field(A, G, r - h).sigma_r) / (2.0 * h);
        let s = f.sigma_theta.abs();
        // central differences: truncation (h/r)² ≈ 1e-8 relative
        assert!((dsr + (f.sigma_r - f.sigma_theta) / r).abs() < 1e-7 * s / r);
        assert!((f.sigma_r - (lam_l * (du + f.u / r) + 2.0 * G * du)).abs() < 1e-7 * s);
        assert!((f.sigma_theta - (lam_l * (du + f.u / r) + 2.0 * G * f.u / r)).abs() < 1e-7 * s);
    }
    assert_eq!(lame_field(A, G, A).sigma_r, -1.0);
}

#[test]
fn each_mode_is_self_equilibrated_in_z() {
    // Vertical equilibrium of the half body r ≥ A, 0 ≤ z ≤ D with a free face z = D:
    // ∫_A^∞ σ_z(r, 0) r dr = −A ∫_0^D τ_rz(A, z) dz. Both sides by Gauss–Legendre (the r-integral
    // on panels of width 1/|λ| until e^{−Re λ (r−A)} < 1e-17).
    use gauss_quad::GaussLegendre;
    let gl = GaussLegendre::new(std::num::NonZeroUsize::new(30).unwrap());
    for m in modes(12) {
        let lam = m.lambda();
        let lhs: Complex64 = {
            let w = 1.0 / lam.norm();
            let n = (40.0 / (lam.re * w)).ceil() as usize;
            (0..n)
                .map(|i| {
                    let (a, b) = (A + i as f64 * w, A + (i + 1) as f64 * w);
                    let re = gl.integrate(a, b, |r| m.midplane_sigma_z(r).re * r);
                    let im = gl.integrate(a, b, |r| m.midplane_sigma_z(r).im * r);
                    Complex64::new(re, im)
                })
                .sum()
        };
        let rhs = {
            let re = gl.integrate(0.0, D, |z| m.field(A, z).tau_rz.re);
            let im = gl.integrate(0.0, D, |z| m.field(A, z).tau_rz.im);
            Complex64::new(re, im) * -A
        };
        // 30-point Gauss on analytic integrands of a few oscillations: ~1e-14 relative.
        assert!(
            (lhs - rhs).norm() < 1e-11 * rhs.norm().max(A * D),
            "{lhs} vs {rhs}"
        );
    }
}

#[test]
fn midplane_bound_bounds_the_midplane_stress() {
    // Modes 1…128 for A/D from 0.05 to 20 (λA from ~0.1 to ~8000), radii from the hole out
    // to 10 D: |σ_z(r, 0)| ≤ bound.
    let roots = symmetric_roots(128);
    for a_over_d in [0.05, 0.5, 1.0, 5.0, 20.0] {
        let (d, a) = (0.1, 0.1 * a_over_d);
        for x in &roots {
            let m = Mode::new(*x, a, d, 0.3, 1.0);
            for step in [0.0, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0] {
                let r = a + step * d;
                let (value, bound) = (m.midplane_sigma_z(r).norm(), m.midplane_bound(r));
                assert!(
                    value <= bound,
                    "A/D {a_over_d}, λD {x}, r {r}: {value:e} > {bound:e}"
                );
            }
        }
    }
}
