//! The holed two-plate route near its smallest hole (`hankel::receding::MIN_A_OVER_D`, A/D ≥
//! 0.04): the hole's residual traction (`residual_max`, `bilateral_residual`, relative to P)
//! and R_o's estimate against a run finer in every knob (more hole modes, heights, Nyström
//! points, ξ_l, tail), at A/D from 0.3 down to the limit, B/D 1, 3 and 8, ν = 0.3, C = ∞ and a
//! rim C = B + 8D. The question: does the residual grow smoothly toward the limit, and is the
//! estimate honest there (error ≤ estimate)? Ignored (minutes); printed as a table. Found: at
//! C = ∞ the residual grows smoothly and every error is within its estimate; with the rim the
//! estimate misses the Chebyshev heights at every A/D (`rim_knobs_one_at_a_time`; module
//! `hankel::receding::holed::rim`). In CI: the limit A/D = 0.04 against the tier for 1e-8.

use boltzone::hankel::hole::HoleParams;
use boltzone::hankel::receding::holed::{two_plate_hole, HoledContact, HoledParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// The hole radii A/D of the study, largest first.
const A_OVER_D: [f64; 6] = [0.3, 0.2, 0.15, 0.1, 0.06, 0.04];

/// The plate D = 1 with a hole A/D, uniform load out to B/D, ν = 0.3, rim `c` (C = ∞: None).
fn plate(a_over_d: f64, b_over_d: f64, c: Option<f64>) -> SinglePlate {
    SinglePlate::new(
        a_over_d,
        c.map_or(OuterRadius::Infinite, OuterRadius::Finite),
        1.0,
        Material::new(3.0e7, 0.3).unwrap(),
        FaceLoad::uniform(a_over_d, b_over_d, 1.0).unwrap(),
    )
    .unwrap()
}

/// Knobs finer than the tier for 1e-8 in every one (no estimate): the reference.
fn finer() -> HoledParams {
    let base = HoledParams::for_tolerance(1e-8);
    HoledParams {
        hole: HoleParams {
            terms: None,
            start_terms: 64,
            max_terms: 192,
            residual_target: 5e-8,
            ..base.hole
        },
        nodes: 32,
        heights: 36,
        xi_l: 80.0,
        tail: 20.0,
        hole_decay: 22.0,
        rel_tol: 1e-12,
        iteration_tol: 1e-12,
        estimate: false,
        ..base
    }
}

/// One line of the table: the run at `tol` against `reference`, relative to R_o.
fn line(tol: f64, out: &HoledContact, reference: f64) -> String {
    let error = (out.r_o - reference).abs() / reference;
    let estimate = out.info.r_o_error / out.r_o;
    format!(
        "tol {tol:.0e}: residual {:.2e} P, bilateral {:.2e} P, error {error:.2e}, estimate \
         {estimate:.2e}, ratio {:.2}, {:.2} s{}",
        out.info.residual_max,
        out.info.bilateral_residual,
        error / estimate,
        out.info.seconds,
        if error > estimate {
            "  ERROR > ESTIMATE"
        } else {
            ""
        }
    )
}

/// The study on the loads `b_over_d`, each with C = ∞ or the rim C = B + 8D.
fn study(b_over_d: &[f64], rim: bool) {
    for &b in b_over_d {
        for a in A_OVER_D {
            let p = plate(a, b, rim.then_some(b + 8.0));
            let reference = two_plate_hole(&p, &finer()).unwrap();
            println!(
                "B/D {b} A/D {a}{}: R_o {:.12} (finer: residual {:.2e} P, bilateral {:.2e} P, \
                 {:.1} s)",
                if rim { " C = B + 8D" } else { "" },
                reference.r_o,
                reference.info.residual_max,
                reference.info.bilateral_residual,
                reference.info.seconds
            );
            for tol in [1e-6, 1e-8] {
                let out = two_plate_hole(&p, &HoledParams::for_tolerance(tol)).unwrap();
                println!("    {}", line(tol, &out, reference.r_o));
            }
        }
    }
}

/// At the limit A/D = 0.04 (B/D = 1, the study's largest residual, C = ∞): the knobs for 1e-6
/// against the tier for 1e-8 (a run finer in every knob, its estimate added to the bar), and
/// the hole's residual traction far below the 1e1–1e4 P the fuzz found at A/D 0.001–0.005 that
/// set the limit (the study: 2.5e-6 P here, growing smoothly from 1.6e-8 P at A/D 0.3).
#[test]
fn at_the_smallest_hole_the_estimate_covers_a_finer_run() {
    let p = plate(0.04, 1.0, None);
    let fine = two_plate_hole(&p, &HoledParams::for_tolerance(1e-8)).unwrap();
    let out = two_plate_hole(&p, &HoledParams::for_tolerance(1e-6)).unwrap();
    let error = (out.r_o - fine.r_o).abs();
    println!(
        "A/D 0.04, B/D 1: error {error:.2e} D, estimate {:.2e} D (+ {:.2e}), residual {:.2e} P",
        out.info.r_o_error, fine.info.r_o_error, out.info.residual_max
    );
    assert!(error <= out.info.r_o_error + fine.info.r_o_error);
    assert!(out.info.r_o_error <= 1e-6 * out.r_o, "converged at 1e-6");
    // a sentinel six orders below the fuzz's smallest failure (1e1 P), 4× the study's value
    assert!(out.info.residual_max < 1e-5, "{}", out.info.residual_max);
}

#[test]
#[ignore = "study: minutes of CPU"]
fn small_holes_infinite_plate() {
    study(&[1.0, 3.0, 8.0], false);
}

#[test]
#[ignore = "study: minutes of CPU"]
fn small_holes_with_a_rim() {
    study(&[1.0, 3.0, 8.0], true);
}

/// Which knob moves the rim's R_o: the tier for 1e-8 with one knob at a time set to the
/// reference's, on B/D = 1, A/D = 0.1, C = B + 8D (where the rim's error was 107× its estimate).
#[test]
#[ignore = "study: a minute of CPU"]
fn rim_knobs_one_at_a_time() {
    let p = plate(0.1, 1.0, Some(9.0));
    let f = finer();
    let tier = HoledParams {
        estimate: false,
        ..HoledParams::for_tolerance(1e-8)
    };
    let reference = two_plate_hole(&p, &f).unwrap().r_o;
    let variants = [
        ("tier for 1e-8", tier),
        (
            "heights 36",
            HoledParams {
                heights: 36,
                ..tier
            },
        ),
        (
            "heights 44",
            HoledParams {
                heights: 44,
                ..tier
            },
        ),
        (
            "heights 56",
            HoledParams {
                heights: 56,
                ..tier
            },
        ),
        ("nodes 32", HoledParams { nodes: 32, ..tier }),
        ("xi_l 80", HoledParams { xi_l: 80.0, ..tier }),
        ("tail 20", HoledParams { tail: 20.0, ..tier }),
        (
            "modes",
            HoledParams {
                hole: f.hole,
                ..tier
            },
        ),
        (
            "hole_decay 22",
            HoledParams {
                hole_decay: 22.0,
                ..tier
            },
        ),
        (
            "root 1e-12",
            HoledParams {
                rel_tol: 1e-12,
                iteration_tol: 1e-12,
                ..tier
            },
        ),
    ];
    for (name, params) in variants {
        let out = two_plate_hole(&p, &params).unwrap();
        println!(
            "{name}: R_o − reference {:+.2e} R_o ({:.1} s)",
            (out.r_o - reference) / reference,
            out.info.seconds
        );
    }
}

/// With a rim (B/D = 1, A/D = 0.1, C = 9D) the Chebyshev heights converge slowly (S₂'s lift
/// holds ln r): the knobs for 1e-6 against the tier for 1e-8 and a run with 56 heights, within
/// the estimates. Before the rim's estimate had its heights variant the 1e-6 knobs were
/// 7.4× and the 1e-8 tier 107× outside theirs here (`small_holes_with_a_rim`).
#[test]
fn with_a_rim_the_estimate_covers_the_heights() {
    let p = plate(0.1, 1.0, Some(9.0));
    let loose = two_plate_hole(&p, &HoledParams::for_tolerance(1e-6)).unwrap();
    let tight = two_plate_hole(&p, &HoledParams::for_tolerance(1e-8)).unwrap();
    let heights = HoledParams {
        heights: 56,
        ..finer()
    };
    let reference = two_plate_hole(&p, &heights).unwrap();
    for (tol, out) in [(1e-6, &loose), (1e-8, &tight)] {
        println!("{}", line(tol, out, reference.r_o));
        assert!(
            (out.r_o - reference.r_o).abs() <= out.info.r_o_error,
            "tol {tol:e}: {} against {}",
            out.r_o,
            reference.r_o
        );
    }
    assert!((loose.r_o - tight.r_o).abs() <= loose.info.r_o_error + tight.info.r_o_error);
}
