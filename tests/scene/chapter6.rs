//! Chapter VI's gap figure (`examples/scenes/chapter6_pair.toml`): the report's "98.6
//! microinches at the outer radius of the plate of 2 inches" for the 1/4 in pair (Table 2
//! case 4). The rim gap is linear in the load and R_o is not load-dependent (identities checked
//! here: the solver scales stresses by the bearing pressure, so R_o is the same bits at any
//! load and the gap scales by the load ratio to round-off); at the test's 1100 lb (P = 12,501
//! psi) the rim gap is 124.5 µin, 26 % above the report, and at a nominal P = 10,000 psi it is
//! 99.6 µin, 1.0 % above: the scene's comments give the assumption and the variants tried.

use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::f64::consts::PI;

/// R_o (in) and the gap at r = C (µin) of the case 4 pair at bearing pressure `p` psi.
fn rim_gap(p: f64) -> (f64, f64) {
    let steel = Material::new(28.0e6, 0.3).unwrap();
    let joint = Joint::new(
        0.1285,
        OuterRadius::Finite(2.0),
        Plate::new(0.253, steel).unwrap(),
        Plate::new(0.253, steel).unwrap(),
        FaceLoad::uniform(0.1285, 0.211, p).unwrap(),
    )
    .unwrap();
    let s = solve(&joint, &TwoPlateParams::default()).unwrap();
    assert!(s.converged);
    assert_eq!(s.radius.last().copied(), Some(2.0));
    (s.r_o, s.gap.last().unwrap() * 1e6)
}

#[test]
fn chapter6_rim_gap_at_the_test_load_and_at_10000_psi() {
    let p_test = 1100.0 / (PI * (0.211f64.powi(2) - 0.1285f64.powi(2)));
    assert!((p_test - 12501.0).abs() < 1.0, "P = {p_test} psi");
    let (r_test, g_test) = rim_gap(p_test);
    let (r_nominal, g_nominal) = rim_gap(10_000.0);
    // identities: R_o independent of the load, the gap proportional to it
    assert_eq!(r_test.to_bits(), r_nominal.to_bits());
    let ratio = g_nominal / g_test / (10_000.0 / p_test);
    assert!((ratio - 1.0).abs() < 1e-12, "gap ratio {ratio}");
    // against the report's 98.6 µin: the test load misses by a quarter, the nominal 10,000 psi
    // comes within 1.1 % (measured 1.0 %)
    let off = |g: f64| (g - 98.6).abs() / 98.6;
    assert!(off(g_test) > 0.2, "{g_test} µin at 1100 lb");
    assert!(off(g_nominal) < 0.011, "{g_nominal} µin at 10,000 psi");
}
