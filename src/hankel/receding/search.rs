//! The search for R_o of the receding contact ([`super::contact`]) and the check of its
//! answer, written on closures so that this file needs nothing of the solver's types:
//!
//! - [`root`]: the first sign change of the scaled edge coefficient c·φ(c; c)/p̄(0) from
//!   compressive (> 0) to tensile, outward from the load's outer radius B (or inward when the
//!   contact zone is narrower than the load), refined by Brent's method
//!   ([`crate::numerics::root`]); later changes outward are the far, tiny oscillations of the
//!   solution, not separations;
//! - [`RuleCache`]: the one ξ-rule shared by every solve of a search, widened when the scan
//!   passes its cap;
//! - [`unilateral`]: the contact pressure inside R_o and the gap beyond, sampled and checked
//!   for sign.
//!
//! # Accuracy
//!
//! The contact radius is bracketed and refined until the edge condition holds:
//! `tests/hankel/receding_contact.rs` (`contact_radius_does_not_depend_on_load_scale_or_nu`,
//! `contact_radius_shortcut_matches_the_layer`).
//!
//! # Cost
//!
//! A few Nyström solves per bracket step; example 06.

use super::system::XiRule;
use crate::numerics::root::{brent, first_upward_root, scan_steps};

/// Where and how finely [`root`] looks.
pub(super) struct Scan {
    /// The load's outer radius B, where the scan starts.
    pub(super) b: f64,
    /// The layer's thickness D.
    pub(super) d: f64,
    /// Scan step (a length).
    pub(super) step: f64,
    /// Outer end of the outward scan.
    pub(super) end: f64,
    /// Half-width of the final bracket.
    pub(super) tol: f64,
    /// Brent's iteration cap.
    pub(super) max_iterations: usize,
}

/// The root of `edge` (the scaled edge coefficient as a function of the contact radius);
/// `near`: a guess to bracket first (the fine run's root, for the coarse run). `Ok(None)` when
/// the edge coefficient keeps its sign over the scan.
pub(super) fn root<E>(
    edge: &mut impl FnMut(f64) -> Result<f64, E>,
    scan: &Scan,
    near: Option<f64>,
) -> Result<Option<f64>, E> {
    if let Some(x) = near {
        // a few widening brackets around the guess before the full scan
        let mut w = 0.01 * scan.d;
        while w < 0.2 * scan.d {
            let (lo, hi) = ((x - w).max(scan.b), x + w);
            let (f_lo, f_hi) = (edge(lo)?, edge(hi)?);
            if f_lo > 0.0 && f_hi <= 0.0 {
                return Ok(Some(
                    brent(edge, lo, f_lo, hi, f_hi, scan.tol, scan.max_iterations)?.x,
                ));
            }
            w *= 4.0;
        }
    }
    let f_b = edge(scan.b)?;
    let found = if f_b > 0.0 {
        // outward: the first upward crossing of −edge
        let mut minus = |c: f64| edge(c).map(|v| -v);
        first_upward_root(
            &mut minus,
            (scan.b, -f_b),
            scan.step,
            scan.end,
            scan.tol,
            scan.max_iterations,
        )?
    } else {
        // inward, to the last scan point above the axis
        let inner = scan.b - (scan_steps(scan.b, 0.0, -scan.step).max(1) - 1) as f64 * scan.step;
        first_upward_root(
            edge,
            (scan.b, f_b),
            -scan.step,
            inner,
            scan.tol,
            scan.max_iterations,
        )?
    };
    Ok(found.map(|r| r.x))
}

/// The ξ-rule shared by the solves of one R_o search, and their count.
pub(super) struct RuleCache {
    /// The largest contact radius the rule serves.
    pub(super) cap: f64,
    /// The rule.
    pub(super) rule: XiRule,
    /// Solves counted by [`RuleCache::rule_for`].
    pub(super) solves: usize,
}

impl RuleCache {
    /// The rule for one more solve at contact radius `c`: rebuilt by `make(cap)` for a cap of
    /// at least c and two thicknesses `d` more when c is beyond the current one.
    pub(super) fn rule_for(&mut self, c: f64, d: f64, make: impl Fn(f64) -> XiRule) -> &XiRule {
        if c > self.cap {
            self.cap = c.max(self.cap + 2.0 * d);
            self.rule = make(self.cap);
        }
        self.solves += 1;
        &self.rule
    }
}

/// A sampled value of the wrong sign: (what, where, value).
pub(super) type Violation = (&'static str, f64, f64);

/// Samples the contact `pressure` at r = k·R_o/8 (k = 0…7) and the `gap` at R_o(1 + k/8)
/// (k = 1…8); a negative value beyond rounding (1e-9 of the mean contact pressure 2p̄(0)/R_o²
/// or of the largest gap sampled) is a [`Violation`]. Returns the two minima.
pub(super) fn unilateral(
    r_o: f64,
    p0: f64,
    pressure: impl Fn(f64) -> f64,
    gap: impl Fn(f64) -> f64,
) -> Result<(f64, f64), Violation> {
    let mean = 2.0 * p0 / (r_o * r_o);
    let lowest = |samples: &[(f64, f64)]| {
        samples
            .iter()
            .copied()
            .fold((f64::INFINITY, 0.0), |m, s| if s.0 < m.0 { s } else { m })
    };
    let q: Vec<(f64, f64)> = (0..8)
        .map(|k| r_o * k as f64 / 8.0)
        .map(|r| (pressure(r), r))
        .collect();
    let min_q = lowest(&q);
    if min_q.0 < -1e-9 * mean.abs() {
        return Err(("contact pressure", min_q.1, min_q.0));
    }
    let g: Vec<(f64, f64)> = (1..=8)
        .map(|k| r_o * (1.0 + k as f64 / 8.0))
        .map(|r| (gap(r), r))
        .collect();
    let largest = g.iter().fold(0.0f64, |m, s| m.max(s.0.abs()));
    let min_g = lowest(&g);
    if min_g.0 < -1e-9 * largest {
        return Err(("gap", min_g.1, min_g.0));
    }
    Ok((min_q.0, min_g.0))
}
