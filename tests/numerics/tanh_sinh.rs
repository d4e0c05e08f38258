//! Tanh–sinh quadrature against closed forms: logarithmic end-point singularities to full
//! precision; stronger ones (inverse square roots) stop short of the end and must say so in
//! their error estimate.

use boltzone::numerics::tanh_sinh::tanh_sinh;
use std::f64::consts::PI;

#[test]
fn singular_and_smooth_integrals_match_their_closed_forms() {
    type Case = (&'static str, fn(f64) -> f64, f64, f64, f64);
    let cases: [Case; 3] = [
        ("ln x on [0, 1]", |x| x.ln(), 0.0, 1.0, -1.0),
        // ∫₀¹ ln x ln(1 − x) dx = 2 − π²/6 (Gradshteyn & Ryzhik 4.221.1)
        (
            "ln x ln(1-x) on [0, 1]",
            |x| x.ln() * (-x).ln_1p(),
            0.0,
            1.0,
            2.0 - PI * PI / 6.0,
        ),
        ("sin on [0, pi]", f64::sin, 0.0, PI, 2.0),
    ];
    for (name, f, a, b, exact) in cases {
        let (v, e, n) = tanh_sinh(a, b, 1e-13, f);
        let err = (v - exact).abs();
        println!("{name}: value {v}, error {err:e}, estimate {e:e}, {n} evaluations");
        assert!(err <= 1e-12 * exact.abs().max(1.0), "{name}: error {err:e}");
        assert!(err <= e, "{name}: error {err:e} above the estimate {e:e}");
        assert!(n < 500, "{name}: {n} evaluations");
    }
}

#[test]
fn inverse_square_root_singularities_are_not_hidden() {
    // The nodes stop where they would round onto the end, which drops ∫₀^δ x^(−1/2) = 2√δ:
    // the value is short by ~1e-8, and the estimate must cover that.
    type Case = (&'static str, fn(f64) -> f64, f64, f64, f64);
    let cases: [Case; 2] = [
        ("x^(-1/2) on [0, 1]", |x| 1.0 / x.sqrt(), 0.0, 1.0, 2.0),
        // ∫₀² (4 − x²)^(−1/2) dx = π/2: the singularity at the upper end
        (
            "(4 - x^2)^(-1/2) on [0, 2]",
            |x| 1.0 / (4.0 - x * x).sqrt(),
            0.0,
            2.0,
            PI / 2.0,
        ),
    ];
    for (name, f, a, b, exact) in cases {
        let (v, e, _) = tanh_sinh(a, b, 1e-13, f);
        let err = (v - exact).abs();
        println!("{name}: value {v}, error {err:e}, estimate {e:e}");
        assert!(err <= e, "{name}: error {err:e} above the estimate {e:e}");
    }
}
