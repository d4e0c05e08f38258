//! R_o of the single plate with a hole: the first radius beyond B where the midplane σ_z of
//! slab (extended load) + hole correction turns tensile. An outward scan from B in steps of
//! `step`·D finds the first compressive→tensile sign change; Brent's method
//! ([`crate::hankel::root::brent`]) narrows it. The midplane σ_z is a
//! [`MidplaneRule`] of the slab (one node set for all radii) plus the modes' closed forms.
//!
//! The slab's part does not change as N doubles, and the root stays in the same scan interval
//! (it moves by ≪ `step`·D): on that interval the slab's σ_z(r, 0) is replaced by its Chebyshev
//! interpolant ([`LocalMidplane`]), built once from 17–65 rule evaluations, so each level's
//! root search costs only the modes' closed forms (a rule evaluation is a sum over its
//! 500–1000 ξ-nodes, the modes N complex K₀/K₁ pairs). σ_z(r, 0) is analytic in the strip
//! |Im r| < D (its ξ-integrand is bounded by e^(−ξD)·e^(ξ|Im r|)), so on an interval of
//! half-width D/4 the coefficients fall like ρ^(−k), ρ = 4 + √17 ≈ 8.1: 17 points give ~1e-15
//! of the scale.

use super::chebyshev::{clenshaw, lobatto_coefficients, lobatto_points};
use super::{HoleInfo, HoleParams, HolePlate};
use crate::error::positive;
use crate::hankel::midplane::MidplaneRule;
use crate::hankel::root::{brent, Root};
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
    let mut local: Option<LocalMidplane> = None;
    loop {
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
        let ((a, fa), (c, fc)) = bracket;
        if local.as_ref().is_none_or(|l| l.lo != a || l.hi != c) {
            let l = LocalMidplane::new(&rule, a, c, sigma_tol);
            evaluations += l.evaluations;
            local = Some(l);
        }
        let slab = local.as_ref().expect("built above");
        let mut f = |r: f64| {
            let s = slab.eval(r).unwrap_or_else(|| {
                evaluations += 1;
                rule.eval(r).value
            });
            sign * (s + holed.correction_midplane(r))
        };
        let mut g = |x: f64| Ok::<f64, std::convert::Infallible>(f(x));
        let Ok(Root { x: r_o, half_width }) = brent(&mut g, a, fa, c, fc, tol, sep.max_iterations);
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
            let error = half_width
                + (slab.error + rule.eval(r_o).error + data_error) / slope.abs()
                + hole_error;
            let sep_info = SeparationInfo {
                r_o,
                error,
                evaluations: evaluations + scan_cache.len() + 1,
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

/// The slab's midplane σ_z(r, 0) on one scan interval [lo, hi] by Chebyshev interpolation on
/// the Chebyshev–Lobatto grid (see the module docs): M = 16, doubled (nested) until the last
/// three coefficients are below the tolerance, at most 64.
struct LocalMidplane {
    lo: f64,
    hi: f64,
    coef: Vec<f64>,
    /// Interpolation error estimate (2 × the largest of the last three coefficients).
    error: f64,
    /// Rule evaluations spent.
    evaluations: usize,
}

impl LocalMidplane {
    fn new(rule: &MidplaneRule, lo: f64, hi: f64, tol: f64) -> Self {
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        let at = |x: f64| rule.eval(mid + half * x).value;
        let mut m = 16;
        let mut values: Vec<f64> = lobatto_points(m).into_iter().map(at).collect();
        let mut evaluations = values.len();
        loop {
            let coef = lobatto_coefficients(&values);
            let error = 2.0 * coef[m - 2..].iter().fold(0.0f64, |e, c| e.max(c.abs()));
            if error <= tol || m >= 64 {
                return Self {
                    lo,
                    hi,
                    coef,
                    error,
                    evaluations,
                };
            }
            // nested doubling: the old values sit at the even points of the new grid
            let x = lobatto_points(2 * m);
            values = (0..=2 * m)
                .map(|j| {
                    if j % 2 == 0 {
                        values[j / 2]
                    } else {
                        evaluations += 1;
                        at(x[j])
                    }
                })
                .collect();
            m *= 2;
        }
    }

    /// σ_z(r, 0) of the slab, or None outside [lo, hi].
    fn eval(&self, r: f64) -> Option<f64> {
        (r >= self.lo && r <= self.hi).then(|| {
            clenshaw(
                &self.coef,
                (2.0 * r - self.lo - self.hi) / (self.hi - self.lo),
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::LocalMidplane;
    use crate::hankel::field::Slab;
    use crate::hankel::midplane::MidplaneRule;
    use crate::load::FaceLoad;
    use crate::material::Material;

    #[test]
    fn local_midplane_interpolates_the_rule_within_its_estimate() {
        // Scan intervals of width D/2 around Table 1's zeros (wide and narrow load): the
        // interpolant against the rule itself at points off the grid, within the interpolant's
        // estimate plus rounding of the rule's sum (~1e-15 of its scale).
        for (b, d) in [(0.31, 0.1), (0.13, 0.2)] {
            let slab = Slab::new(
                d,
                Material::unit(0.3).unwrap(),
                FaceLoad::uniform(0.0, b, 1.0).unwrap(),
            )
            .unwrap();
            let rule = MidplaneRule::new(&slab, b + 12.0 * d, 1e-13).unwrap();
            for k in [2.0, 5.0] {
                let lo = b + 0.5 * k * d;
                let hi = lo + 0.5 * d;
                let l = LocalMidplane::new(&rule, lo, hi, 1e-12);
                assert!(l.error <= 1e-12, "estimate {:e}", l.error);
                for i in 0..40 {
                    let r = lo + (hi - lo) * (i as f64 + 0.37) / 40.0;
                    let diff = (l.eval(r).unwrap() - rule.eval(r).value).abs();
                    assert!(diff <= l.error + 1e-14, "r {r}: {diff:e} vs {:e}", l.error);
                }
                assert!(l.eval(lo - 1e-9).is_none() && l.eval(hi + 1e-9).is_none());
            }
        }
    }
}
