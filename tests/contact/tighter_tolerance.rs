//! Asking the two-plate FE for more than it can give (a tolerance below its 2e-5 R_o floor)
//! never returns a worse answer than a looser tolerance: the study refines as it would for the
//! floor and reports `converged: false`. Before the fix, Table 1's (1, 1.3) joint with the
//! report's rim C = 1.54 in stopped at level 5 at `--tol 1e-6` with an estimate of 4.5e-3 R_o,
//! where `--tol 1e-5` went on to 2.7e-5 R_o.

use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::{Joint, Material, OuterRadius};

#[test]
fn a_tighter_tolerance_never_returns_a_larger_estimate() {
    let joint = Joint::symmetric(0.1, 0.13, 0.1, Material::new(3.0e7, 0.3).unwrap())
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(1.54))
        .unwrap();
    let run = |tolerance: f64| {
        let params = TwoPlateParams {
            tolerance,
            ..TwoPlateParams::default()
        };
        solve(&joint, &params).unwrap()
    };
    let loose = run(1e-5);
    for tol in [1e-6, 1e-9] {
        let tight = run(tol);
        assert!(
            !tight.converged,
            "tol {tol:e}: below the floor, never converged"
        );
        assert!(
            tight.r_o_error <= loose.r_o_error,
            "tol {tol:e}: estimate {} against {} at 1e-5",
            tight.r_o_error,
            loose.r_o_error
        );
        // and the two answers agree within the looser one's bar
        assert!((tight.r_o - loose.r_o).abs() <= loose.r_o_error);
    }
}
