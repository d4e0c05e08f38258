//! The closed-form transform of piecewise-linear loads: ∫₀^x J₀ against mpmath
//! (`tests/data/hole_int_j0.py`), and p̄(ξ) against the slab's own Gauss–Legendre transform.

use boltzone::hankel::hole::linear_transform::{int_j0, LinearTransform};
use boltzone::hankel::transform::LoadTransform;
use boltzone::{FaceLoad, Peak};

#[test]
fn integral_of_j0_matches_mpmath() {
    let mut worst = 0.0f64;
    for l in include_str!("data/hole_int_j0.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('x'))
    {
        let v: Vec<f64> = l.split(',').map(|s| s.parse().unwrap()).collect();
        let (x, f) = (v[0], v[1]);
        let e = (int_j0(x) - f).abs();
        worst = worst.max(e);
        // Table: interpolation of 24-point Chebyshev on panels of 2 (error ~1e-25) plus the
        // Gauss values' rounding, ~20 ε accumulated over 20 panels; asymptotic range: the
        // cancellation of xJ₀ against (πx/2)J₀M₁ costs ~ε·x|J₀| ~ ε√x (3e-14 at x = 1e5).
        assert!(
            e < 1e-14 * x.sqrt().max(1.0),
            "x = {x}: {} vs {f}",
            int_j0(x)
        );
    }
    println!("worst absolute error {worst:e}");
}

#[test]
fn closed_form_transform_matches_gauss_legendre() {
    let loads = [
        FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
        FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA).unwrap(),
        FaceLoad::triangular(0.1, 0.16, 1.0, Peak::AtB).unwrap(),
        FaceLoad::tabulated(&[0.0, 0.05, 0.1, 0.2, 0.31], &[0.5, 0.8, 1.3, 1.0, 0.0]).unwrap(),
    ];
    for load in &loads {
        let (fast, slow) = (LinearTransform::new(load), LoadTransform::new(load));
        let m = slow.abs_moment();
        for xi in [0.0, 1e-6, 0.3, 3.0, 17.0, 99.0, 1234.5, 2.0e4] {
            let (a, b) = (fast.eval(xi), slow.eval(xi));
            // Both ≈ exact: the Gauss sums to ~1e-15 of the load's moment; the closed form loses
            // ~log10(ξB) digits to cancelling boundary terms of size ≤ M (see the module docs).
            let tol = 1e-14 * m * (1.0 + xi * 0.31);
            assert!((a - b).abs() <= tol, "ξ = {xi}: {a:e} vs {b:e}");
        }
    }
}
