//! `numerics::panel_grid`'s J₀ below x = 25 (from 2, a table of Chebyshev interpolants of
//! degree 12 on unit intervals, built once; below 2, `libm::j0`) against a second method that shares nothing with it: Bessel's
//! integral J₀(x) = (1/π)∫₀^π cos(x sin θ) dθ by the midpoint rule, whose error for a periodic
//! analytic integrand is of the order of J₂ₙ(x) for n points (n = 96: below 1e-60 at x ≤ 25).

use boltzone::numerics::panel_grid::PanelGrid;

/// Bessel's integral by the midpoint rule on 96 points.
fn j0_bessel_integral(x: f64) -> f64 {
    let n = 96;
    let h = std::f64::consts::PI / n as f64;
    (0..n)
        .map(|k| (x * ((k as f64 + 0.5) * h).sin()).cos())
        .sum::<f64>()
        / n as f64
}

#[test]
fn the_j0_table_equals_bessels_integral_below_25() {
    // 1000 nodes on [0, 25) (ξ = 1, so x = s exactly), every unit interval of the table
    // visited about 40 times. The table's own error is ≤ 5e-18; the rest is rounding: of libm's
    // values at the Chebyshev points (carried with a Lebesgue constant under 2.5), and in the
    // integral of the argument x sin θ (a few ulp of x, moving the cosine by as much). Held to
    // that argument's rounding, 4ε(1 + x) as in `panel_grid.rs`. Measured: the row at most
    // 0.69 of it, the table (x ≥ 2) 0.21, libm's own J₀ 0.69.
    let grid = PanelGrid::new(0.0, 25.0, 0.5);
    let mut row = vec![0.0; grid.len()];
    grid.j0_row(1.0, &mut row);
    let (mut worst, mut worst_table, mut worst_libm) = (0.0f64, 0.0f64, 0.0f64);
    for (&x, &j) in grid.nodes().iter().zip(&row) {
        let bound = 4.0 * f64::EPSILON * (1.0 + x);
        let reference = j0_bessel_integral(x);
        worst = worst.max((j - reference).abs() / bound);
        if x >= 2.0 {
            worst_table = worst_table.max((j - reference).abs() / bound);
        }
        worst_libm = worst_libm.max((libm::j0(x) - reference).abs() / bound);
    }
    println!(
        "largest |error|/bound: row {worst:.2} (table, x ≥ 2: {worst_table:.2}), libm {worst_libm:.2}"
    );
    assert!(worst <= 1.0, "{worst}");
}
