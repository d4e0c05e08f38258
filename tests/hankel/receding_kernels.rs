//! The layer kernels of `hankel::receding::layer` against three independent references: the general
//! four-constant Love solution of the layer (tests/data/receding_layer_kernels.py, exact
//! rational arithmetic), the slab's midplane kernel of `hankel::kernel` (the bilateral limit),
//! and the Kirchhoff plate (the thin-layer limit).

use boltzone::hankel::kernel::midplane;
use boltzone::hankel::receding::layer::{
    bending, bottom_from_bottom, bottom_from_top, symmetric_remainder,
};

/// (x, ν, M_q, M_p) rows of tests/data/receding_layer_kernels.csv.
fn reference() -> Vec<[f64; 4]> {
    let text = include_str!("../data/receding_layer_kernels.csv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('x'))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.trim().parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

#[test]
fn kernels_match_the_general_love_solution() {
    let rows = reference();
    assert_eq!(rows.len(), 20);
    for [x, nu, mq, mp] in rows {
        // relative error: the series branch (x < 1) is exact to rounding, the direct branch
        // loses at most one digit at x = 1 (0.13 of terms ≤ 1): 20ε covers both
        let tol = 20.0 * f64::EPSILON;
        let (eq, ep) = (
            bottom_from_bottom(x) / mq - 1.0,
            bottom_from_top(x) / mp - 1.0,
        );
        assert!(
            eq.abs() < tol && ep.abs() < tol,
            "x={x} nu={nu}: {eq:e} {ep:e}"
        );
    }
}

#[test]
fn symmetric_part_matches_where_the_difference_is_resolved() {
    // M_q − 1 − M_p = S − 1 from the reference's two values: the f64 difference of the parsed
    // numbers carries an absolute error ≈ 2ε·M_q, so compare only where that is below 1e-12
    for [x, _, mq, mp] in reference() {
        if mq < 1e3 {
            let s1 = mq - 1.0 - mp;
            let err = (symmetric_remainder(x) - s1).abs();
            assert!(err < 4.0 * f64::EPSILON * mq, "x={x}: {err:e}");
        }
    }
}

#[test]
fn bilateral_limit_is_the_slab_midplane_kernel() {
    // contact everywhere: w̄(0) = 0 gives q̄ = p̄·M_p/M_q, which must be the midplane σ_z kernel
    // of the slab of half-thickness D (two welded plates). 1e-13: a few roundings of each side.
    let mut x: f64 = 1e-6;
    while x < 700.0 {
        let ratio = bottom_from_top(x) / bottom_from_bottom(x);
        let k = midplane(x);
        assert!((ratio - k).abs() <= 1e-13 * k, "x={x}: {ratio} vs {k}");
        x *= 1.37;
    }
}

#[test]
fn thin_layer_limit_is_the_kirchhoff_plate() {
    // w̄ = (q̄ − p̄)/(𝒟ξ⁴), 𝒟 = E D³/(12(1−ν²)), is M_q ≈ M_p ≈ 6/x³ in half-space units;
    // the next term of Λ's Laurent series is O(1/x), so M·x³ − 6 = O(x²)
    for &x in &[1e-2, 1e-3, 1e-4] {
        for m in [bottom_from_top(x), bottom_from_bottom(x), 0.5 * bending(x)] {
            assert!(
                (m * x * x * x - 6.0).abs() < 2.0 * x * x,
                "x={x}: {}",
                m * x * x * x
            );
        }
    }
}

#[test]
fn thick_layer_limit_decays_like_the_asymptote() {
    // M_p → 2(1 + x)e^(−x), M_q − 1 → 0 (the half-space); relative corrections O(x e^(−x))
    for &x in &[30.0f64, 60.0, 200.0, 700.0] {
        let asym = 2.0 * (1.0 + x) * (-x).exp();
        assert!((bottom_from_top(x) / asym - 1.0).abs() < 1e-10, "x={x}");
        assert!((bottom_from_bottom(x) - 1.0).abs() < 1e-12);
    }
    // far beyond exp underflow: finite, no NaN
    for &x in &[750.0, 1e4, 1e300, f64::MAX] {
        assert!(
            bottom_from_top(x).is_finite() && bottom_from_bottom(x).is_finite(),
            "x={x}"
        );
    }
}
