//! The two-plate model's finite rim r = C, measured with the FE two-plate model (which meshes
//! the rim) against the semi-analytic route's C = ∞ (which shares no code with it).
//!
//! Plate theory predicts the rim's effect: beyond R_o each plate is a free annular plate whose
//! infinite-plate moment decays like r⁻²; a free rim at C needs a uniform bending state of
//! curvature ∝ C⁻² to cancel it, which tilts the contact zone by ∝ C⁻², so R_o(C) − R_o(∞) ∝ C⁻²
//! (algebraic: not the e^(−2.1(C − R_o)/D) of the symmetric single plate).
//!
//! Measured (release, load ≈ 4 on 2 cores, 3.8 s): Hankel C = ∞ R_o = 0.3524229817 in
//! (± 1.1e-11); FE minus that −2.653e-4, −6.758e-5, −1.671e-5 in at C = 1.54, 3.08, 6.16 in
//! (observed rates 1.97, 2.02); the C⁻² extrapolation lands 2.5e-7 in (7e-7 R_o) from the
//! Hankel value, its bar 3.6e-5 in. On row 2 (B/A = 2.2, CLI runs) the rates were 1.95, 1.99,
//! 2.03 over C = 0.77 … 6.16 in. So at the report's C = 1.54 in the rim moves R_o by 7.5e-4 R_o,
//! and even a rim 40D beyond B moves it by ≈ 1e-4 R_o: a finite-C Hankel route must free the
//! rim of each plate's bending moment, not only of self-equilibrated tractions.

use boltzone::contact::params::TwoPlateParams;
use boltzone::contact::two_plate::solve;
use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, SinglePlate};

/// Table 1's first row (A/D = 1, B/A = 3.1, A = 0.1 in), ν = 0.3.
const A: f64 = 0.1;
const B: f64 = 0.31;
const D: f64 = 0.1;

#[test]
fn the_fe_rim_effect_extrapolates_to_the_hankel_infinite_plate() {
    // FE R_o at C = 1.54, 3.08, 6.16 in (tol 1e-4; estimate carries 2e-5 R_o) minus the Hankel
    // route's C = ∞: the differences fall like C⁻², and the Richardson extrapolation in C⁻² of
    // the two widest rims must meet the Hankel C = ∞ value within the propagated error bars.
    let mat = Material::new(3.0e7, 0.3).unwrap();
    let load = FaceLoad::uniform(A, B, 1.0).unwrap();
    let plate = SinglePlate::new(A, OuterRadius::Infinite, D, mat, load).unwrap();
    let h = two_plate_hole(&plate, &HoledParams::default()).unwrap();
    let params = TwoPlateParams {
        tolerance: 1e-4,
        ..TwoPlateParams::default()
    };
    let fe: Vec<(f64, f64, f64)> = [1.54, 3.08, 6.16]
        .iter()
        .map(|&c| {
            let joint = Joint::symmetric(A, B, D, mat)
                .unwrap()
                .with_outer_radius(OuterRadius::Finite(c))
                .unwrap();
            let out = solve(&joint, &params).unwrap();
            assert!(out.converged, "C = {c}: {:?}", out.r_o_error);
            (c, out.r_o, out.r_o_error)
        })
        .collect();
    println!(
        "Hankel C = inf: R_o = {:.10} in ± {:.1e} in",
        h.r_o, h.info.r_o_error
    );
    for (c, r, e) in &fe {
        println!(
            "FE C = {c} in: R_o = {r:.7} in ± {e:.1e} in, minus Hankel(inf) {:+.3e} in",
            r - h.r_o
        );
    }
    for w in fe.windows(3) {
        let rate = ((w[0].1 - h.r_o) / (w[1].1 - h.r_o)).log2();
        let rate2 = ((w[1].1 - h.r_o) / (w[2].1 - h.r_o)).log2();
        println!("observed rates in C: {rate:.3}, {rate2:.3}");
    }
    let (r2, e2) = (fe[1].1, fe[1].2);
    let (r3, e3) = (fe[2].1, fe[2].2);
    // C = 1.54 in: the rim shortens R_o by more than both error bars together
    assert!(fe[0].1 - h.r_o < -(fe[0].2 + h.info.r_o_error));
    let r_inf = r3 + (r3 - r2) / 3.0;
    let bar = (4.0 * e3 + e2) / 3.0 + h.info.r_o_error;
    println!(
        "Richardson (C⁻²): {r_inf:.8} in, minus Hankel {:+.2e} in, bar {bar:.1e} in",
        r_inf - h.r_o
    );
    assert!((r_inf - h.r_o).abs() <= bar);
}
