//! The oscillatory quadrature on closed-form Hankel pairs (Gradshteyn & Ryzhik 6.611.1,
//! 6.512.3), including slowly decaying and non-decaying ones; the error estimate must never be
//! below the actual error.

use boltzone::numerics::quadrature::{integrate_oscillatory, wynn_epsilon, QuadParams};

fn check(name: &str, value: f64, error: f64, exact: f64, max_err: f64) {
    let actual = (value - exact).abs();
    assert!(
        actual <= error,
        "{name}: actual error {actual:e} above the estimate {error:e}"
    );
    assert!(
        error <= max_err,
        "{name}: estimate {error:e} above {max_err:e}"
    );
}

#[test]
fn exponential_times_j0_from_fast_to_no_decay() {
    let p = QuadParams::default();
    for &r in &[0.3, 1.0, 7.0] {
        for &a in &[0.0, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0] {
            let e = integrate_oscillatory(|x| (-a * x).exp() * libm::j0(x * r), r, 1.0 / a, &p);
            let exact = 1.0 / (a * a + r * r).sqrt();
            // the requested 1e-12 relative, with room for the rounding floor
            check(
                &format!("J0 a={a} r={r}"),
                e.value,
                e.error,
                exact,
                1e-11 * exact,
            );
        }
    }
}

#[test]
fn exponential_times_j1() {
    let p = QuadParams::default();
    for &r in &[0.5, 2.0] {
        for &a in &[0.0, 1e-3, 0.1, 3.0] {
            let e = integrate_oscillatory(|x| (-a * x).exp() * libm::j1(x * r), r, 1.0 / a, &p);
            let exact = (1.0 - a / (a * a + r * r).sqrt()) / r;
            check(
                &format!("J1 a={a} r={r}"),
                e.value,
                e.error,
                exact,
                1e-11 * exact.abs().max(1e-3),
            );
        }
    }
}

#[test]
fn weber_schafheitlin_step() {
    // ∫₀^∞ J₀(ξr) J₁(ξb) dξ = 1/b for r < b, 0 for r > b: two frequencies, no decay beyond ξ^(−1).
    let p = QuadParams {
        rel_tol: 1e-8,
        abs_tol: 1e-8,
        products: true,
        ..Default::default()
    };
    let b = 1.0;
    for &r in &[0.2, 0.5, 2.0, 3.0] {
        let e = integrate_oscillatory(
            |x| libm::j0(x * r) * libm::j1(x * b),
            r + b,
            f64::INFINITY,
            &p,
        );
        let exact = if r < b { 1.0 / b } else { 0.0 };
        check(&format!("step r={r}"), e.value, e.error, exact, 1e-7);
    }
}

#[test]
fn gauss_legendre_panels_converge_with_order() {
    // the same integral with 10 and 20 points per panel agrees to rounding
    let f = |x: f64| (-0.05 * x).exp() * libm::j0(2.0 * x) * x / (1.0 + x * x);
    let a = integrate_oscillatory(f, 2.0, 1.0, &QuadParams::default());
    let b = integrate_oscillatory(
        f,
        2.0,
        1.0,
        &QuadParams {
            order: 20,
            ..Default::default()
        },
    );
    assert!((a.value - b.value).abs() <= a.error + b.error);
}

#[test]
fn wynn_is_exact_on_two_geometric_components() {
    // ε₄ of S_n = L + c₁q₁ⁿ + c₂q₂ⁿ is exactly L (Shanks' transformation of order 2)
    let s: Vec<f64> = (0..9)
        .map(|n| 1.0 + 0.5 * (-0.8f64).powi(n) + 0.3 * 0.6f64.powi(n))
        .collect();
    let e = wynn_epsilon(&s);
    assert!((e - 1.0).abs() < 1e-13, "{e}");
}
