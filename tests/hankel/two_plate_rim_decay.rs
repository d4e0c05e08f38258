//! The rim's decay bound D·e^(−4.21(C − R_o)/D) (module `hankel::receding::holed::rim`), which
//! the holed route with a rim adds to R_o's estimate for the self-equilibrated residue its
//! bending correction leaves: measured against the FE two-plate model meshed to C (shares no
//! code) on rims near R_o, where the bound is large enough for the FE to see the residue's
//! effect. Ignored (FE at --tol 1e-5: tens of seconds per rim).

use boltzone::contact::params::TwoPlateParams;
use boltzone::contact::two_plate::solve;
use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, SinglePlate};

/// (|FE − Hankel|, the FE's estimate, the decay bound), in D, for (A/D, B/A) with the rim
/// `k` plate thicknesses beyond the infinite plate's R_o (A = 0.1, ν = 0.3).
fn shift(a_over_d: f64, b_over_a: f64, k: f64) -> (f64, f64, f64) {
    let (a, d) = (0.1, 0.1 / a_over_d);
    let mat = Material::new(3.0e7, 0.3).unwrap();
    let plate = |c| {
        let load = FaceLoad::uniform(a, a * b_over_a, 1.0).unwrap();
        SinglePlate::new(a, c, d, mat, load).unwrap()
    };
    let params = HoledParams::for_tolerance(1e-6);
    let r_inf = two_plate_hole(&plate(OuterRadius::Infinite), &params)
        .unwrap()
        .r_o;
    let c = r_inf + k * d;
    let h = two_plate_hole(&plate(OuterRadius::Finite(c)), &params).unwrap();
    let bound = h.info.rim.map(|r| r.decay_bound).unwrap();
    let joint = Joint::symmetric(a, a * b_over_a, d, mat)
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(c))
        .unwrap();
    let fe_params = TwoPlateParams {
        tolerance: 1e-5,
        ..TwoPlateParams::default()
    };
    let fe = solve(&joint, &fe_params).unwrap();
    ((fe.r_o - h.r_o).abs() / d, fe.r_o_error / d, bound / d)
}

/// Measured (CLI runs of the same comparison, 2026-11-25, (A/D, B/A) = (1, 2.2)): at
/// C − R_o = 0.6, 1.0, 1.5, 2.0 D, |FE − H| = 3.7e-4, 2.3e-5, 9.2e-7, 7.7e-7 D against bounds
/// 6.9e-2, 1.3e-2, 1.6e-3, 2.0e-4 D (the FE's estimate 8.5e-5 D): at 0.6D, where the FE
/// resolves it, the residue's shift is at most 0.005 of the bound; beyond 1D it is within the
/// FE's own error; (0.5, 1.6) at 0.6D: 3.8e-4 D against 6.4e-2 D (FE estimate 3.9e-5 D).
#[test]
#[ignore = "FE meshed to C at --tol 1e-5: tens of seconds per rim"]
fn the_decay_bound_covers_the_rims_residue() {
    for (ad, ba) in [(1.0, 2.2), (0.5, 1.6)] {
        for k in [0.6, 1.0] {
            let (diff, fe_est, bound) = shift(ad, ba, k);
            println!(
                "(A/D, B/A) = ({ad}, {ba}), C − R_o = {k} D: |FE − H| {diff:.2e} D, FE estimate \
                 {fe_est:.1e} D, bound {bound:.2e} D, (|FE − H| − FE est)/bound {:.1e}",
                (diff - fe_est) / bound
            );
            assert!(diff <= bound + fe_est, "the rim's shift beyond its bound");
        }
    }
}
