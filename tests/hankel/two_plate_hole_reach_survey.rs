//! The holed route's tiers held to their estimates over its whole reach (the survey, ignored):
//! the tiers' survey (`two_plate_hole_tiers.rs`) samples A/D 0.3–3, B/A 1.1–4, ν 0–0.45, Table
//! 1's neighbourhood; this one samples everything the entry point accepts at C = ∞: A/D from
//! the smallest hole taken (`MIN_A_OVER_D`, 0.04) to 15, B/A 1.02–20 with B/D ≤ `MAX_B_OVER_D`
//! (16), ν from −0.95 to 0.499. Each tier's R_o against the tier for 1e-9, its own estimate
//! added to the bound.
//!
//! Measured (2026-11-25, 30 geometries each, ~4 min each on two cores beside other work):
//! - before the loose tiers doubled their modes (6 and 8 fixed): the tier for 1e-3 found no
//!   contact radius on 5 of 30 (small holes, A/D 0.05–0.19) and on (0.067, 1.58, −0.29) missed
//!   its bar (error 6.6e-3 R_o, estimate 2.4e-3, not converged); the tier for 1e-4 not
//!   converged on 6, estimates up to 0.82 R_o;
//! - after (module `holed_params`): every run within its bar, at most 0.29, 0.27, 0.29, 0.21 of
//!   it for 1e-3 … 1e-6, converged on 28, 30, 30, 30 of 30;
//! - narrow loads (B/A 1.001–1.1, the second survey), the tiers for 1e-5 and 1e-6 with their
//!   modes at most 64: every run within its bar, but at most 0.94 and 0.96 of it there (the
//!   reference's estimate carrying it: (0.206, 1.022, 0.263) at 1e-5 error 1.0e-5 R_o,
//!   estimate 9.7e-6, with 1.6e-3 P left on the hole at 64 modes);
//! - with those modes to 128 and `converged` as `HoledContact::meets` (no claim where the
//!   modes stop short of their residual target): whole reach as above (converged 28, 30, 30,
//!   30 of 30); narrow loads every run within its bar, at most 0.35, 0.50, 0.32, 0.30 of it,
//!   converged on 19, 13, 16, 9 of 30. The reference stops at 128 modes too, so on the
//!   unresolved runs it shares their modes' error: there the survey cannot see it, and those
//!   runs claim nothing.

use super::reach::{survey, Outcome};
use super::two_plate_hole_tiers::plate;
use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};

/// R_o, its estimate and whether it meets `tol` (`HoledContact::meets`), by the knobs for `tol`.
fn run(g: (f64, f64, f64), tol: f64) -> Outcome {
    two_plate_hole(&plate(g), &HoledParams::for_tolerance(tol))
        .map(|out| (out.r_o, out.info.r_o_error, out.meets(tol)))
        .map_err(|e| e.to_string())
}

#[test]
#[ignore = "survey: seconds to a minute per geometry (SURVEY_N, default 30)"]
fn random_geometries_over_the_whole_reach_are_within_their_estimates() {
    survey(0x1f83_d9ab_fb41_bd6b, (1.02, 20.0), 30, run);
}

#[test]
#[ignore = "survey: seconds to a minute per geometry (SURVEY_N, default 30)"]
fn random_narrow_loads_are_within_their_estimates() {
    survey(0x5be0_cd19_137e_2179, (1.001, 1.1), 30, run);
}
