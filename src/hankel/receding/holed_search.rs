//! The search for R_o of the holed two-plate model ([`super::holed`]) and its error estimate:
//! the trial contact radii of module `crack` bracketed by the receding solver's scan
//! ([`super::search::root`]) and refined by inverse interpolation that stops on its step
//! ([`crate::numerics::secant::refine`]), every edge value kept so that none is computed twice,
//! each radius's crack iteration started from the correction of the nearest radius solved.
//!
//! - [`Setup::search`]: R_o, the solve at R_o (reused from the search when no pressure is asked
//!   for) and the edge values (c, c·φ(c)/p̄(0)) the search computed;
//! - [`estimate`]: the R_o of the two coarser variants (⌈3n/4⌉ Nyström points; half the hole
//!   modes and 2/3 of the heights), each one Newton step from R_o with the slope of the edge
//!   coefficient taken as a secant through two of the search's own edge values (a solve at
//!   R_o + 10⁻³D only when the search left none between 10⁻⁵D and 10⁻²D of R_o); the two
//!   variants run in parallel (rayon).
//!
//! # Accuracy
//!
//! The secant's relative error is about f″δ/f′ for points δ ≤ 10⁻²D apart; the Newton step's
//! error is that times the step, below 10⁻⁸D for the steps (≤ 10⁻⁶D) of Table 1. Measured as the
//! estimate against a finer run: `tests/hankel/two_plate_hole_fast.rs`.
//!
//! # Cost
//!
//! Two solves fewer per geometry than a fresh solve at R_o and a secant solve (13 → 11 on Table 1
//! row 1), and two more than Brent's method, whose last steps shrink the bracket around a root
//! it already has (11 → 9: 3 scan points, 4 refinements, 2 variants); the warm start saves one
//! crack iteration of three on the radii near R_o; the variants' solves on two cores at once,
//! the half-terms variant's setup sharing the slab's midplane curve and the corner table
//! ([`Setup::sharing`]). The scan from B + 0.45D instead of B (R_o − B is 0.38–0.56D on
//! Table 1) brackets R_o in two solves instead of three or four: all twelve rows took 95
//! radii instead of 110 at --tol 1e-6 and 79 at 1e-3, R_o moved ≤ 3.2e-10 R_o (by turns
//! against main, module [`super::holed`]'s Cost). Timed by example 19.

use super::contact::RecedingError;
use super::holed_params::HoledParams;
use super::holed_setup::{Crack, Setup};
use super::search::{root, Scan};
use crate::hankel::hole::fit::Fit;
use crate::hankel::hole::HoleParams;
use crate::joint::SinglePlate;
use crate::numerics::secant::refine;

/// Where [`Setup::search`]'s scan starts, beyond B in D.
const SCAN_FROM: f64 = 0.45;

/// What [`Setup::search`] found.
pub(super) struct Found {
    /// The contact radius R_o.
    pub(super) r_o: f64,
    /// The solve at R_o (with the pressure at the radii asked for).
    pub(super) last: Crack,
    /// Contact radii solved.
    pub(super) solves: usize,
    /// Crack iterations over those radii.
    pub(super) iterations: usize,
    /// Every edge value of the search, (c, c·φ(c)/p̄(0)).
    pub(super) edges: Vec<(f64, f64)>,
}

impl Setup {
    /// R_o with `n` Nyström points ([`Setup::nodes_for`]: more for wide loads; bracketing
    /// `near` first) and the contact pressure at
    /// r = A + x(R_o − A) for x in `at`.
    pub(super) fn search(
        &self,
        b: f64,
        n: usize,
        params: &HoledParams,
        near: Option<f64>,
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
        // the receding solver's scan for the bracket only (an infinite tolerance ends its
        // Brent refinement before any evaluation), then refine from the scan's last points
        // the scan starts where R_o lies on Table 1 (B + 0.38…0.56 D) and on the tiers' survey,
        // so that two solves bracket it, and scans outward or inward from there as before
        let scan = Scan {
            b: b + (SCAN_FROM * self.d).min(params.reach * self.d),
            d: self.d,
            step: params.step * self.d,
            end: b + params.reach * self.d,
            tol: f64::INFINITY,
            max_iterations: 100,
        };
        root(&mut |c| edge(c, &mut seen), &scan, near)?.ok_or(RecedingError::NotFound {
            from: b,
            to: scan.end,
        })?;
        let known: Vec<(f64, f64)> = seen.iter().map(|(c, k)| (*c, k.edge)).collect();
        let r_o = refine(
            &mut |c| edge(c, &mut seen),
            &known,
            params.rel_tol * self.d,
            100,
        )?
        .x;
        let edges: Vec<(f64, f64)> = seen.iter().map(|(c, k)| (*c, k.edge)).collect();
        let mut solves = seen.len();
        let mut iterations: usize = seen.iter().map(|(_, k)| k.iterations).sum();
        let reuse = seen.iter().position(|(c, _)| *c == r_o);
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
            solves,
            iterations,
            edges,
        })
    }
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
    let (slope, solves) = match secant_slope(&found.edges, found.r_o, found.last.edge, setup.d) {
        Some(s) => (s, 0),
        None => {
            let h = 1e-3 * setup.d;
            let warm = found.last.fit.as_ref();
            let n = setup.nodes_for(params.nodes);
            let up = setup.crack(r_o + h, n, params, &[], warm, None)?.edge;
            ((up - found.last.edge) / h, 1)
        }
    };
    // the fewer-nodes variant starts from the search's correction (same modes); the
    // half-terms one has other modes and starts from none
    let variant = |setup: &Setup, p: &HoledParams| -> Result<(f64, usize), RecedingError> {
        let step = -setup
            .crack(
                r_o,
                setup.nodes_for(p.nodes),
                p,
                &[],
                found.last.fit.as_ref(),
                None,
            )?
            .edge
            / slope;
        if step.is_finite() && step.abs() < 0.01 * setup.d {
            return Ok((r_o + step, 1));
        }
        setup
            .search(b, p.nodes, p, Some(r_o), &[])
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
