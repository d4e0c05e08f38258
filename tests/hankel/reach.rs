//! The survey driver shared by the holed routes' whole-reach surveys
//! (`hole_reach_survey.rs`, the single plate; `two_plate_hole_reach_survey.rs`, two plates):
//! random geometries from [`Rng::reach_geometry`], each tolerance's R_o against the run at
//! 1e-9, its own estimate added to the bound, and no run claiming convergence beyond its
//! tolerance.

use super::two_plate_hole_tiers::{survey_n, Rng};

/// One run's R_o, its estimate and whether it claims the tolerance; or why it failed.
pub(crate) type Outcome = Result<(f64, f64, bool), String>;

/// The tolerances surveyed.
const TOLERANCES: [f64; 4] = [1e-3, 1e-4, 1e-5, 1e-6];

/// SURVEY_N (else `default_n`) geometries from `seed` with B/A in `ba_lo`–`ba_hi`, each run by
/// `run(geometry, tol)`; prints a line per geometry and per tolerance the largest
/// error/(estimate + reference's) and how many claimed convergence; fails on any failed run,
/// any error beyond that bar, or any claimed convergence whose error passes the tolerance.
pub(crate) fn survey(
    seed: u64,
    (ba_lo, ba_hi): (f64, f64),
    default_n: usize,
    run: impl Fn((f64, f64, f64), f64) -> Outcome,
) {
    let n = survey_n(default_n);
    let mut rng = Rng(seed);
    let mut worst = [(0.0f64, 0usize); 4];
    let mut failures = Vec::new();
    for _ in 0..n {
        let g = rng.reach_geometry(ba_lo, ba_hi);
        let mut line = format!("A/D {:.6} B/A {:.6} nu {:.6}:", g.0, g.1, g.2);
        let (r_ref, e_ref) = match run(g, 1e-9) {
            Ok((r, e, _)) => (r, e),
            Err(e) => {
                line += &format!(" reference failed: {e}");
                println!("{line}");
                failures.push(line);
                continue;
            }
        };
        line += &format!(" ref est {:.1e}", e_ref / r_ref);
        for (w, tol) in worst.iter_mut().zip(TOLERANCES) {
            match run(g, tol) {
                Ok((r, e, converged)) => {
                    let error = (r - r_ref).abs();
                    line += &format!(
                        "  {tol:.0e}: {:.1e}/{:.1e}{}",
                        error / r,
                        e / r,
                        if converged { "" } else { " NC" }
                    );
                    w.0 = w.0.max(error / (e + e_ref));
                    w.1 += usize::from(converged);
                    if error > e + e_ref || (converged && error > tol * r + e_ref) {
                        failures.push(format!("{line} BEYOND"));
                    }
                }
                Err(e) => {
                    line += &format!("  {tol:.0e}: failed ({e})");
                    failures.push(line.clone());
                }
            }
        }
        println!("{line}");
    }
    for (tol, (ratio, conv)) in TOLERANCES.iter().zip(worst) {
        println!("tol {tol:e}: largest error/bar {ratio:.2}, converged {conv} of {n}");
    }
    assert!(failures.is_empty(), "failures: {failures:#?}");
}
