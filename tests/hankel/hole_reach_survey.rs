//! The single plate with the hole (`single --method hankel`: `single_plate_separation` with
//! `HoleParams::for_tolerance`, the search's root tolerance as the command line sets it) held to
//! its estimates over random geometries across its reach (the survey, ignored): A/D 0.04–15,
//! B/A 1.02–20 (B/D ≤ 16), ν −0.95 to 0.499, C = ∞; each tolerance's R_o against the run at
//! 1e-9, its own estimate added to the bound, and no run claiming `converged` beyond its
//! tolerance.

use super::reach::{survey, Outcome};
use super::two_plate_hole_tiers::plate;
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::SeparationParams;

/// R_o, its estimate and `converged` at `tol`, as `single --method hankel --tol tol`.
fn run(g: (f64, f64, f64), tol: f64) -> Outcome {
    let search = SeparationParams {
        rel_tol: SeparationParams::default().rel_tol.max(1e-3 * tol),
        ..Default::default()
    };
    single_plate_separation(&plate(g), &search, &HoleParams::for_tolerance(tol))
        .map(|(sep, _)| (sep.r_o, sep.r_o_error, sep.converged))
        .map_err(|e| e.to_string())
}

#[test]
fn random_single_plates_are_within_their_estimates() {
    survey(0x6a09_e667_f3bc_c908, (1.02, 20.0), 60, run);
}

#[test]
fn random_narrow_loads_on_single_plates_are_within_their_estimates() {
    survey(0xbb67_ae85_84ca_a73b, (1.001, 1.1), 60, run);
}
