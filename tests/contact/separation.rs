//! The R_o estimators on synthetic data with a known separation radius.

use boltzone::contact::separation::{estimate, NodalInterface};
use boltzone::numerics::convergence::fitted_rate;

/// Nodes spaced h from 0.1, pressure c√(R−r)(1 + a(R−r)), gap (r−R)^{3/2}(1 + a(r−R)).
fn synthetic(h: f64, r_o: f64, a: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let r: Vec<f64> = (0..)
        .map(|i| 0.1 + h * i as f64)
        .take_while(|&x| x < 1.0)
        .collect();
    let p = r
        .iter()
        .map(|&x| {
            if x < r_o {
                3.0 * (r_o - x).sqrt() * (1.0 + a * (r_o - x))
            } else {
                0.0
            }
        })
        .collect();
    let g = r
        .iter()
        .map(|&x| {
            if x > r_o {
                1e-4 * (x - r_o).powf(1.5) * (1.0 + a * (x - r_o))
            } else {
                0.0
            }
        })
        .collect();
    (r, p, g)
}

#[test]
fn exact_on_the_pure_asymptotic_form() {
    for &r_o in &[0.2713, 0.35, 0.4999] {
        let (r, p, g) = synthetic(0.013, r_o, 0.0);
        let e = estimate(&NodalInterface {
            radius: &r,
            pressure: &p,
            gap: &g,
        })
        .unwrap();
        // Round-off only: g^{2/3} and p² are exactly linear; a few ε relative to r.
        assert!((e.r_o - r_o).abs() < 1e-14, "{} vs {r_o}", e.r_o);
        assert!((e.r_o_pressure.unwrap() - r_o).abs() < 1e-13);
        assert!(e.spread < 1e-13);
        assert!(e.last_contact < r_o && r_o <= e.first_open);
    }
}

#[test]
fn second_order_with_curvature_and_spread_bounds_error() {
    let r_o = 0.3171;
    let mut errs = Vec::new();
    let mut hs = Vec::new();
    for k in 0..5 {
        let h = 0.02 / 2f64.powi(k);
        let (r, p, g) = synthetic(h, r_o, 2.0);
        let e = estimate(&NodalInterface {
            radius: &r,
            pressure: &p,
            gap: &g,
        })
        .unwrap();
        let err = (e.r_o - r_o).abs();
        // The spread of the estimators is an upper bound of the actual error here.
        assert!(err <= e.spread, "h={h}: error {err} > spread {}", e.spread);
        errs.push(err);
        hs.push(h);
    }
    // Least-squares slope of log error against log h: the gap estimator is second order.
    let pts: Vec<(f64, f64)> = hs.iter().copied().zip(errs.iter().copied()).collect();
    let slope = boltzone::numerics::convergence::log_log_slope(&pts);
    assert!((1.8..2.3).contains(&slope), "observed order {slope}");
}

#[test]
fn fitted_rate_recovers_a_power_law() {
    // x_k = 1 + 0.3 hₖ^1.5 with h halving: the changes fall at rate 1.5 exactly.
    let xs: Vec<f64> = (0..4)
        .map(|k| 1.0 + 0.3 * 0.5f64.powi(k).powf(1.5))
        .collect();
    assert!((fitted_rate(&xs, 2.0).unwrap() - 1.5).abs() < 1e-12);
    assert!(fitted_rate(&xs[..2], 2.0).is_none());
}

#[test]
fn no_estimate_without_contact_or_open_nodes() {
    let r = [0.1, 0.2, 0.3];
    assert!(estimate(&NodalInterface {
        radius: &r,
        pressure: &[0.0; 3],
        gap: &[1.0; 3]
    })
    .is_none());
    assert!(estimate(&NodalInterface {
        radius: &r,
        pressure: &[1.0, 1.0, 0.0],
        gap: &[0.0, 0.0, 1.0]
    })
    .is_none());
}
