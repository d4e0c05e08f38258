//! The infinite plate of the semi-analytic two-plate route with the hole ([`super`]):
//! the geometry's setup, the search for R_o over trial contact radii (module `search`),
//! the error estimate's variant runs and the interface pressure at the radii asked for. The
//! finite rim (module `rim`) starts from it.
//!
//! # Accuracy
//!
//! As [`super`]: `tests/hankel/two_plate_hole.rs`, `tests/hankel/two_plate_hole_fast.rs`,
//! `tests/hankel/two_plate_hole_tiers.rs`.
//!
//! # Cost
//!
//! The route's whole cost at C = ∞ (example 19).
//!
//! ```
//! // Internal to the route; reached through its entry point:
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let _ = (two_plate_hole, HoledParams::default());
//! ```

use super::params::HoledParams;
use super::record::{HoledContact, HoledInfo};
use super::search::{estimate, fraction_radius};
use super::setup::Setup;
use crate::hankel::receding::contact::RecedingError;
use crate::joint::SinglePlate;
use std::time::Instant;

/// R_o of the infinite `plate` and the pressure at the fractions `at` of [A, R_o] (checked by
/// the caller): [`super::two_plate_hole_pressure`] at C = ∞.
pub(super) fn solve(
    plate: &SinglePlate,
    params: &HoledParams,
    at: &[f64],
) -> Result<(HoledContact, Vec<(f64, f64)>), RecedingError> {
    let start = Instant::now();
    let setup = Setup::new(plate, params)?;
    let (mut out, curve, _) = solve_on(&setup, plate, params, at)?;
    out.info.seconds = start.elapsed().as_secs_f64();
    Ok((out, curve))
}

/// R_o with its record, the pressure curve (r, q) and the edge coefficient's slope at R_o.
pub(super) type Solved = (HoledContact, Vec<(f64, f64)>, Option<f64>);

/// As [`solve`] on a `setup` built for `plate` and `params` (module `rim` shares it with
/// the rim's solves); `seconds` counts from this call, not the setup's. Also the edge
/// coefficient's slope at R_o, where the search's edge values give it (the rim's Newton start).
pub(super) fn solve_on(
    setup: &Setup,
    plate: &SinglePlate,
    params: &HoledParams,
    at: &[f64],
) -> Result<Solved, RecedingError> {
    let start = Instant::now();
    let b = plate.load().outer();
    let found = setup.search(b, params.nodes, params, None, at)?;
    let (r_o, last) = (found.r_o, &found.last);
    let curve: Vec<(f64, f64)> = at
        .iter()
        .map(|&x| fraction_radius(setup.a, r_o, x))
        .zip(last.pressure.iter().copied())
        .collect();
    let mut info = HoledInfo {
        r_o_error: params.rel_tol * setup.d,
        r_o_fewer_nodes: f64::NAN,
        r_o_half_terms: f64::NAN,
        residual_max: last.residual,
        bilateral_residual: setup.bilateral.info().residual_max,
        hole_resolved: params.hole.terms.is_some()
            || setup.bilateral.info().residual_max <= params.hole.residual_target,
        crack_traction: last.crack_traction,
        iterations: last.iterations,
        search_iterations: found.iterations,
        solves: 0,
        seconds: 0.0,
        rim: None,
    };
    let mut solves = found.solves;
    if params.estimate {
        let ((r1, r2), spread, s) = estimate(setup, plate, params, &found)?;
        solves += s;
        info.r_o_fewer_nodes = r1;
        info.r_o_half_terms = r2;
        info.r_o_error += (r1 - r_o).abs() + spread;
    }
    info.solves = solves;
    info.seconds = start.elapsed().as_secs_f64();
    Ok((HoledContact { r_o, info }, curve, found.slope(setup.d)))
}
