//! The closed-form load transform p̄(ξ) = ∫ p(r) J₀(ξr) r dr of piecewise-linear loads (shared by
//! the slab and the hole correction) against a brute-force Gauss–Legendre integration over r,
//! which shares none of its closed forms (no Ji₀, no x²J₁ identities).

use boltzone::hankel::transform::LoadTransform;
use boltzone::numerics::quadrature::gauss_legendre;
use boltzone::{FaceLoad, Peak};

/// ∫ p(r) J₀(ξr) r dr by 20-point Gauss–Legendre on every linear piece, split into panels of
/// at most a tenth of a period of J₀(ξr) (error far below ε of the integrand's size).
fn brute_force(load: &FaceLoad, xi: f64) -> f64 {
    let rule = gauss_legendre(20);
    load.segments()
        .map(|s| {
            let n = ((s.r1 - s.r0) * xi / (0.2 * std::f64::consts::PI))
                .ceil()
                .max(1.0) as usize;
            let h = (s.r1 - s.r0) / n as f64;
            (0..n)
                .map(|k| {
                    let (a, b) = (s.r0 + k as f64 * h, s.r0 + (k + 1) as f64 * h);
                    let (m, hw) = (0.5 * (a + b), 0.5 * (b - a));
                    rule.iter()
                        .map(|(x, w)| {
                            let r = m + hw * x;
                            w * s.at(r) * r * libm::j0(xi * r)
                        })
                        .sum::<f64>()
                        * hw
                })
                .sum::<f64>()
        })
        .sum()
}

#[test]
fn closed_form_transform_matches_brute_force_quadrature() {
    let loads = [
        FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
        FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA).unwrap(),
        FaceLoad::triangular(0.1, 0.16, 1.0, Peak::AtB).unwrap(),
        FaceLoad::tabulated(&[0.0, 0.05, 0.1, 0.2, 0.31], &[0.5, 0.8, 1.3, 1.0, 0.0]).unwrap(),
    ];
    for load in &loads {
        let t = LoadTransform::new(load);
        let m = t.abs_moment();
        // ξr spans every branch of Ji₀: series (< 2), table (2..40) and asymptotic (≥ 40).
        for xi in [0.0, 1e-6, 0.3, 3.0, 17.0, 99.0, 1234.5, 2.0e4] {
            let (a, b) = (t.eval(xi), brute_force(load, xi));
            // The closed form loses ~log10(ξB) digits to cancelling boundary terms of size ≤ M
            // (the load's moment ∫|p| r dr); the brute force sums ~ξB/0.6 panels of size ≤ M.
            let tol = 1e-14 * m * (1.0 + xi * 0.31);
            assert!((a - b).abs() <= tol, "ξ = {xi}: {a:e} vs {b:e}");
        }
    }
}
