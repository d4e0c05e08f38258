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
/// described by the returned [`HoleInfo`]. R_o's error estimate is the bracket half-width, plus
/// (midplane quadrature error + the hole data's quadrature error)/slope at R_o, plus the hole's
/// share (the larger of the last two changes of R_o as N doubled, or max residual·P/slope).
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
    // R_o lies on the plate: a rim at C ends the search there.
    let r_end = (b + sep.reach * d).min(holed.rim().unwrap_or(f64::INFINITY));
    let p_ref = Some(plate.load().mean_pressure().abs())
        .filter(|p| *p > 0.0)
        .unwrap_or(1.0);
    // The hole's share of R_o's error is ≥ r_o_tolerance·R_o: the slab's midplane σ_z need not
    // be resolved to a much finer relative tolerance than a thousandth of it.
    let rel_tol = sep.rel_tol.max(1e-3 * hole.r_o_tolerance);
    let sigma_tol = (1e-3 * rel_tol * p_ref).max(1e-15 * p_ref);
    let rule = MidplaneRule::new(holed.slab(), r_end, sigma_tol)?;
    let sign = plate.load().total_force().signum();
    let mut evaluations = 0;
    let mut previous: Option<f64> = None;
    let mut changes: Vec<f64> = Vec::new();
    // The slab's σ_z at the scan radii B + kh does not change with N: kept across levels.
    let h = sep.step * d;
    let mut scan_cache: Vec<f64> = Vec::new();
    loop {
        let mut f = |r: f64| {
            evaluations += 1;
            sign * (rule.eval(r).value + holed.correction_midplane(r))
        };
        let mut scan = |k: usize| {
            let r = (b + k as f64 * h).min(r_end);
            while scan_cache.len() <= k {
                let rk = (b + scan_cache.len() as f64 * h).min(r_end);
                scan_cache.push(rule.eval(rk).value);
            }
            (r, sign * (scan_cache[k] + holed.correction_midplane(r)))
        };
        let bracket = first_upward_crossing(&mut scan, r_end)?;
        let tol = rel_tol * b * 0.25;
        let (r_o, half_width) = illinois(&mut f, bracket.0, bracket.1, tol, sep.max_iterations);
        let dr = (1e-4 * d).max(1e-6 * r_o);
        let slope = (f(r_o + dr) - f(r_o - dr)) / (2.0 * dr);
        let residual_max = holed.info().residual_max;
        if let Some(p) = previous {
            changes.push((r_o - p).abs());
        }
        // R_o's convergence in N is not monotone (the fit redistributes the corner residual):
        // the larger of the last two changes estimates the remaining error.
        let change = (changes.len() >= 2)
            .then(|| {
                changes[changes.len() - 2..]
                    .iter()
                    .copied()
                    .fold(0.0, f64::max)
            })
            .or(changes.last().copied());
        let converged = residual_max <= hole.residual_target
            || (changes.len() >= 2 && change.is_some_and(|c| c <= hole.r_o_tolerance * r_o));
        if hole.terms.is_some() || converged || !holed.refine() {
            // Hole error: the larger of the last two changes of R_o under doubling N (the
            // residual falls algebraically, like N^(−1.74), so a change bounds what is left), or
            // with a single N the bound max residual·P / slope.
            let hole_error = change.unwrap_or(residual_max * p_ref / slope.abs());
            // The slab's hole tractions enter the fit with their quadrature error, which the
            // residual (measured against the same data) cannot see: add its effect too.
            let data_error = holed.info().slab_error * p_ref;
            let error = half_width + (rule.eval(r_o).error + data_error) / slope.abs() + hole_error;
            let sep_info = SeparationInfo {
                r_o,
                error,
                evaluations: evaluations + scan_cache.len(),
                slope,
                nodes: rule.nodes(),
                seconds: start.elapsed().as_secs_f64(),
            };
            return Ok((sep_info, holed.info().clone()));
        }
        previous = Some(r_o);
    }
}

/// The first compressive→tensile sign change of the scan `(r_k, f(r_k))`, k = 0, 1, … (r_0 = B,
/// steps of `step`·D, up to `r_end`): the bracket ((r_{k−1}, f), (r_k, f)).
#[allow(clippy::type_complexity)]
fn first_upward_crossing(
    scan: &mut impl FnMut(usize) -> (f64, f64),
    r_end: f64,
) -> Result<((f64, f64), (f64, f64)), SeparationError> {
    let mut lo = scan(0);
    for k in 1.. {
        let hi = scan(k);
        if lo.1 <= 0.0 && hi.1 > 0.0 {
            return Ok((lo, hi));
        }
        if hi.0 >= r_end {
            break;
        }
        lo = hi;
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
