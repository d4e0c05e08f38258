//! Lamé thick cylinder against its exact solution (src/fem/lame.rs): observed L2 orders of every
//! element, and volumetric locking at ν = 0.499.
//!
//! Tolerances come from the study in examples/02_lame_convergence.rs: on n = 8, 16, 32 elements
//! the fitted orders are 1.99–2.00 (linear elements) and 2.99 (Q9) at ν = 0.3, so ±0.1 around
//! the theoretical 2 and 3 leaves room for nothing but a real loss of order.

use boltzone::fem::lame::{lame_error, LameCase};
use boltzone::numerics::convergence::log_log_slope;

/// The observed order: minus the least-squares slope of ln(error) against ln(elements).
fn observed_order(ns: &[usize], errs: &[f64]) -> f64 {
    let pts: Vec<(f64, f64)> = ns.iter().zip(errs).map(|(&n, &e)| (n as f64, e)).collect();
    -log_log_slope(&pts)
}
use boltzone::fem::ElementKind;

const NS: [usize; 3] = [8, 16, 32];

fn errors(nu: f64, kind: ElementKind, ns: &[usize]) -> Vec<f64> {
    let case = LameCase { a: 1.0, b: 2.0, nu };
    ns.iter()
        .map(|&n| lame_error(&case, kind, n).unwrap())
        .collect()
}

#[test]
fn observed_orders_are_two_for_linear_and_three_for_quadratic() {
    for (kind, expected) in [
        (ElementKind::Cst4, 2.0),
        (ElementKind::Q4, 2.0),
        (ElementKind::Q4Bbar, 2.0),
        (ElementKind::Q9, 3.0),
    ] {
        let e = errors(0.3, kind, &NS);
        let p = observed_order(&NS, &e);
        assert!(
            (p - expected).abs() < 0.1,
            "{kind:?}: order {p}, errors {e:?}"
        );
    }
}

#[test]
fn nearly_incompressible_q4_locks_and_bbar_q9_do_not() {
    let ns = [4, 8, 16];
    // Q4 with full integration: at ν = 0.499 the error on 4 elements is > 50 × that at ν = 0.3
    // (measured 137×): this is the locking the next two checks must NOT show.
    let (q4a, q4b) = (
        errors(0.3, ElementKind::Q4, &ns),
        errors(0.499, ElementKind::Q4, &ns),
    );
    assert!(q4b[0] > 50.0 * q4a[0], "Q4 should lock: {q4a:?} {q4b:?}");
    // B-bar: the error barely depends on ν (measured ratio ≤ 1.19)
    let (ba, bb) = (
        errors(0.3, ElementKind::Q4Bbar, &ns),
        errors(0.499, ElementKind::Q4Bbar, &ns),
    );
    for (a, b) in ba.iter().zip(&bb) {
        assert!(*b < 1.5 * a, "B-bar locks: {ba:?} {bb:?}");
    }
    assert!((observed_order(&ns, &bb) - 2.0).abs() < 0.1);
    // Q9 (3×3 Gauss): converges at ν = 0.499 at least at its nominal order 3 (measured 3.9,
    // pre-asymptotic) to below 0.1 % already on 8 elements; locking would stall the rate.
    let q9 = errors(0.499, ElementKind::Q9, &ns);
    assert!(observed_order(&ns, &q9) > 2.9, "Q9 at ν = 0.499: {q9:?}");
    assert!(q9[1] < 1e-3, "Q9 at ν = 0.499: {q9:?}");
}
