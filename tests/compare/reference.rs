//! The report's tables load, and their printed numbers are consistent with one another within the
//! rounding of the printed digits (a check on the OCR transcription, not on any solver).

use boltzone::reference::{chapter5_interface, table1, table2};
use std::f64::consts::PI;

/// The interval a printed value stands for, given its last printed decimal.
fn rounding_interval(value: f64, half_unit: f64) -> (f64, f64) {
    (value - half_unit, value + half_unit)
}

#[test]
fn table1_discrepancies_follow_from_the_radii() {
    let t = table1();
    assert_eq!(t.len(), 12);
    let d: Vec<f64> = t.iter().map(|r| r.d()).collect();
    assert!((d[0] - 0.1).abs() < 1e-15 && (d[4] - 0.13333333333333333).abs() < 1e-15);
    for r in &t {
        // R_o/A printed to one decimal: each stands for an interval of half-width 0.05.
        let (s0, s1) = rounding_interval(r.single, 0.05);
        let (t0, t1) = rounding_interval(r.two, 0.05);
        let lo = (s0 - t1) / t1 * 100.0;
        let hi = (s1 - t0) / t0 * 100.0;
        assert!(
            (lo..=hi).contains(&r.discrepancy_percent),
            "row A/D={} B/A={}: {} outside [{lo:.1}, {hi:.1}]",
            r.a_over_d,
            r.b_over_a,
            r.discrepancy_percent
        );
        assert!(
            r.single > r.two,
            "the single plate overpredicts in every row"
        );
        assert!(
            r.two > r.b_over_a,
            "contact extends beyond the load in every row"
        );
    }
}

#[test]
fn table2_discrepancies_follow_from_the_diameters() {
    let t = table2();
    assert_eq!(t.len(), 7);
    for r in &t {
        assert!(r.rubbing.min <= r.rubbing.average && r.rubbing.average <= r.rubbing.max);
        // Printed percentages are |computed − tested|/computed to one decimal; the tested averages
        // are printed to 0.01 in, so allow their rounding (±0.005 in) in the check.
        let check = |tested: f64, printed: f64| {
            let lo = ((r.computed - tested).abs() - 0.005) / r.computed * 100.0;
            let hi = ((r.computed - tested).abs() + 0.005) / r.computed * 100.0;
            assert!(
                printed >= lo - 0.05 && printed <= hi + 0.05,
                "case {}: printed {printed} outside [{lo:.2}, {hi:.2}]",
                r.case
            );
        };
        check(r.rubbing.average, r.discrepancy_rubbing_percent);
        if let (Some(m), Some(p)) = (r.autoradiographic, r.discrepancy_autoradiographic_percent) {
            assert!(m.min <= m.average && m.average <= m.max, "case {}", r.case);
            check(m.average, p);
        }
    }
    assert_eq!(t[2].footnote, "*");
    assert_eq!(t[3].footnote, "**");
    assert!(t.iter().filter(|r| r.two_b == 1.0).count() == 2);
}

#[test]
fn chapter5_conductances_follow_from_the_areas() {
    let t = chapter5_interface();
    assert_eq!(t.len(), 3);
    let recomputed: Vec<f64> = t
        .iter()
        .map(|r| PI / 4.0 * (r.r_outer.powi(2) - r.r_inner.powi(2)) / 144.0 * r.h_c)
        .collect();
    // Rows 2 and 3 agree with the printed area·h_c to the printed digit.
    assert!((recomputed[1] - t[1].area_h_c).abs() < 0.05);
    assert!((recomputed[2] - t[2].area_h_c).abs() < 0.05);
    // Row 1 does not: a quarter of the 0.1–0.13 in annulus times 446,000 is 16.8, printed 16.6.
    // Recorded here so that the discrepancy in the 1970 text stays visible.
    assert!((recomputed[0] - 16.78).abs() < 0.01, "{}", recomputed[0]);
    // The stresses fall outward and the radii tile 0.1..0.175 in.
    assert!(t
        .windows(2)
        .all(|w| w[0].sigma_z_psi > w[1].sigma_z_psi && w[0].r_outer == w[1].r_inner));
}
