//! `two_plate_hole_to`: the knobs for the tolerance, and the next tier's when their run falls
//! short (module `holed`'s docs), on geometries the whole-reach survey
//! (`two_plate_hole_reach_survey.rs`) found: small holes, where the tier for 1e-3 with its former
//! 6 fixed modes found no contact radius or missed its estimate. And `two --method auto` (and a
//! scene's `method = "auto"`), which hand a hole the modes leave unresolved to the finite
//! elements.

use super::two_plate_hole_tiers::{plate, plate_with};
use boltzone::hankel::receding::holed::{
    two_plate_hole, two_plate_hole_to, HoledContact, HoledParams,
};
use boltzone::OuterRadius;

/// |R_o − reference| within the run's estimate plus the reference's.
fn within(out: &HoledContact, reference: &HoledContact) -> bool {
    (out.r_o - reference.r_o).abs() <= out.info.r_o_error + reference.info.r_o_error
}

#[test]
fn the_loose_tiers_reach_small_holes() {
    // (0.186, 1.456, −0.176): with 6 fixed modes the tier for 1e-3 found no contact radius
    // (the edge coefficient of one sign from B to B + 8D) and the tier for 1e-4 estimated
    // 1.2e-3 R_o; (0.067, 1.58, −0.29): 6.1 P left on the hole, R_o off by 6.6e-3 against an
    // estimate of 2.4e-3 R_o. Measured now (the modes doubled to 1e-3 and 1e-4 P): errors
    // 9.7e-6, 1.5e-6 and 4.2e-6, 8.2e-7 R_o against estimates 1.1e-4, 9.8e-6 and 9.7e-5,
    // 9.4e-6, at most 0.15 of them; bilateral residuals 1.4e-4 … 8.7e-6 P; all converged.
    for g in [
        (0.185529, 1.456349, -0.175678),
        (0.067285, 1.580153, -0.294051),
    ] {
        let p = plate(g);
        let reference = two_plate_hole(&p, &HoledParams::for_tolerance(1e-9)).unwrap();
        for tol in [1e-3, 1e-4] {
            let out = two_plate_hole(&p, &HoledParams::for_tolerance(tol)).unwrap();
            println!(
                "{g:?} tol {tol:e}: error {:.1e}, estimate {:.1e} R_o, bilateral residual {:.1e} P",
                (out.r_o - reference.r_o).abs() / reference.r_o,
                out.info.r_o_error / out.r_o,
                out.info.bilateral_residual
            );
            assert!(within(&out, &reference), "{g:?} at {tol:e}");
            assert!(out.meets(tol), "{g:?} at {tol:e} not converged");
        }
    }
}

#[test]
fn a_run_short_of_its_tolerance_is_handed_to_the_next_tier() {
    // (0.268, 3.00, 0.253): the tier for 1e-3 estimates 1.1e-3 R_o (its error 3.5e-6 R_o).
    let p = plate((0.267605, 3.002807, 0.252935));
    let first = two_plate_hole(&p, &HoledParams::for_tolerance(1e-3)).unwrap();
    assert!(
        first.info.r_o_error > 1e-3 * first.r_o,
        "the geometry no longer needs a handover"
    );
    let (out, _) = two_plate_hole_to(&p, 1e-3, &[]).unwrap();
    let second = two_plate_hole(&p, &HoledParams::for_tolerance(1e-4)).unwrap();
    assert_eq!(out.r_o, second.r_o);
    assert_eq!(out.info.r_o_error, second.info.r_o_error);
    assert!(out.info.r_o_error <= 1e-3 * out.r_o);
    let reference = two_plate_hole(&p, &HoledParams::for_tolerance(1e-9)).unwrap();
    assert!(within(&out, &reference));
}

#[test]
fn a_run_that_meets_its_tolerance_or_hits_the_rim_is_not_handed_on() {
    // Table 1's first row at 1e-3: the tier's own run
    let p = plate((1.0, 3.1, 0.3));
    let own = two_plate_hole(&p, &HoledParams::for_tolerance(1e-3)).unwrap();
    let (out, _) = two_plate_hole_to(&p, 1e-3, &[]).unwrap();
    assert_eq!((out.r_o, out.info.solves), (own.r_o, own.info.solves));
    // a rim 1.5D beyond B: its residue's bound alone is over 1e-6 R_o, which no tier lowers
    let g = (1.0, 2.2, 0.3);
    let p = plate_with(g, OuterRadius::Finite(0.22 + 1.5 * 0.1));
    let own = two_plate_hole(&p, &HoledParams::for_tolerance(1e-6)).unwrap();
    let rim = own.info.rim.as_ref().unwrap().decay_bound;
    assert!(rim > 1e-6 * own.r_o, "decay bound {rim:e}");
    let (out, _) = two_plate_hole_to(&p, 1e-6, &[]).unwrap();
    assert_eq!((out.r_o, out.info.solves), (own.r_o, own.info.solves));
}

#[test]
fn bad_input_is_returned_at_once() {
    let p = plate((1.0, 3.1, 0.3));
    assert!(two_plate_hole_to(&p, 1e-3, &[1.5]).is_err());
}

#[test]
fn a_hole_the_modes_do_not_resolve_claims_no_tolerance() {
    // a narrow load on a small hole: the tier for 1e-4's modes stop at 64 with 1.6e-3 P left
    // on the hole (target 1e-4 P), its estimate 1.6e-5 R_o; the tier for 1e-5 with its modes
    // at most 64 (as they were) estimated 9.7e-6 R_o for an error of 9.4e-6 against a run to
    // 256 modes (module `holed_record`), too close to trust
    let g = (0.205524, 1.022406, 0.263163);
    let p = plate(g);
    let out = two_plate_hole(&p, &HoledParams::for_tolerance(1e-4)).unwrap();
    assert!(
        out.info.bilateral_residual > 1e-4,
        "{:e}",
        out.info.bilateral_residual
    );
    assert!(!out.info.hole_resolved);
    assert!(
        out.info.r_o_error <= 1e-4 * out.r_o,
        "the estimate alone would claim 1e-4"
    );
    assert!(!out.meets(1e-4));
    // Table 1's narrowest load resolves
    let t1 = two_plate_hole(&plate((1.0, 1.3, 0.3)), &HoledParams::for_tolerance(1e-4)).unwrap();
    assert!(t1.info.hole_resolved && t1.meets(1e-4));
    // the command line (every tier to 1e-6 unresolved) says so and exits 3
    let d = format!("{}", 0.1 / g.0);
    let b = format!("{}", 0.1 * g.1);
    let nu = format!("{}", g.2);
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args([
            "two", "--method", "hankel", "--a", "0.1", "--b", &b, "--d", &d, "--nu", &nu,
        ])
        .args(["--tol", "1e-4"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&run.stdout);
    assert_eq!(run.status.code(), Some(3), "{text}");
    assert!(text.contains("hole modes stopped short"), "{text}");
}

#[test]
fn an_unresolved_hole_goes_on_only_to_a_tier_with_more_modes() {
    // the narrow load above: the tier for 1e-3 stops at 64 modes short of 1e-3 P, and so would
    // the tier for 1e-4 (also at most 64): its run is returned as it is
    let p = plate((0.205524, 1.022406, 0.263163));
    let own = two_plate_hole(&p, &HoledParams::for_tolerance(1e-3)).unwrap();
    assert!(!own.info.hole_resolved);
    let (out, _) = two_plate_hole_to(&p, 1e-3, &[]).unwrap();
    assert_eq!((out.r_o, out.info.solves), (own.r_o, own.info.solves));
    // from 1e-4 (at most 64 modes) it goes on to the tier for 1e-5 (at most 128), and no further
    let (out, _) = two_plate_hole_to(&p, 1e-4, &[]).unwrap();
    let next = two_plate_hole(&p, &HoledParams::for_tolerance(1e-5)).unwrap();
    assert_eq!((out.r_o, out.info.solves), (next.r_o, next.info.solves));
}

/// `two --method M --tol T --json` on the narrow load above (A = 0.1): the exit code and the JSON.
fn two_json(method: &str, tol: &str) -> (Option<i32>, serde_json::Value) {
    let g = (0.205524, 1.022406, 0.263163);
    let (d, b, nu) = (0.1 / g.0, 0.1 * g.1, g.2);
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args([
            "two", "--method", method, "--a", "0.1", "--tol", tol, "--json",
        ])
        .args([
            "--b",
            &b.to_string(),
            "--d",
            &d.to_string(),
            "--nu",
            &nu.to_string(),
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&run.stdout);
    (run.status.code(), serde_json::from_str(&text).unwrap())
}

#[test]
fn auto_hands_an_unresolved_hole_to_the_finite_elements() {
    // below 3e-5 `auto` takes the Hankel route, whose modes stop at 128 short of their target
    // here: its ± is no bound, so the finite elements answer, and say why
    let (code, auto) = two_json("auto", "2e-5");
    let (fem_code, fem) = two_json("fem", "2e-5");
    assert_eq!(auto["method"], "fem");
    let why = auto["fallback"].as_str().unwrap();
    assert!(why.contains("hole modes stopped short"), "{why}");
    assert_eq!((code, &auto["r_o"]), (fem_code, &fem["r_o"]));
    assert!(fem.get("fallback").is_none());
    // the declined run lies within both bars of the answer
    let (hankel_code, hankel) = two_json("hankel", "2e-5");
    assert_eq!(hankel_code, Some(3));
    assert_eq!(hankel["hankel"]["hole_resolved"], false);
    let f = |v: &serde_json::Value, k: &str| v[k].as_f64().unwrap();
    let gap = (f(&hankel, "r_o") - f(&fem, "r_o")).abs();
    assert!(
        gap <= f(&hankel, "r_o_error") + f(&fem, "r_o_error"),
        "{gap:e}"
    );
    // a scene with `method = "auto"` does the same, its plan saying so
    let scene = |method: &str| {
        let g = (0.205524, 1.022406, 0.263163);
        let text = format!(
            "model = \"two-plate\"\nmethod = \"{method}\"\ntolerance = 2e-5\n[hole]\nradius = 0.1\n\
             [load]\nouter_radius = {}\npressure = 1.0\n[[plates]]\nthickness = {}\n\
             material = {{ E = 28e6, nu = {} }}\n",
            0.1 * g.1,
            0.1 / g.0,
            g.2
        );
        boltzone::scene::solve(&boltzone::scene::Scene::parse(&text).unwrap()).unwrap()
    };
    let (s, by_fem) = (scene("auto"), scene("fem"));
    assert_eq!(s.method, boltzone::scene::Method::Fem);
    assert_eq!((s.r_o, s.converged), (by_fem.r_o, by_fem.converged));
    let step = s.plan.iter().find(|p| p.name == "hankel route").unwrap();
    assert!(
        step.ran && step.note.starts_with("declined: the hole modes"),
        "{}",
        step.note
    );
}
