//! R_o of the single plate with a hole: the first radius beyond B where the midplane σ_z of
//! slab (extended load) + hole correction turns tensile. An outward scan from B in steps of
//! `step`·D finds the first compressive→tensile sign change; the Illinois variant of regula falsi
//! (Dowell & Jarratt, *BIT* 11 (1971) 168) narrows it. The midplane σ_z is a
//! [`MidplaneRule`] of the slab (one node set for all radii) plus the modes' closed forms.

use super::{HoleInfo, HoleParams, HolePlate};
use crate::error::positive;
use crate::hankel::midplane::MidplaneRule;
use crate::hankel::separation::{SeparationError, SeparationInfo, SeparationParams};
use crate::joint::SinglePlate;
use std::time::Instant;

/// R_o of `plate` with its hole made traction-free (see [`super`]); the hole's fit is
/// described by the returned [`HoleInfo`]. R_o's error estimate is the bracket half-width plus
/// (slab quadrature error + max hole residual·P)/slope at R_o.
pub fn single_plate_separation(
    plate: &SinglePlate,
    sep: &SeparationParams,
    hole: &HoleParams,
) -> Result<(SeparationInfo, HoleInfo), SeparationError> {
    let start = Instant::now();
    positive("R_o relative tolerance", sep.rel_tol)?;
    positive("scan step", sep.step)?;
    positive("scan reach", sep.reach)?;
    let mut holed = HolePlate::with_terms(plate, hole, hole.terms.unwrap_or(hole.start_terms))?;
    let d = plate.half_thickness();
    let b = plate.load().outer();
    let r_end = b + sep.reach * d;
    let p_ref = plate.load().mean_pressure().abs();
    let sigma_tol = (1e-3 * sep.rel_tol * p_ref).max(1e-15 * p_ref);
    let rule = MidplaneRule::new(holed.slab(), r_end, sigma_tol)?;
    let sign = plate.load().total_force().signum();
    let mut evaluations = 0;
    let mut previous: Option<f64> = None;
    loop {
        let mut f = |r: f64| {
            evaluations += 1;
            sign * (rule.eval(r).value + holed.correction_midplane(r))
        };
        let (r_o, half_width) = first_upward_zero(&mut f, b, r_end, sep)?;
        let dr = (1e-4 * d).max(1e-6 * r_o);
        let slope = (f(r_o + dr) - f(r_o - dr)) / (2.0 * dr);
        let residual_max = holed.info().residual_max;
        let change = previous.map(|p| (r_o - p).abs());
        let converged = residual_max <= hole.residual_target
            || change.is_some_and(|c| c <= hole.r_o_tolerance * r_o);
        if hole.terms.is_some() || converged || !holed.refine() {
            // Hole error: the last change of R_o under doubling N (the residual falls
            // algebraically, so the change bounds the remaining error), or with a single N the
            // bound max residual·P / slope.
            let hole_error = change.unwrap_or(residual_max * p_ref / slope.abs());
            let error = half_width + rule.eval(r_o).error / slope.abs() + hole_error;
            let sep_info = SeparationInfo {
                r_o,
                error,
                evaluations,
                slope,
                nodes: rule.nodes(),
                seconds: start.elapsed().as_secs_f64(),
            };
            return Ok((sep_info, holed.info().clone()));
        }
        previous = Some(r_o);
    }
}

/// The first compressive→tensile sign change of `f` in (b, r_end], by an outward scan in steps
/// of `step`·D and Illinois on the bracket: (root, bracket half-width).
fn first_upward_zero(
    f: &mut impl FnMut(f64) -> f64,
    b: f64,
    r_end: f64,
    sep: &SeparationParams,
) -> Result<(f64, f64), SeparationError> {
    let h = sep.step * (r_end - b) / sep.reach;
    let (mut lo, mut f_lo) = (b, f(b));
    for k in 1.. {
        let hi = (b + k as f64 * h).min(r_end);
        let f_hi = f(hi);
        if f_lo <= 0.0 && f_hi > 0.0 {
            return Ok(illinois(
                f,
                (lo, f_lo),
                (hi, f_hi),
                sep.rel_tol * b * 0.25,
                sep.max_iterations,
            ));
        }
        (lo, f_lo) = (hi, f_hi);
        if hi >= r_end {
            break;
        }
    }
    Err(SeparationError::NotFound { searched_to: r_end })
}

/// Illinois regula falsi on a bracket with f(a) ≤ 0 < f(b): returns the root and the final
/// bracket half-width (≤ `tol` unless `max_iter` ran out).
fn illinois(
    f: &mut impl FnMut(f64) -> f64,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    tol: f64,
    max_iter: usize,
) -> (f64, f64) {
    let mut side = 0i8;
    for _ in 0..max_iter {
        if (b - a).abs() <= 2.0 * tol {
            break;
        }
        let c = (a * fb - b * fa) / (fb - fa);
        // keep the new point strictly inside; fall back to bisection on a degenerate step
        let c = if c > a.min(b) && c < a.max(b) {
            c
        } else {
            0.5 * (a + b)
        };
        let fc = f(c);
        if fc == 0.0 {
            return (c, 0.0);
        }
        if (fc > 0.0) == (fb > 0.0) {
            (b, fb) = (c, fc);
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            (a, fa) = (c, fc);
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    let root = (a * fb - b * fa) / (fb - fa);
    let root = if root.is_finite() && root >= a.min(b) && root <= a.max(b) {
        root
    } else {
        0.5 * (a + b)
    };
    (root, 0.5 * (b - a).abs())
}
