//! The tier of `HoledParams::for_tolerance` for 1e-8 (hole modes doubled from 32 until the
//! bilateral residual is 5e-7 P, 28 heights, ξ_l = 55/D, the hole rule to e^(−18); its coarse
//! variants, each alone: 3/4 of the modes, 2/3 of the heights, 2/3 of ξ_l) held to its
//! estimate: R_o against a run finer in
//! every knob (96 modes, 36 heights, ξ_l = 80/D, tail 20D, 32 Nyström points, the hole rule to
//! e^(−24), root to 1e-12 D; its own estimate added to the bound), on Table 1's narrowest load
//! in CI and over random geometries in the survey (ignored: A/D 0.3–3, B/A 1.1–4, ν 0–0.45, as
//! `two_plate_hole_tiers.rs`). The error must never exceed the estimate, so that `converged`
//! (estimate ≤ 1e-8 R_o) is never claimed above the tolerance.

use super::two_plate_hole_tiers::{run_with as run, survey_n, Rng};
use boltzone::hankel::hole::HoleParams;
use boltzone::hankel::receding::holed::HoledParams;

/// The tier checked.
const TOL: f64 = 1e-8;

/// The reference: finer than the tier in every knob, its estimate's coarse variant at 72 modes.
fn finer() -> HoledParams {
    let base = HoledParams::for_tolerance(TOL);
    HoledParams {
        hole: HoleParams {
            terms: Some(96),
            ..base.hole
        },
        heights: 36,
        xi_l: 80.0,
        tail: 20.0,
        nodes: 32,
        hole_decay: 24.0,
        rel_tol: 1e-12,
        iteration_tol: 1e-13,
        ..base
    }
}

/// (error, estimate) of the tier on `g`, relative to R_o, after checking that the error
/// against the finer run is within the tier's estimate plus the finer run's.
fn check(g: (f64, f64, f64)) -> (f64, f64, f64) {
    let reference = run(g, &finer());
    let out = run(g, &HoledParams::for_tolerance(TOL));
    let err = (out.r_o - reference.r_o).abs();
    let bound = out.info.r_o_error + reference.info.r_o_error;
    assert!(
        err <= bound,
        "(A/D, B/A, ν) = {g:?}: R_o {} vs {} finer, error {err:e} beyond the estimates {bound:e}",
        out.r_o,
        reference.r_o
    );
    (
        err / out.r_o,
        out.info.r_o_error / out.r_o,
        reference.info.r_o_error / out.r_o,
    )
}

#[test]
fn table1_narrowest_thick_row_is_within_the_tier_estimate() {
    // (A/D, B/A) = (0.5, 1.3): the row whose 16-mode defaults err by 5e-8 R_o (their N/2
    // variant said 1.3e-6). Measured: error 1.2e-10 against the estimate 4.8e-9 R_o.
    let (err, est, ref_est) = check((0.5, 1.3, 0.3));
    println!("(0.5, 1.3): error {err:.1e}, estimate {est:.1e}, finer's {ref_est:.1e} of R_o");
    assert!(est <= TOL, "estimate {est:e} of R_o above the tier's 1e-8");
}

/// Measured (SURVEY_N = 30, 992 s at load ~10): every error within its estimate, at most 0.54
/// of it ((A/D, B/A, ν) = (0.347, 1.29, 0.238): 3.3e-10 against 6.2e-10 R_o), estimates
/// 1.3e-12 … 6.4e-9 R_o, all 30 converged at 1e-8. Before the variants were split, 0.82 on
/// (0.819, 1.480, 0.316); with 32 modes fixed, 8.8 (3.5e-9 against 4.0e-10) on the first.
#[test]
#[ignore = "survey: 5-30 s per geometry (SURVEY_N, default 30)"]
fn random_geometries_are_within_the_tier_estimate() {
    let n = survey_n(30);
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    // largest error/estimate, largest estimate, runs claiming convergence
    let mut worst = (0.0f64, 0.0f64, 0usize);
    for _ in 0..n {
        let g = rng.geometry();
        let (err, est, ref_est) = check(g);
        println!(
            "A/D {:.3} B/A {:.3} nu {:.3}: error {err:.1e} estimate {est:.1e} finer's {ref_est:.1e}",
            g.0, g.1, g.2
        );
        worst = (
            worst.0.max(err / est),
            worst.1.max(est),
            worst.2 + usize::from(est <= TOL),
        );
    }
    println!(
        "tier 1e-8: largest error/estimate {:.2}, largest estimate {:.1e}, converged {} of {n}",
        worst.0, worst.1, worst.2
    );
}
