//! Fig. 22, the deflection of the loaded face under the nut: what it shows.
//!
//! - Under the nut (A ≤ r ≤ B) the curve of Fig. 21's loading is flat at the prescribed
//!   −50 µin (the report's value, `reference/text_values.csv`), to rounding.
//! - Outside the nut the shape is checked by refinement: the curves drawn at the default
//!   tolerance 5e-3 against a run at 1.25e-3 (finer meshes), at the fine run's nodes. The
//!   figures promise every R_o to 5e-3 relative; the curves are drawn from the same meshes, so
//!   they are held to the same relative accuracy of their scale (the largest |w| of each curve)
//!   beyond 1.2 B. Between B and 1.2 B the drawn kink at the nut's edge is coarser: measured
//!   (2026-11-24) up to 4.3 % of the scale for the nut's displacement, 1.6 % for the triangular
//!   load peaking at B, 0.45 % uniform, 0.04 % peaking at A, falling to ≤ 0.6 % beyond 1.05 B;
//!   the figure's note says so. This is a convergence check of the drawn shape, not a second
//!   method.

use super::gallery::{curve, dir, figure, reference, rows};
use crate::common::boltzone;
use std::path::Path;

/// Hole radius of the test plates, in (Chapter III: hole 0.257 in in diameter).
const A: f64 = 0.257 / 2.0;

/// B of the 1/4 in pair: Table 2 case 4's 2B / 2.
fn bearing_radius() -> f64 {
    let row = reference("table2_experiments.csv")
        .into_iter()
        .find(|r| r[0] == "4")
        .unwrap();
    row[4].parse::<f64>().unwrap() / 2.0
}

#[test]
fn fig22_nut_curve_is_flat_at_the_prescribed_displacement() {
    let w: f64 = reference("text_values.csv")
        .into_iter()
        .find(|r| r[0] == "nut_displacement")
        .unwrap()[2]
        .parse()
        .unwrap();
    let fig = figure("fig22");
    assert!(fig["curves"][3]["label"]
        .as_str()
        .unwrap()
        .starts_with("50 µin under each nut"));
    let b = bearing_radius();
    let (r, y) = curve("fig22", 3);
    let under: Vec<f64> = r
        .iter()
        .zip(&y)
        .filter(|(r, _)| **r >= A * (1.0 - 1e-12) && **r <= b * (1.0 + 1e-12))
        .map(|(_, y)| *y)
        .collect();
    assert!(under.len() >= 5, "{} nodes under the nut", under.len());
    for y in under {
        // toward the interface: negative; one scaling of the unit solution
        assert!((y + w).abs() <= 1e-12 * w, "{y} µin vs −{w} µin");
    }
}

#[test]
fn fig22_shape_outside_the_nut_is_converged_to_the_tolerance() {
    let fine = Path::new(env!("CARGO_TARGET_TMPDIR")).join("figures_fig22_fine");
    let _ = std::fs::remove_dir_all(&fine);
    let out = boltzone(&[
        "figures",
        "--only",
        "22",
        "--tol",
        "1.25e-3",
        "--out",
        fine.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let b = bearing_radius();
    let data = rows(&fine.join("fig22.csv"));
    let tolerance = 5e-3;
    let mut worst: f64 = 0.0;
    for k in 0..4 {
        let (x, y) = curve("fig22", k);
        let (xf, yf): (Vec<f64>, Vec<f64>) = data
            .iter()
            .filter(|r| r[2] == k as f64)
            .map(|r| (r[0], r[1]))
            .unzip();
        let scale = y.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        // the default run's piecewise-linear curve at the fine run's nodes beyond B
        let beyond = |r: &f64| *r >= 1.2 * b && *r <= x[x.len() - 1];
        for (r, wf) in xf.iter().zip(&yf).filter(|(r, _)| beyond(r)) {
            let i = x.partition_point(|v| v < r).max(1);
            let t = (r - x[i - 1]) / (x[i] - x[i - 1]);
            let w = y[i - 1] + t * (y[i] - y[i - 1]);
            worst = worst.max((w - wf).abs() / scale);
            assert!(
                (w - wf).abs() <= tolerance * scale,
                "curve {k} at r = {r}: {w} vs {wf} µin (scale {scale})"
            );
        }
    }
    println!(
        "fig22 beyond 1.2 B: largest change 5e-3 → 1.25e-3 = {worst:.2e} of the curve's scale"
    );
    assert!(dir().join("fig22.csv").is_file());
}
