//! `numerics::panel_grid`: the rows of cos ξs, cos ξs − 1 and J₀(ξs) over equal Gauss panels
//! against the library functions evaluated at the same nodes (`f64::cos`, `libm::j0`, an
//! independent rational-approximation implementation), within the rounding of the argument.

use boltzone::numerics::panel_grid::PanelGrid;

/// The argument ξs carries a rounding of a few ulp of x, which moves cos ξs by that much and
/// J₀ by that times its amplitude √(2/(πx)): the bound both rows are held to.
fn argument_rounding(x: f64) -> f64 {
    4.0 * f64::EPSILON * (1.0 + x)
}

#[test]
fn rows_equal_the_library_functions_at_the_nodes() {
    // the holed route's ranges: s on [c, c + 14D] (D = 0.1), ξ up to 450/D·D (x ≤ ~1000)
    let grid = PanelGrid::new(0.35, 1.75, 0.035);
    let n = grid.len();
    assert_eq!(n % 20, 0);
    let (mut cos, mut m1, mut j) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut worst_j = 0.0f64;
    for xi in [
        0.0,
        1e-3,
        0.7,
        13.0,
        25.0 / 0.35,
        40.0 / 0.35,
        101.3,
        400.0,
        617.9,
    ] {
        grid.cos_rows(xi, &mut cos, &mut m1);
        grid.j0_row(xi, &mut j);
        for (i, &s) in grid.nodes().iter().enumerate() {
            let x = xi * s;
            let e = argument_rounding(x);
            assert!((cos[i] - x.cos()).abs() <= e, "cos {xi} {s}");
            assert!((m1[i] - (x.cos() - 1.0)).abs() <= e, "cos − 1 {xi} {s}");
            let amp = if x > 1.0 {
                (2.0 / (std::f64::consts::PI * x)).sqrt()
            } else {
                1.0
            };
            let dj = (j[i] - libm::j0(x)).abs();
            assert!(
                dj <= e * amp + 2.0 * f64::EPSILON * amp,
                "J0 {xi} {s}: {dj:e}"
            );
            worst_j = worst_j.max(dj / amp);
        }
    }
    // the asymptotic branch is exercised and sits at the rounding floor
    assert!(worst_j > 0.0 && worst_j < 1e-12, "{worst_j:e}");
}

#[test]
fn cos_minus_one_keeps_its_relative_accuracy_at_small_arguments() {
    let grid = PanelGrid::new(0.0, 1.0, 0.25);
    let mut m1 = vec![0.0; grid.len()];
    for xi in [1e-6, 1e-3, 0.1] {
        grid.cos_m1_row(xi, &mut m1);
        for (i, &s) in grid.nodes().iter().enumerate() {
            // the Taylor series Σ_{k=1}^{6} (−1)^k x^{2k}/(2k)!: the first term left out,
            // x¹⁴/14!, is < 1e-22 of x²/2 for x ≤ 0.1
            let x = xi * s;
            let y = x * x;
            let mut exact = 0.0;
            for k in (1..=6).rev() {
                let (a, b) = ((2 * k - 1) as f64, (2 * k) as f64);
                exact = -y / (a * b) * (1.0 + exact);
            }
            // the addition theorem's sum cancels by at most (m/s)² ≤ 16 (module docs) on a few
            // ulp: 16·4 ulp
            assert!(
                (m1[i] - exact).abs() <= 64.0 * f64::EPSILON * exact.abs(),
                "{xi} {s}: {} {exact}",
                m1[i]
            );
        }
    }
}

#[test]
fn weights_integrate_polynomials_exactly() {
    // 20-point Gauss–Legendre panels integrate degree-39 polynomials: ∫₁³ s⁹ ds = (3¹⁰ − 1)/10
    let grid = PanelGrid::new(1.0, 3.0, 0.7);
    let integral: f64 = grid
        .nodes()
        .iter()
        .zip(grid.weights())
        .map(|(s, w)| w * s.powi(9))
        .sum();
    let exact = (3f64.powi(10) - 1.0) / 10.0;
    assert!(
        (integral - exact).abs() < 1e-13 * exact,
        "{integral} {exact}"
    );
}

#[test]
fn j0_dot_is_the_row_summed() {
    // the slab's midplane rule sums J₀(ξ_i r) against its weights panel by panel: against the
    // row of `j0_row` summed term by term here, within the rounding of the sums (n ε Σ|w J₀|)
    let grid = PanelGrid::new(0.0, 60.0, 1.5);
    let n = grid.len();
    let w: Vec<f64> = (0..n)
        .map(|i| ((i * 7919) % 101) as f64 / 50.0 - 1.0)
        .collect();
    let mut row = vec![0.0; n];
    for r in [0.0, 0.3, 1.7, 4.0, 25.0, 310.0] {
        grid.j0_row(r, &mut row);
        let plain: f64 = w.iter().zip(&row).map(|(a, b)| a * b).sum();
        let scale: f64 = w.iter().zip(&row).map(|(a, b)| (a * b).abs()).sum();
        let got = grid.j0_dot(r, &w);
        assert!(
            (got - plain).abs() <= n as f64 * f64::EPSILON * scale,
            "r = {r}: {got:e} against {plain:e}"
        );
    }
}
