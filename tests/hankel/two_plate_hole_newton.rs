//! The holed two-plate route's search for R_o by Newton from a predictor
//! (`hankel::receding::holed_search`) and the 1e-6 tier's hole modes doubled until the
//! bilateral plate's residual is 2e-6 P (`HoledParams::for_tolerance`), each against a run
//! that shares the search's function but not its stopping: the same knobs with the root and
//! iteration tolerances at 1e-13, and the tier for 1e-8.

use boltzone::hankel::receding::holed::{two_plate_hole, HoledContact, HoledParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

const A: f64 = 0.1;

/// Geometry (A/D, B/A, ν), A = 0.1, C = ∞ or `c`, by `params`.
fn solve(g: (f64, f64, f64), c: Option<f64>, params: &HoledParams) -> HoledContact {
    let outer = c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    let load = FaceLoad::uniform(A, g.1 * A, 1.0).unwrap();
    let plate = SinglePlate::new(A, outer, A / g.0, Material::new(3.0e7, g.2).unwrap(), load);
    two_plate_hole(&plate.unwrap(), params).unwrap()
}

/// Table 1's geometry (A/D, B/A), ν = 0.3.
fn run(a_over_d: f64, b_over_a: f64, c: Option<f64>, params: &HoledParams) -> HoledContact {
    solve((a_over_d, b_over_a, 0.3), c, params)
}

#[test]
fn narrowest_row_converges_at_1e6_within_its_estimate_of_the_1e8_tier() {
    // (A/D, B/A) = (0.5, 1.3): with 16 modes fixed the half-modes variant (8 modes) moved R_o
    // by 1.65e-6 R_o over an error of 5.1e-8 (not converged at 1e-6). The bilateral residual
    // there is 1.1e-5 P at 16 modes, so the tier doubles to 32 (3.0e-7 P). Measured (with the
    // tier's split variants, 8 solves): estimate 2.1e-7 R_o, |R_o − R_o(1e-8 tier)| 7.7e-9 R_o
    // (0.04 of the estimate), the 1e-8 tier's estimate 4.8e-9.
    let fast = run(0.5, 1.3, None, &HoledParams::for_tolerance(1e-6));
    let tight = run(0.5, 1.3, None, &HoledParams::for_tolerance(1e-8));
    let err = (fast.r_o - tight.r_o).abs();
    println!(
        "1e-6: R_o {} ± {:.1e} ({} solves, bilateral residual {:.1e} P); 1e-8: {} ± {:.1e}; \
         error {:.1e} R_o",
        fast.r_o,
        fast.info.r_o_error / fast.r_o,
        fast.info.solves,
        fast.info.bilateral_residual,
        tight.r_o,
        tight.info.r_o_error / tight.r_o,
        err / fast.r_o
    );
    assert!(
        fast.info.r_o_error <= 1e-6 * fast.r_o,
        "not converged at 1e-6"
    );
    assert!(
        fast.info.bilateral_residual <= 2e-6,
        "the modes did not double"
    );
    assert!(
        err <= fast.info.r_o_error + tight.info.r_o_error,
        "1e-6 tier {} vs 1e-8 tier {}: {err:e} beyond the estimates",
        fast.r_o,
        tight.r_o
    );
}

/// The knobs `p` with the root and iteration tolerances at 1e-13 (the search then runs until
/// its steps are rounding) and no estimate.
fn exact_root(p: HoledParams) -> HoledParams {
    HoledParams {
        rel_tol: 1e-13,
        iteration_tol: 1e-13,
        estimate: false,
        ..p
    }
}

#[test]
fn newton_stops_within_its_root_tolerance() {
    // The Newton search stops on a step below the root tolerance rel_tol·D or, after three
    // points, returns the last point plus a secant step whose error (the secant's
    // (f″/2f′)·s·e′, times 4) is below it. Against the same knobs iterated to 1e-13: the
    // difference must be within rel_tol·D plus the iteration's own noise (φ(c) to rel_tol of
    // p̄(0)/c, over the slope D·f′ ≥ 0.5: 2·rel_tol·D). Rows (1, 3.1), the widest load, and
    // (1, 1.3), the narrowest on A/D = 1, at the tiers for 1e-3 and 1e-6; C = ∞ and
    // C = 1.54 in on (1, 3.1). Measured: 0.01, 0.01, 0.22, 0.10 of the bound (4, 4, 3 radii;
    // 7 crack solves with the rim, the infinite plate's included).
    let cases = [
        (1.0, 3.1, None, 1e-6),
        (1.0, 1.3, None, 1e-6),
        (1.0, 1.3, None, 1e-3),
        (1.0, 3.1, Some(1.54), 1e-3),
    ];
    for (ad, ba, c, tol) in cases {
        let p = HoledParams {
            estimate: false,
            ..HoledParams::for_tolerance(tol)
        };
        let out = run(ad, ba, c, &p);
        let exact = run(ad, ba, c, &exact_root(p));
        let bound = 3.0 * p.rel_tol * A / ad;
        let err = (out.r_o - exact.r_o).abs();
        println!(
            "({ad}, {ba}), C {c:?}, tol {tol:e}: {} solves, R_o − exact root {:+.1e} ({:.2} of \
             the bound)",
            out.info.solves,
            out.r_o - exact.r_o,
            err / bound
        );
        assert!(
            err <= bound,
            "({ad}, {ba}) {c:?} {tol:e}: {err:e} > {bound:e}"
        );
    }
}

#[test]
#[ignore = "study: the 1e-6 tier's knobs one at a time on a thick plate with a narrow load (~20 s)"]
fn tier6_knobs_one_at_a_time() {
    // the tiers survey's geometry where the 1e-6 tier with the modes doubled to 2e-6 P missed
    // its error (1.07e-8 R_o against an estimate of 3.3e-9)
    let g = (
        0.340_626_739_939_247_75,
        1.174_749_879_350_246,
        0.387_643_678_326_079_6,
    );
    let reference = solve(g, None, &HoledParams::for_tolerance(1e-9));
    let base = HoledParams::for_tolerance(1e-6);
    let modes = |target: f64, start: usize| HoledParams {
        hole: boltzone::hankel::hole::HoleParams {
            terms: None,
            start_terms: start,
            max_terms: 128,
            residual_target: target,
            ..base.hole
        },
        ..base
    };
    let variants = [
        ("tier 1e-6", base),
        ("modes to 2e-6 P", modes(2e-6, 16)),
        ("modes to 5e-8 P", modes(5e-8, 32)),
        (
            "hole_decay 18",
            HoledParams {
                hole_decay: 18.0,
                ..base
            },
        ),
        ("tail 14D", HoledParams { tail: 14.0, ..base }),
        (
            "heights 28",
            HoledParams {
                heights: 28,
                ..base
            },
        ),
        ("xi_l 55/D", HoledParams { xi_l: 55.0, ..base }),
        ("nodes 24", HoledParams { nodes: 24, ..base }),
    ];
    for (name, p) in variants {
        let out = solve(g, None, &p);
        println!(
            "{name}: R_o − reference {:+.2e} R_o, estimate {:.2e} R_o, bilateral residual {:.1e} P",
            (out.r_o - reference.r_o) / out.r_o,
            out.info.r_o_error / out.r_o,
            out.info.bilateral_residual
        );
    }
}
