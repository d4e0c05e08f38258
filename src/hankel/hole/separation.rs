//! R_o of the single plate with a hole: the first radius beyond B where the midplane σ_z of
//! slab (extended load) + hole correction turns tensile. An outward scan from B in steps of
//! `step`·D finds the first compressive→tensile sign change; Brent's method
//! ([`crate::numerics::root::brent`]) narrows it. The midplane σ_z is a
//! [`MidplaneRule`] of the slab (one node set for all radii) plus the modes' closed forms.
//!
//! The slab's part does not change as N doubles, and the root stays in the same scan interval
//! (it moves by ≪ `step`·D): on that interval the slab's σ_z(r, 0) is replaced by its Chebyshev
//! interpolant ([`LocalMidplane`]), so each level's root search costs only the modes' closed
//! forms (a rule evaluation is a sum over its 500–1000 ξ-nodes, the modes N complex K₀/K₁
//! pairs). σ_z(r, 0) is analytic in the strip |Im r| < D (its ξ-integrand is bounded by
//! e^(−ξD)·e^(ξ|Im r|)), so on an interval of half-width D/4 the coefficients fall like
//! ρ^(−k), ρ = 4 + √17 ≈ 8.1: 9 points give ~1e-6, 17 points ~1e-15 of the scale (measured on
//! Table 1: 2e-6 and 4e-15 as estimated). The corner enrichment's fields do not change with N
//! either (only their amplitudes do): their midplane σ_z are kept at the scan radii and
//! interpolated on the bracket the same way, each on a node set sized for the radii it serves.
//! The interpolants start on 9 points and double (nested) while their error — the slab's plus
//! the corner fields' weighted by the fitted amplitudes — divided by the slope at R_o exceeds
//! 5 % of R_o's tolerance; it joins R_o's estimate.
//!
//! N doubles until R_o's whole error estimate is below `r_o_tolerance`·R_o (see [`super`] for
//! the hole's share of it). The scan is [`crate::numerics::root::first_upward_crossing`].
//!
//! # Accuracy
//!
//! The estimate bounds the actual error beyond Table 1 (`tests/hankel/hole_correction.rs`,
//! `r_o_estimate_bounds_the_actual_error_beyond_table_1`) and on Table 1 (example 14).
//!
//! # Cost
//!
//! ~15 % of a hole run (`cargo bench --bench hole`).

use super::corner::CornerMidplaneRule;
use super::midplane_sum::MidplaneSum;
use super::plate::dot;
use super::rim::{rim_bound, worth_trying, RIM_SHARE};
use super::{HoleInfo, HoleParams, HolePlate};
use crate::error::positive;
use crate::hankel::midplane::MidplaneRule;
use crate::hankel::separation::{SeparationError, SeparationInfo, SeparationParams};
use crate::joint::{OuterRadius, SinglePlate};
use crate::numerics::chebyshev::{clenshaw, lobatto_coefficients, lobatto_points};
use crate::numerics::root::{brent, first_upward_crossing, scan_steps, Root};
use std::time::Instant;

/// R_o of `plate` with its hole made traction-free (see [`super`]); the hole's fit is
/// described by the returned [`HoleInfo`]. R_o's error estimate is the bracket half-width, plus
/// (midplane quadrature and interpolation errors + the hole data's quadrature error)/slope at
/// R_o, plus the hole's share (the last change of R_o as N doubled when the doublings contract,
/// else the larger of the last two; at the first N max residual·P/slope); N doubles until it is
/// below `hole.r_o_tolerance`·R_o. A rim far enough from R_o to move it by at most a tenth of
/// that is not fitted ([`super::rim`]): its bound joins the estimate.
pub fn single_plate_separation(
    plate: &SinglePlate,
    sep: &SeparationParams,
    hole: &HoleParams,
) -> Result<(SeparationInfo, HoleInfo), SeparationError> {
    let start = Instant::now();
    positive("R_o relative tolerance", sep.rel_tol)?;
    positive("scan step", sep.step)?;
    positive("scan reach", sep.reach)?;
    hole.check()?;
    let (d, b) = (plate.half_thickness(), plate.load().outer());
    let without_rim = || {
        SinglePlate::new(
            plate.hole_radius(),
            OuterRadius::Infinite,
            d,
            plate.material(),
            plate.load().clone(),
        )
    };
    let OuterRadius::Finite(c) = plate.outer_radius() else {
        return search(plate, sep, hole, start);
    };
    // A rim farther than B + 30 D is an end effect decaying like e^(−2.1 (C − r)/D) at the
    // midplane, below f64 resolution of R_o (see `fem::single`): the plate is infinite to
    // every digit, and its rim correction (whose cost grows with C/D) is skipped.
    if c > crate::joint::FAR_RIM * d + b {
        return search(&without_rim()?, sep, hole, start);
    }
    // A rim far enough from R_o to move it by at most RIM_SHARE of the tolerance: the
    // infinite plate to the rest of the tolerance, with the rim's bound added to its estimate.
    if plate.hole_radius() > 0.0 && c > b && worth_trying(c, b, d, hole.r_o_tolerance) {
        let trial = HoleParams {
            r_o_tolerance: (1.0 - RIM_SHARE) * hole.r_o_tolerance,
            ..*hole
        };
        let p_ref = Some(plate.load().mean_pressure().abs())
            .filter(|p| *p > 0.0)
            .unwrap_or(1.0);
        if let Ok((mut s, mut h)) = search(&without_rim()?, sep, &trial, start) {
            let bound = rim_bound(c, s.r_o, d, s.slope, p_ref);
            if s.r_o < c && bound <= RIM_SHARE * hole.r_o_tolerance * s.r_o {
                s.r_o_error += bound;
                s.converged = s.converged && s.r_o_error <= hole.r_o_tolerance * s.r_o;
                h.rim_bound = bound;
                return Ok((s, h));
            }
        }
    }
    search(plate, sep, hole, start)
}

/// The search of [`single_plate_separation`] on `plate` as it is (rim fitted if it has one).
fn search(
    plate: &SinglePlate,
    sep: &SeparationParams,
    hole: &HoleParams,
    start: Instant,
) -> Result<(SeparationInfo, HoleInfo), SeparationError> {
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
    // The slab's σ_z and the corner fields' σ_z at the scan radii B + kh do not change with N:
    // kept across levels (only the modes and the amplitudes do).
    let h = sep.step * d;
    let mut scan_cache: Vec<(f64, Vec<f64>)> = Vec::new();
    let mut local: Option<LocalMidplane> = None;
    // The slab's σ_z and the corner fields' on one node set sized for the radii asked: to
    // B + 4D (Table 1's brackets end by B + 2.5D; the fewer radii it serves, the fewer nodes),
    // beyond that the slab's rule and the corner fields' own node sets.
    let near = holed.midplane_sum((b + 4.0 * d).min(r_end));
    loop {
        let weights = holed.corner_weights().to_vec();
        let values = |r: f64, corner: Option<&CornerMidplaneRule>| {
            midplane_values(near.as_ref(), &rule, &holed, corner, r)
        };
        let mut scan = |k: usize| {
            let r = (b + k as f64 * h).min(r_end);
            while scan_cache.len() <= k {
                let rk = (b + scan_cache.len() as f64 * h).min(r_end);
                scan_cache.push((rk, values(rk, None)));
            }
            let v = &scan_cache[k].1;
            let value = v[0] + holed.modes_midplane(r) + dot(&weights, &v[1..]);
            (r, sign * value)
        };
        let Ok(crossing) = first_upward_crossing(
            |k| Ok::<_, std::convert::Infallible>(scan(k)),
            scan_steps(b, r_end, h),
        );
        let crossing = crossing.ok_or(SeparationError::NotFound { searched_to: r_end })?;
        let tol = rel_tol * b * 0.25;
        let ((a, fa), (c, fc)) = (crossing.before, crossing.after);
        // The slab's σ_z and the corner fields' on the bracket (beyond `near`, the corner
        // fields from a node set sized for it), interpolated from the scan's values at its
        // ends and new ones inside; kept across levels while the bracket stays.
        let bracket_rule = match &near {
            Some(q) if q.r_max() >= c => None,
            _ => holed.corner_midplane_rule(c),
        };
        let at = |r: f64| match scan_cache.iter().find(|(rk, _)| *rk == r) {
            Some((_, v)) => v.clone(),
            None => values(r, bracket_rule.as_ref()),
        };
        let abs_weights: Vec<f64> = weights.iter().map(|w| w.abs()).collect();
        let local_error = |l: &LocalMidplane| l.errors[0] + dot(&abs_weights, &l.errors[1..]);
        if local.as_ref().is_none_or(|l| l.lo != a || l.hi != c) {
            let l = LocalMidplane::new(at, a, c);
            evaluations += l.evaluations;
            local = Some(l);
        }
        // Brent on the interpolants; while their error's share of R_o's (error/slope) exceeds
        // LOCAL_SHARE of the tolerance, refine them and search again.
        let (r_o, half_width, slope) = loop {
            let l = local.as_ref().expect("built above");
            let mut f = |r: f64| {
                let v = l.eval(r).unwrap_or_else(|| {
                    evaluations += 1;
                    values(r, None)
                });
                sign * (v[0] + holed.modes_midplane(r) + dot(&weights, &v[1..]))
            };
            let mut g = |x: f64| Ok::<f64, std::convert::Infallible>(f(x));
            let Ok(Root { x, half_width }) = brent(&mut g, a, fa, c, fc, tol, sep.max_iterations);
            let dr = (1e-4 * d).max(1e-6 * x);
            let slope = (f(x + dr) - f(x - dr)) / (2.0 * dr);
            let target = LOCAL_SHARE * hole.r_o_tolerance * x * slope.abs();
            if local_error(l) <= target || l.intervals() >= LOCAL_MAX {
                break (x, half_width, slope);
            }
            let l = local.as_mut().expect("built above");
            evaluations += l.refine(at, |l| local_error(l) <= target);
        };
        let local = local.as_ref().expect("built above");
        // The rim's residual counts as the hole's: a rim near R_o converges by its own modes.
        let residual_max = holed.info().residual_max.max(holed.info().rim_residual_max);
        let residual_met = residual_max <= hole.residual_target;
        if let Some(p) = previous {
            changes.push((r_o - p).abs());
        }
        // The hole's share of R_o's error. With a single N, the bound max residual·P/slope
        // (|δσ_z| ≤ max residual traction; see the module docs). After doublings, the last
        // change of R_o: it bounds the current error whenever that error at least halves per
        // doubling (|R_N − R_N/2| ≥ err(N/2) − err(N) ≥ err(N)). That contraction is checked
        // on what is measured: the last two changes (the last at most half the one before),
        // or after one doubling the residual met its target. Without it, the
        // larger of the last two changes (or of the change and the bound). (With the corner
        // enrichment R_o's error falls 3–300× per doubling on Table 1: example 14.)
        let bound = residual_max * p_ref / slope.abs();
        let hole_error = match changes.len() {
            0 => bound,
            n => {
                let last = changes[n - 1];
                let before = (n >= 2).then(|| changes[n - 2]);
                let contracting = match before {
                    Some(c) => last <= 0.5 * c,
                    // A rim's residual falls only ~0.4× per doubling (its corners are not
                    // enriched) and R_o's error with it more slowly still: with a rim, one
                    // change is never trusted alone (example 16 found a 1.2× overshoot).
                    None if holed.rim().is_some() => false,
                    // One change alone only where the residual met its target: a halved
                    // residual far above it did not make R_o's error contract (a narrow load,
                    // (A/D, B/A, ν) = (0.336, 1.066, −0.026): N = 4 → 8 left 2.4e-3 P, R_o
                    // moved little and was 4.3e-5 R_o off, estimated 3.9e-6;
                    // `tests/hankel/hole_reach_survey.rs`).
                    None => residual_met,
                };
                match (contracting, before) {
                    // R_o's error at N/2 is about the change before; it falls with the
                    // residual: the last change alone fell faster than that on a narrow load,
                    // (A/D, B/A, ν) = (1.82, 1.037, −0.18): changes 1.1e-5, 1.8e-7 R_o at
                    // N = 8, 16, residual 4.6e-4 → 1.4e-4 P, the error at 16 3.1e-7 R_o
                    (true, Some(c)) => {
                        let h = &holed.info().history[holed.info().history.len() - 2];
                        let r_prev = h.residual_max.max(h.rim_residual_max);
                        last.max(c * (residual_max / r_prev).min(1.0))
                    }
                    (true, None) => last,
                    (false, _) => last.max(before.unwrap_or(bound)),
                }
            }
        };
        // The slab's hole tractions enter the fit with their quadrature error, which the
        // residual (measured against the same data) cannot see: add its effect too; and the
        // local interpolants' errors (the corner fields' weighted by the fitted amplitudes).
        let data_error = holed.info().slab_error * p_ref;
        let error = half_width
            + (local_error(local) + rule.eval(r_o).error + data_error) / slope.abs()
            + hole_error;
        // Stop when R_o's whole estimate meets the R_o target (the residual target alone does
        // not: at the first N its bound can exceed it), or N is fixed, or N can grow no more.
        let converged = error <= hole.r_o_tolerance * r_o;
        if hole.terms.is_some() || converged || !holed.refine() {
            let sep_info = SeparationInfo {
                r_o,
                r_o_error: error,
                converged,
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

/// [σ_z(r, 0) of the slab, the corner basis…] at r: from `near` if it serves r, else the
/// slab's `rule` and the corner fields' `corner` rule (or the plate's own).
fn midplane_values(
    near: Option<&MidplaneSum>,
    rule: &MidplaneRule,
    holed: &HolePlate,
    corner: Option<&CornerMidplaneRule>,
    r: f64,
) -> Vec<f64> {
    near.and_then(|q| q.eval(r)).unwrap_or_else(|| {
        let mut v = vec![rule.eval(r).value];
        v.extend(corner_basis(holed, corner, r));
        v
    })
}

/// The corner fields' midplane basis at r from `rule` if it serves r, else the plate's own.
fn corner_basis(holed: &HolePlate, rule: Option<&CornerMidplaneRule>, r: f64) -> Vec<f64> {
    rule.and_then(|q| q.basis(r))
        .unwrap_or_else(|| holed.corner_midplane_basis(r))
}

/// Functions of r on one scan interval [lo, hi] (the slab's midplane σ_z(r, 0) and the corner
/// enrichment's fields there) by Chebyshev interpolation on the Chebyshev–Lobatto grid (see the
/// module docs): M = 8, doubled (nested) while the caller asks (error estimates: twice the
/// largest of the last three coefficients of each function), at most 64.
struct LocalMidplane {
    lo: f64,
    hi: f64,
    /// Samples on the current grid (one vector of all functions per point).
    values: Vec<Vec<f64>>,
    /// Chebyshev coefficients, one vector per function.
    coef: Vec<Vec<f64>>,
    /// Interpolation error estimates.
    errors: Vec<f64>,
    /// Function evaluations spent.
    evaluations: usize,
}

/// Largest M of a [`LocalMidplane`].
const LOCAL_MAX: usize = 64;

/// The share of R_o's tolerance the bracket's interpolation error may take (its error over the
/// slope at R_o); beyond it the interpolants are refined.
const LOCAL_SHARE: f64 = 0.05;

impl LocalMidplane {
    /// The interpolants on the first grid (M = 8); `at(r)` gives every function at r.
    fn new(at: impl Fn(f64) -> Vec<f64>, lo: f64, hi: f64) -> Self {
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        // the ends exactly (a caller may know the values there)
        let values: Vec<Vec<f64>> = lobatto_points(8)
            .into_iter()
            .enumerate()
            .map(|(j, x)| match j {
                0 => at(hi),
                8 => at(lo),
                _ => at(mid + half * x),
            })
            .collect();
        let mut l = Self {
            lo,
            hi,
            evaluations: values.len(),
            values,
            coef: Vec::new(),
            errors: Vec::new(),
        };
        l.coefficients();
        l
    }

    /// Intervals M of the current grid.
    fn intervals(&self) -> usize {
        self.values.len() - 1
    }

    /// Doubles M (nested: the old samples are the even points of the new grid) until
    /// `accept(self)` or M = [`LOCAL_MAX`]; returns the evaluations spent.
    fn refine(&mut self, at: impl Fn(f64) -> Vec<f64>, accept: impl Fn(&Self) -> bool) -> usize {
        let before = self.evaluations;
        let (mid, half) = (0.5 * (self.lo + self.hi), 0.5 * (self.hi - self.lo));
        while !accept(self) && self.intervals() < LOCAL_MAX {
            let m = self.intervals();
            let x = lobatto_points(2 * m);
            let mut old = std::mem::take(&mut self.values).into_iter();
            self.values = (0..=2 * m)
                .map(|j| {
                    if j % 2 == 0 {
                        old.next().expect("nested grid")
                    } else {
                        self.evaluations += 1;
                        at(mid + half * x[j])
                    }
                })
                .collect();
            self.coefficients();
        }
        self.evaluations - before
    }

    /// Coefficients and error estimates from the samples.
    fn coefficients(&mut self) {
        let m = self.values.len() - 1;
        (self.coef, self.errors) = (0..self.values[0].len())
            .map(|j| {
                let column: Vec<f64> = self.values.iter().map(|v| v[j]).collect();
                let c = lobatto_coefficients(&column);
                let error = 2.0 * c[m - 2..].iter().fold(0.0f64, |e, c| e.max(c.abs()));
                (c, error)
            })
            .unzip();
    }

    /// Every function at r, or None outside [lo, hi].
    fn eval(&self, r: f64) -> Option<Vec<f64>> {
        let x = (2.0 * r - self.lo - self.hi) / (self.hi - self.lo);
        (r >= self.lo && r <= self.hi).then(|| self.coef.iter().map(|c| clenshaw(c, x)).collect())
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
        // estimate plus rounding of the rule's sum (~1e-15 of its scale); at a loose tolerance
        // from the first grid (M = 8), at a tight one after doublings.
        for (b, d) in [(0.31, 0.1), (0.13, 0.2)] {
            let slab = Slab::new(
                d,
                Material::unit(0.3).unwrap(),
                FaceLoad::uniform(0.0, b, 1.0).unwrap(),
            )
            .unwrap();
            let rule = MidplaneRule::new(&slab, b + 12.0 * d, 1e-13).unwrap();
            for (k, tol) in [(2.0, 1e-12), (5.0, 1e-12), (2.0, 1e-6), (5.0, 1e-6)] {
                let lo = b + 0.5 * k * d;
                let hi = lo + 0.5 * d;
                let at = |r| vec![rule.eval(r).value];
                let mut l = LocalMidplane::new(at, lo, hi);
                l.refine(at, |l| l.errors[0] <= tol);
                let error = l.errors[0];
                assert!(error <= tol, "estimate {error:e}");
                assert_eq!(
                    l.values.len() == 9,
                    tol > 1e-7,
                    "M = {}",
                    l.values.len() - 1
                );
                for i in 0..40 {
                    let r = lo + (hi - lo) * (i as f64 + 0.37) / 40.0;
                    let diff = (l.eval(r).unwrap()[0] - rule.eval(r).value).abs();
                    assert!(diff <= error + 1e-14, "r {r}: {diff:e} vs {error:e}");
                }
                assert!(l.eval(lo - 1e-9).is_none() && l.eval(hi + 1e-9).is_none());
            }
        }
    }
}
