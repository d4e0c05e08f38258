//! The search for R_o of the holed two-plate model ([`super`]) and its error estimate:
//! Newton's method on the edge coefficient f(c) = c·φ(c)/p̄(0) of the trial contact radii of
//! module `crack` ([`newton_root`]), from a predictor, every edge value kept so that none is
//! computed twice, each radius's crack iteration started from the correction of the nearest
//! radius solved.
//!
//! - [`Setup::search`]: R_o from B + 0.45D, the first step with a fitted slope
//!   −min(0.35 + 0.45D/(B − A), 2)/D (`Setup::predictor`), then secants (inverse quadratic
//!   interpolation through three points when it agrees with the secant), kept in the bracket
//!   once there is one; when Newton fails (a slope not negative, a step out of range, ten
//!   evaluations) the receding solver's scan ([`crate::hankel::receding::search::root`]) and step-stopping
//!   inverse interpolation ([`crate::numerics::secant::refine`]) as before. Also the solve at
//!   R_o (or at the last radius, within the root tolerance of R_o, when no pressure is asked
//!   for) and the edge values the search computed;
//! - the stop: the next step s is at most the root tolerance (returning the last point, as
//!   `refine`), or, after three points, the secant step's own error 4·|f″/2f′|·|s|·(|s| + |x −
//!   x′|) (f″/2 the last three points' divided difference, x′ the previous point) is: R_o is
//!   then x + s, not solved at; the error of a secant step through x′ and x is
//!   (f″/2f′)·e·e′ to leading order, with |e| ≈ |s| and |e′| ≤ |s| + |x − x′|;
//! - [`estimate`]: the R_o of the coarser variants (⌈3n/4⌉ Nyström points; half the hole modes
//!   and 2/3 of the heights, or each alone), each one Newton step from R_o with the slope of
//!   the edge coefficient taken as a secant through two of the search's own edge values (a
//!   solve at R_o + 10⁻³D only when the search left none between 10⁻⁵D and 10⁻²D of R_o); the
//!   variants run in parallel (rayon). When the search extrapolated R_o from its last radius x,
//!   each variant is solved at x (the fewer-nodes one with the tables the setup kept there) and
//!   its change is −(f_v(x) − f(x))/f′: the two edge coefficients' slopes differ by about as
//!   much as their roots, so the difference at x is their roots' difference to that order, the
//!   extrapolated root's own error (counted apart, the root tolerance) left out. The finite
//!   rim (module `rim`) starts its own Newton search from the infinite plate's R_o with
//!   its slope ([`Found::slope`]) and solves its variants likewise.
//!
//! # Accuracy
//!
//! The stop against the same knobs iterated to 1e-13 (`tests/hankel/two_plate_hole_newton.rs`,
//! `newton_stops_within_its_root_tolerance`). The variants' secant: its relative error is about
//! f″δ/f′ for points δ ≤ 10⁻²D apart; the Newton step's error is that times the step, below
//! 10⁻⁸D for the steps (≤ 10⁻⁶D) of Table 1. Measured as the estimate against a finer run:
//! `tests/hankel/two_plate_hole_fast.rs`.
//!
//! # Cost
//!
//! Measured on all twelve Table 1 rows by `boltzone two --method hankel --tol T`
//! (C = ∞ and C = 1.54 in), this search's binary and main's by turns per row in one session,
//! two rounds, the median CPU (user + sys), load 5–10 on the 2 cores (the other helpers'
//! builds), with the 1e-6 tier's modes doubled to 2e-6 P but one coarse variant (the tier's
//! split variants, below, came after):
//!
//! | T | C | radii (crack solves) in all | CPU per row | main's | in total | R_o moved |
//! |---|---|-----------------------------|-------------|--------|----------|-----------|
//! | 1e-6 | ∞ | 71 (main 95) | 0.33–0.60 s | 0.42–0.74 s | 1.20× | ≤ 4.6e-10 R_o but (0.5, 1.3)'s 5.2e-8 (its modes) |
//! | 1e-3 | ∞ | 59 (79) | 0.10–0.14 s | 0.10–0.18 s | 1.17× | ≤ 4.3e-5 R_o (the root tolerance 1e-4 D), ≤ 0.54 of the estimate |
//! | 1e-6 | 1.54 in | 191 (287) | 1.25–2.50 s | 2.08–3.27 s | 1.43× | ≤ 2.9e-11 R_o but (0.5, 1.3)'s 5.3e-8 |
//! | 1e-3 | 1.54 in | 157 (245) | 0.34–0.61 s | 0.57–1.10 s | 1.55× | ≤ 4.8e-5 R_o, ≤ 0.22 of the estimate |
//!
//! At C = ∞ the search takes 3–5 radii instead of 5–6 (traced with a unit first slope, before
//! the fitted one: 3–6, the extrapolated stop saving the last); with the rim 13–17 crack
//! solves instead of 20–24 in all, the rim's search from the infinite R_o and no re-solve at
//! R_o. At 1e-3 R_o moves within the root
//! tolerance (1e-4 D), which both searches meet differently; it is part of both estimates.
//! The 1e-6 tier's split variants (module [`super::params`]) add two solves per geometry
//! (four variants instead of two): by turns with main's binary once more (one round,
//! load ~8, the tiers' survey running beside), at --tol 1e-6 C = ∞ 95 solves as main's (the
//! search's 24 saved go to the variants), CPU per row 0.36–0.72 s against 0.34–0.80 s (1.01×
//! in total), estimates up to 9× larger on narrow loads ((0.75, 1.3): 3.9e-8 → 3.6e-7 R_o)
//! and every row converged, (0.5, 1.3) too (1.3e-6 → 2.1e-7); at C = 1.54 in 215 solves
//! against 287, 1.34–2.88 s per row against 1.92–3.06 s (1.32× in total), all twelve
//! converged (main: eleven).
//!
//! The variants at the search's last radius, when R_o was extrapolated from it (the fewer-nodes
//! variant on the tables kept there), and the modes variant on the setup's hole tables: the
//! same solves, 1.11× less CPU in total at 1e-6 (C = ∞), 1.07× at 1e-3, 1.06× at 1e-6 with
//! C = 1.54 in, R_o unchanged (module [`super`]'s Cost, by turns with main's binary).
//!
//! **Why still four radii.** Traced at 1e-6 on Table 1 (C = ∞): the search takes four radii on
//! nine rows, three on (0.75, 1.3) and (0.5, 3.1), where B + 0.45D lies within 3.4e-3 D and
//! 1e-4 D of R_o, five on (0.5, 1.6). After three radii the extrapolated stop's own error
//! bound was 3.9e-8 … 3.2e-5 D on the others, against the root tolerance 1e-9 D; the first
//! step's slope was 0.5–17 % off, and R_o − (B + 0.45D) was −0.073 … +0.113 D. Three radii
//! need a start within a few 1e-3 D. The no-hole receding solution under the same annular
//! load (module `contact`'s `contact_radius`, 7–32 ms) is no such start: the holed R_o lies
//! 0.005 … 0.30 D inside it, widest on the narrow loads (B − A ≤ 0.6D), where the hole's
//! own compliance matters most.
//!
//! Before (the scan): two solves fewer per geometry than a fresh solve at R_o and a secant
//! solve (13 → 11 on Table 1 row 1), the warm start saving one crack iteration of three on the
//! radii near R_o; the variants' solves on two cores at once, the half-terms variant's setup
//! sharing the slab's midplane curve and the corner table ([`Setup::sharing`]); the scan from
//! B + 0.45D instead of B bracketed R_o in two solves instead of three or four (all twelve rows
//! 95 radii instead of 110 at --tol 1e-6). Timed by example 19.

use super::params::HoledParams;
use super::setup::{Crack, Setup};
use crate::hankel::hole::fit::Fit;
use crate::hankel::hole::HoleParams;
use crate::hankel::receding::contact::RecedingError;
use crate::hankel::receding::search::{root, Scan};
use crate::joint::SinglePlate;
use crate::numerics::secant::refine;

/// Where [`Setup::search`]'s scan starts, beyond B in D.
const SCAN_FROM: f64 = 0.45;

/// What [`Setup::search`] found.
pub(super) struct Found {
    /// The contact radius R_o.
    pub(super) r_o: f64,
    /// The solve at R_o (with the pressure at the radii asked for), or with none asked for and
    /// R_o extrapolated by one step, the last solve of the search.
    pub(super) last: Crack,
    /// The correction of the search's solve nearest R_o (the variants' warm start, the same
    /// whether or not a pressure was asked for).
    pub(super) warm: Option<Fit>,
    /// The search's solve at R_o, or with R_o extrapolated by one step its last solve, and
    /// its edge value: where the estimate's variants are solved (the same whether or not a
    /// pressure was asked for; with none asked for, the setup keeps its tables there).
    pub(super) anchor: (f64, f64),
    /// Contact radii solved.
    pub(super) solves: usize,
    /// Crack iterations over those radii.
    pub(super) iterations: usize,
    /// Every edge value of the search, (c, c·φ(c)/p̄(0)).
    pub(super) edges: Vec<(f64, f64)>,
}

impl Found {
    /// The edge coefficient at R_o: the search's value there, else zero (R_o extrapolated, to
    /// within the root tolerance).
    pub(super) fn at_r_o(&self) -> f64 {
        self.edges
            .iter()
            .find(|e| e.0 == self.r_o)
            .map_or(0.0, |e| e.1)
    }

    /// The edge coefficient's slope at R_o from the search's edge values ([`secant_slope`]).
    pub(super) fn slope(&self, d: f64) -> Option<f64> {
        secant_slope(&self.edges, self.r_o, self.at_r_o(), d)
    }
}

impl Setup {
    /// R_o with `n` Nyström points ([`Setup::nodes_for`]: more for wide loads), from `near`
    /// (else B + 0.45D) by [`newton_root`] with the edge coefficient's slope `slope` (else
    /// −1/D), falling back to the scan and inverse interpolation when Newton fails; and the
    /// contact pressure at r = A + x(R_o − A) for x in `at`.
    pub(super) fn search(
        &self,
        b: f64,
        n: usize,
        params: &HoledParams,
        near: Option<(f64, f64)>,
        at: &[f64],
    ) -> Result<Found, RecedingError> {
        let n = self.nodes_for(n);
        let mut seen: Vec<(f64, Crack)> = Vec::new();
        // each radius starts from the correction of the nearest one solved before
        let nearest = |seen: &[(f64, Crack)], c: f64| -> Option<Fit> {
            seen.iter()
                .min_by(|x, y| (x.0 - c).abs().total_cmp(&(y.0 - c).abs()))
                .and_then(|(_, k)| k.fit.clone())
        };
        let edge = |c: f64, seen: &mut Vec<(f64, Crack)>| {
            let start = nearest(seen, c);
            let k = self.crack(c, n, params, &[], start.as_ref(), None)?;
            let e = k.edge;
            seen.push((c, k));
            Ok::<f64, RecedingError>(e)
        };
        let tol = params.rel_tol * self.d;
        let (x0, slope0) = near.unwrap_or_else(|| self.predictor(b, params));
        let range = (self.a + 0.05 * self.d, b + params.reach * self.d);
        let newton = newton_root(
            &mut |c| edge(c, &mut seen),
            x0,
            slope0,
            NEWTON_STEP * self.d,
            range,
            tol,
            NEWTON_EVALUATIONS,
        )?;
        let (r_o, evaluated) = match newton {
            Some(root) => (root.x, root.evaluated),
            None => (
                self.bracket_and_refine(
                    b,
                    params,
                    near.map(|p| p.0),
                    &mut |c, s| edge(c, s),
                    &mut seen,
                )?,
                true,
            ),
        };
        let edges: Vec<(f64, f64)> = seen.iter().map(|(c, k)| (*c, k.edge)).collect();
        let mut solves = seen.len();
        let mut iterations: usize = seen.iter().map(|(_, k)| k.iterations).sum();
        // the solve at R_o, or with R_o one extrapolated step beyond the last radius solved (its
        // error bounded below the root tolerance) that radius's solve, when no pressure is asked
        let reuse = match evaluated {
            true => seen.iter().position(|(c, _)| *c == r_o),
            false => seen.len().checked_sub(1),
        };
        let warm = nearest(&seen, r_o);
        let anchor = reuse.map_or((r_o, 0.0), |i| (seen[i].0, seen[i].1.edge));
        let last = match reuse.filter(|_| at.is_empty()) {
            Some(i) => seen.swap_remove(i).1,
            None => {
                solves += 1;
                let radii: Vec<f64> = at
                    .iter()
                    .map(|&x| fraction_radius(self.a, r_o, x))
                    .collect();
                let k = self.crack(r_o, n, params, &radii, nearest(&seen, r_o).as_ref(), None)?;
                iterations += k.iterations;
                k
            }
        };
        Ok(Found {
            r_o,
            last,
            warm,
            anchor,
            solves,
            iterations,
            edges,
        })
    }

    /// Where [`Setup::search`] starts without a guess, and the first step's slope: R_o − B is
    /// 0.38…0.56 D on Table 1 (B + 0.45D), and D times the edge coefficient's slope at R_o
    /// is −0.5 … −2.0 there, steeper on narrow loads, fitted as −min(0.35 + 0.45D/(B − A), 2)
    /// (within 25 % on ten of the twelve rows, 1.15× on (0.75, 1.3), 1.2× on (0.5, 1.3)).
    fn predictor(&self, b: f64, params: &HoledParams) -> (f64, f64) {
        let x0 = b + (SCAN_FROM * self.d).min(params.reach * self.d);
        let slope = (0.35 + 0.45 * self.d / (b - self.a)).min(2.0);
        (x0, -slope / self.d)
    }

    /// The fallback of [`Setup::search`]: the receding solver's scan for a bracket (an infinite
    /// tolerance ends its Brent refinement before any evaluation) from B + 0.45D, outward or
    /// inward, then step-stopping inverse interpolation from the scan's last points; `seen`
    /// holds the solves so far (Newton's), whose edge values start the refinement when none of
    /// the scan's bracket.
    fn bracket_and_refine(
        &self,
        b: f64,
        params: &HoledParams,
        near: Option<f64>,
        edge: &mut impl FnMut(f64, &mut Vec<(f64, Crack)>) -> Result<f64, RecedingError>,
        seen: &mut Vec<(f64, Crack)>,
    ) -> Result<f64, RecedingError> {
        let scan = Scan {
            b: b + (SCAN_FROM * self.d).min(params.reach * self.d),
            d: self.d,
            step: params.step * self.d,
            end: b + params.reach * self.d,
            tol: f64::INFINITY,
            max_iterations: 100,
        };
        let from = seen.len();
        root(&mut |c| edge(c, seen), &scan, near)?.ok_or(RecedingError::NotFound {
            from: b,
            to: scan.end,
        })?;
        let known: Vec<(f64, f64)> = seen[from..].iter().map(|(c, k)| (*c, k.edge)).collect();
        Ok(refine(&mut |c| edge(c, seen), &known, params.rel_tol * self.d, 100)?.x)
    }
}

/// A root found by [`newton_root`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct NewtonRoot {
    /// The root.
    pub(super) x: f64,
    /// Whether `x` was evaluated (else it is the last point evaluated plus one secant step).
    pub(super) evaluated: bool,
}

/// The largest Newton step, in D (the scan's step).
const NEWTON_STEP: f64 = 0.25;

/// Evaluations before [`newton_root`] gives up (the search then scans).
pub(super) const NEWTON_EVALUATIONS: usize = 10;

/// The factor on the secant step's error term in [`newton_root`]'s extrapolated stop.
const EXTRAPOLATION_SAFETY: f64 = 4.0;

/// The root of a decreasing smooth `f` from `x0`, the first step with the slope `slope0`, then
/// secants through the last two points (inverse quadratic interpolation through three when it
/// lies within twice the secant step), steps at most `max_step`, kept inside the bracket once
/// there is one (bisection when a step leaves it). Stops when the next step s is at most `tol`
/// (returning the last point evaluated, whose error s bounds), or when the secant step's own
/// error, (f″/2f′)·s·e′ with e′ ≤ |s| + |x − x′| the previous point's, times 4, is at most
/// `tol` (returning x + s unevaluated; f″/2 from the last three points' divided difference).
/// `None` when the slope is not negative, a step leaves `range` or after `max_evaluations`:
/// the caller's fallback.
pub(super) fn newton_root<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    x0: f64,
    slope0: f64,
    max_step: f64,
    range: (f64, f64),
    tol: f64,
    max_evaluations: usize,
) -> Result<Option<NewtonRoot>, E> {
    let mut pts: Vec<(f64, f64)> = Vec::new();
    let mut x = x0;
    for _ in 0..max_evaluations {
        let fx = f(x)?;
        if fx == 0.0 {
            return Ok(Some(NewtonRoot { x, evaluated: true }));
        }
        pts.push((x, fx));
        let k = pts.len();
        let slope = match k {
            1 => slope0,
            _ => (fx - pts[k - 2].1) / (x - pts[k - 2].0),
        };
        if !(slope < 0.0 && slope.is_finite()) {
            return Ok(None);
        }
        let secant = -fx / slope;
        let mut step = secant;
        if k >= 3 {
            let q = inverse_quadratic(&pts[k - 3..]) - x;
            if q.is_finite() && q * secant > 0.0 && q.abs() <= 2.0 * secant.abs() {
                step = q;
            }
        }
        // the bracket: the largest x with f > 0 and the smallest with f < 0
        let lo = pts
            .iter()
            .filter(|p| p.1 > 0.0)
            .map(|p| p.0)
            .fold(f64::NEG_INFINITY, f64::max);
        let hi = pts
            .iter()
            .filter(|p| p.1 < 0.0)
            .map(|p| p.0)
            .fold(f64::INFINITY, f64::min);
        let next = x + step.clamp(-max_step, max_step);
        let bracketed = lo.is_finite() && hi.is_finite();
        if bracketed && !(next > lo.min(hi) && next < lo.max(hi)) {
            x = 0.5 * (lo + hi);
            continue;
        }
        if !(range.0..=range.1).contains(&next) {
            return Ok(None);
        }
        // the secant step's relative error: 4(f″/2f′)(|s| + |x − x′|) from three points, 1 from two
        let relative = if k >= 3 {
            let (p, q) = (pts[k - 3], pts[k - 2]);
            let f2 = ((fx - q.1) / (x - q.0) - (q.1 - p.1) / (q.0 - p.0)) / (x - p.0);
            EXTRAPOLATION_SAFETY * (f2 / slope).abs() * (secant.abs() + (x - q.0).abs())
        } else {
            1.0
        };
        // the last point's error is the step (to within `relative` of it); the predicted slope
        // of the first step measures nothing
        if k >= 2 && step.abs().max(secant.abs()) * (1.0 + relative) <= tol {
            return Ok(Some(NewtonRoot { x, evaluated: true }));
        }
        if k >= 3 && relative * secant.abs() <= tol && secant.abs() <= max_step {
            return Ok(Some(NewtonRoot {
                x: x + secant,
                evaluated: false,
            }));
        }
        x = next;
    }
    Ok(None)
}

/// Inverse quadratic interpolation at f = 0 through three points (NaN when two values
/// coincide).
fn inverse_quadratic(p: &[(f64, f64)]) -> f64 {
    let ((x0, f0), (x1, f1), (x2, f2)) = (p[0], p[1], p[2]);
    x0 * f1 * f2 / ((f0 - f1) * (f0 - f2))
        + x1 * f0 * f2 / ((f1 - f0) * (f1 - f2))
        + x2 * f0 * f1 / ((f2 - f0) * (f2 - f1))
}

/// r = A + x(R_o − A), exactly R_o at x = 1 (where the pressure is zero: one ulp inside, its
/// edge term φ(R_o)/√(R_o² − r²) is the root's rounding over 1e-8 R_o).
pub(super) fn fraction_radius(a: f64, r_o: f64, x: f64) -> f64 {
    if x >= 1.0 {
        r_o
    } else {
        a + x * (r_o - a)
    }
}

/// The slope of the edge coefficient at R_o, whose edge value is `at_r_o`: a secant through
/// it and the nearest other edge value of `edges` (c, f(c)) between 10⁻⁵D and 10⁻²D away;
/// `None` when there is none.
pub(super) fn secant_slope(edges: &[(f64, f64)], r_o: f64, at_r_o: f64, d: f64) -> Option<f64> {
    let near = edges
        .iter()
        .filter(|(c, _)| (1e-5 * d..=1e-2 * d).contains(&(c - r_o).abs()))
        .min_by(|x, y| (x.0 - r_o).abs().total_cmp(&(y.0 - r_o).abs()))?;
    Some((near.1 - at_r_o) / (near.0 - r_o))
}

/// The variants' R_o (⌈3n/4⌉ points; half the modes and 2/3 of the heights) and the solves
/// they took: ((R_o fewer nodes, R_o half terms), the coarse variants' spread, solves). With
/// [`HoledParams::split_variants`] the half-terms variant coarsens the modes only and two more
/// coarsen the heights and ξ_l alone, the spread the sum of their |changes|; without, the
/// spread is the one variant's |change|.
pub(super) fn estimate(
    setup: &Setup,
    plate: &SinglePlate,
    params: &HoledParams,
    found: &Found,
) -> Result<((f64, f64), f64, usize), RecedingError> {
    let (r_o, b) = (found.r_o, plate.load().outer());
    if !(params.coarse_modes > 0.0 && params.coarse_modes < 1.0) {
        return Err(crate::error::InputError::Parameter {
            field: "holed coarse_modes",
            value: params.coarse_modes,
            reason: "a fraction of the hole modes strictly between 0 and 1",
        }
        .into());
    }
    // each variant's R_o by one Newton step from R_o: its change is ~1e-6 D or less, where the
    // step's error, ∝ the change squared, is far below it; a larger change gets the search
    let at_r_o = found.at_r_o();
    let (slope, solves) = match found.slope(setup.d) {
        Some(s) => (s, 0),
        None => {
            let h = 1e-3 * setup.d;
            let warm = found.warm.as_ref();
            let n = setup.nodes_for(params.nodes);
            let up = setup.crack(r_o + h, n, params, &[], warm, None)?.edge;
            ((up - at_r_o) / h, 1)
        }
    };
    // each variant from the search's correction, solved at the anchor x (R_o, or the last
    // radius when R_o was extrapolated from it: the fewer-nodes variant there takes the tables
    // the setup kept): its change is −(f_v(x) − f(x) + f(R_o))/f′ (f(R_o) zero when
    // extrapolated), the difference at x of two edge coefficients whose slopes differ by as
    // little as their roots do; at x = R_o the Newton step from R_o as before
    let (x, f_x) = found.anchor;
    let shift = f_x - at_r_o;
    let variant = |setup: &Setup, p: &HoledParams| -> Result<(f64, usize), RecedingError> {
        let step = -(setup
            .crack(
                x,
                setup.nodes_for(p.nodes),
                p,
                &[],
                found.warm.as_ref(),
                None,
            )?
            .edge
            - shift)
            / slope;
        if step.is_finite() && step.abs() < 0.01 * setup.d {
            return Ok((r_o + step, 1));
        }
        setup
            .search(b, p.nodes, p, Some((r_o, slope)), &[])
            .map(|f| (f.r_o, f.solves))
    };
    let fewer = HoledParams {
        nodes: (3 * params.nodes).div_ceil(4).max(4),
        ..*params
    };
    let half = HoledParams {
        hole: HoleParams {
            terms: Some(((setup.modes.len() as f64 * params.coarse_modes) as usize).max(1)),
            ..params.hole
        },
        heights: (params.heights / 3 * 2).max(4),
        xi_l: if params.vary_xi_l {
            params.xi_l * 2.0 / 3.0
        } else {
            params.xi_l
        },
        ..*params
    };
    let coarse =
        |p: &HoledParams| Setup::sharing(plate, p, Some(setup)).and_then(|s| variant(&s, p));
    if !params.split_variants {
        let (r1, r2) = rayon::join(|| variant(setup, &fewer), || coarse(&half));
        let ((r1, s1), (r2, s2)) = (r1?, r2?);
        return Ok(((r1, r2), (r2 - r_o).abs(), solves + s1 + s2));
    }
    // each coarsening alone: in one variant their changes can cancel (measured: ξ_l's +1.1e-10
    // R_o against the modes' and heights' on (A/D, B/A, ν) = (0.82, 1.48, 0.32))
    let modes = HoledParams {
        hole: half.hole,
        ..*params
    };
    let heights = HoledParams {
        heights: half.heights,
        ..*params
    };
    let xi = HoledParams {
        xi_l: half.xi_l,
        ..*params
    };
    let ((r1, r2), (r3, r4)) = rayon::join(
        || rayon::join(|| variant(setup, &fewer), || coarse(&modes)),
        || rayon::join(|| coarse(&heights), || coarse(&xi)),
    );
    let ((r1, s1), (r2, s2), (r3, s3), (r4, s4)) = (r1?, r2?, r3?, r4?);
    let spread = (r2 - r_o).abs() + (r3 - r_o).abs() + (r4 - r_o).abs();
    Ok(((r1, r2), spread, solves + s1 + s2 + s3 + s4))
}
