//! The search for R_o of [`super::receding`]: a scan for the first sign change of the edge
//! coefficient φ(c; c) from compressive to tensile (outward from the load's outer radius B, or
//! inward when the contact zone is narrower than the load), Brent's method
//! ([`super::root::brent`]) on the bracket, one ξ-rule shared by every solve, and the check of the unilateral conditions
//! on the solution found.

use super::receding::{ContactSolution, Layer, RecedingError, RecedingParams};
use super::receding_system::XiRule;
use super::root::brent;

/// Root of the scaled edge coefficient c·φ(c; c)/p̄(0) with n points; `near`: a guess to
/// bracket first (the fine run's root, for the coarse run).
pub(super) fn root(
    layer: &Layer,
    n: usize,
    params: &RecedingParams,
    near: Option<f64>,
    search: &mut Search,
) -> Result<f64, RecedingError> {
    let p0 = layer.transform.eval(0.0);
    let mut edge = |c: f64| -> Result<f64, RecedingError> {
        let s = search.solve(layer, c, n, params.quad_tol)?;
        Ok(c * s.edge_coefficient() / p0)
    };
    let b = layer.transform.outer();
    let h = params.step * layer.d;
    let end = b + params.reach * layer.d;
    let mut bracket = None;
    if let Some(x) = near {
        // a few widening brackets around the guess before the full scan
        let mut w = 0.01 * layer.d;
        while bracket.is_none() && w < 0.2 * layer.d {
            let (lo, hi) = ((x - w).max(b), x + w);
            let (f_lo, f_hi) = (edge(lo)?, edge(hi)?);
            if f_lo > 0.0 && f_hi <= 0.0 {
                bracket = Some((lo, f_lo, hi, f_hi));
            }
            w *= 4.0;
        }
    }
    if bracket.is_none() {
        // scan for the first change from a compressive (> 0) edge to a tensile one: outward
        // from B, or inward if the edge is already tensile at B (a contact zone narrower
        // than the load); later changes outward are the far, tiny oscillations of the
        // solution, not separations
        let f_b = edge(b)?;
        if f_b > 0.0 {
            let (mut lo, mut f_lo) = (b, f_b);
            while lo < end {
                let hi = (lo + h).min(end);
                let f_hi = edge(hi)?;
                if f_hi <= 0.0 {
                    bracket = Some((lo, f_lo, hi, f_hi));
                    break;
                }
                (lo, f_lo) = (hi, f_hi);
            }
        } else {
            let (mut hi, mut f_hi) = (b, f_b);
            while hi > h {
                let lo = hi - h;
                let f_lo = edge(lo)?;
                if f_lo > 0.0 {
                    bracket = Some((lo, f_lo, hi, f_hi));
                    break;
                }
                (hi, f_hi) = (lo, f_lo);
            }
        }
    }
    let (a, fa, c, fc) = bracket.ok_or(RecedingError::NotFound { from: b, to: end })?;
    let tol = params.rel_tol * layer.d;
    Ok(brent(&mut edge, a, fa, c, fc, tol, params.max_iterations)?.x)
}

/// The ξ-rule shared by the solves of one R_o search, and their count.
pub(super) struct Search {
    pub(super) cap: f64,
    pub(super) rule: XiRule,
    pub(super) solves: usize,
}

impl Search {
    pub(super) fn solve(
        &mut self,
        layer: &Layer,
        c: f64,
        n: usize,
        tol: f64,
    ) -> Result<ContactSolution, RecedingError> {
        if c > self.cap {
            self.cap = c.max(self.cap + 2.0 * layer.d);
            self.rule = layer.rule(self.cap, tol);
        }
        self.solves += 1;
        layer.solve(&self.rule, c, n)
    }
}

/// Samples the contact pressure inside R_o and the gap beyond; a negative value beyond rounding
/// (1e-9 of the mean contact pressure or of the largest gap sampled) is an error.
pub(super) fn verify(s: &ContactSolution, p0: f64) -> Result<(f64, f64), RecedingError> {
    let r_o = s.radius();
    let mean = 2.0 * p0 / (r_o * r_o);
    let mut min_q = (f64::INFINITY, 0.0);
    for k in 0..8 {
        let r = r_o * k as f64 / 8.0;
        let q = s.pressure(r);
        if q < min_q.0 {
            min_q = (q, r);
        }
    }
    if min_q.0 < -1e-9 * mean.abs() {
        return Err(RecedingError::NotUnilateral {
            what: "contact pressure",
            r: min_q.1,
            value: min_q.0,
        });
    }
    let gaps: Vec<(f64, f64)> = (1..=8)
        .map(|k| {
            let r = r_o * (1.0 + k as f64 / 8.0);
            (s.gap(r), r)
        })
        .collect();
    let largest = gaps.iter().fold(0.0f64, |m, g| m.max(g.0.abs()));
    let min_g = gaps
        .iter()
        .copied()
        .fold((f64::INFINITY, 0.0), |m, g| if g.0 < m.0 { g } else { m });
    if min_g.0 < -1e-9 * largest {
        return Err(RecedingError::NotUnilateral {
            what: "gap",
            r: min_g.1,
            value: min_g.0,
        });
    }
    Ok((min_q.0, min_g.0))
}
