//! A free rim r = C on the single plate's table answers: the bound on |R_o(C) − R_o(∞)| that
//! joins the tables' bar, so a rimmed single plate whose rim is far from its contact edge is
//! answered from the infinite plate's tables.
//!
//! **Bound.** [`crate::hankel::hole::rim::rim_bound`]: the traction the infinite plate leaves
//! on r = C, at most the mean pressure P, reaches R_o through the slowest symmetric
//! Papkovich–Fadle mode, e^(−2.1062 (C − R_o)/D)·√(C/R_o), and moves the midplane σ_z's zero
//! by that over its slope there. The tables do not hold the slope, so the bound takes its
//! smallest value over the tables' domain, [`SINGLE_PLATE_SLOPE_MIN`]·P/D, and R_o at the top
//! of the table's bar (the bound grows with R_o).
//!
//! **Two plates.** Their rim is felt through the decaying modes and, first, through bending:
//! a free rim relaxes the infinite plates' bending moment (M_r ∝ 1/r² beyond R_o), which bends
//! them uniformly and moves R_o algebraically. To first order in that bending, with the
//! moments' own 1/C² corrections, the shift is
//!
//! δ = R_o(∞) − R_o(C) = κ·D³/(C² − μD²),
//!
//! κ and μ functions of A/D, (B − A)/D and ν ([`two_plates_rim_shift`]). They are tabulated
//! (`data/near_rim.json`, example 31: tensor Chebyshev grids in (ln A/D, w, ν) over
//! A/D ∈ [0.25, 4], ν ∈ [0, 0.5] and two panels in w, [0.15, 1.2] mapped by ln w and [1.2, 4]
//! linear, 7 × 7 × 4 points each; each node's κ and μ through R_o(∞) and R_o(C)
//! at C = R_o(∞) + 22D and + 40D by the holed route at 1e-8), with the near table's bar
//! ([`super::near`]: the coefficients' tails and the nodes' errors through the cardinal
//! functions). The law's own residual, measured against the route at u = (C − R_o)/D = 4, 6,
//! 9, 14 (example 31), is at most 0.10/u³ of δ; the bar takes [`LAW_K`]/u³ + [`LAW_FLOOR`] of
//! δ, and the tables refuse u < [`U_MIN`].
//!
//! # Accuracy
//!
//! The single plate's slope floor: example 30's `slopes` (the near domain's corners and random plates over
//! the near and far domains, `docs/tables.md`) found the smallest slope 0.0145 P/D, at the
//! near domain's corner A/D = 0.25, (B − A)/D = 0.15, ν = 0 (the narrowest load carries the
//! least force); [`SINGLE_PLATE_SLOPE_MIN`] is half of it. The bound itself was at least 24×
//! the actual shift of R_o with the slope the route measured
//! ([`crate::hankel::hole::rim`]). The tables' rimmed answers against the Hankel route with
//! the rim: example 30's `check` and `tests/table/rim.rs`. The two plates' law and table:
//! example 31 and `tests/table/rim.rs` against the holed route with the rim.
//!
//! # Cost
//!
//! One exponential (single plate); two tensor sums over 196 coefficients each (two plates).
//!
//! ```
//! use boltzone::table::rim::single_plate_rim_bound;
//! // Table 1's first row with its rim: C = 1.54 in, R_o ≈ 0.4032 in, D = 0.1 in
//! assert!(single_plate_rim_bound(1.54, 0.4032, 0.1) < 1e-8);
//! // a rim a thickness beyond R_o bounds nothing useful
//! assert!(single_plate_rim_bound(0.5032, 0.4032, 0.1) > 1e-2);
//! ```

use super::near::{check_domain, Panel};
use crate::error::InputError;
use crate::hankel::hole::rim::rim_bound;
use crate::value::Value;
use serde::Deserialize;
use std::sync::OnceLock;

/// The smallest |∂σ_z/∂r| at R_o over the tables' domain, in P/D (mean pressure P, one plate's
/// thickness D): half the smallest measured (module docs).
pub const SINGLE_PLATE_SLOPE_MIN: f64 = 0.007;

/// The bound (module docs) on |R_o(C) − R_o(∞)| for the single plate 2D thick with a free rim
/// at `c`, the infinite plate's separation radius `r_o` (the top of its bar) and one plate's
/// thickness `d`, in their length unit; infinite when C ≤ R_o.
pub fn single_plate_rim_bound(c: f64, r_o: f64, d: f64) -> f64 {
    rim_bound(c, r_o, d, SINGLE_PLATE_SLOPE_MIN / d, 1.0)
}

/// Largest (B − A)/D of the two plates' rim table (B ≤ 8D: the holed rim route's reach).
pub const W_MAX_TWO: f64 = 4.0;
/// Smallest (C − R_o)/D the two plates' rim table answers.
pub const U_MIN: f64 = 4.0;
/// The law's residual bound, LAW_K/u³ + [`LAW_FLOOR`] of δ: twice the largest measured.
pub const LAW_K: f64 = 0.2;
/// The law's residual floor (of δ): the fit's own, far beyond its nodes.
pub const LAW_FLOOR: f64 = 1e-4;

/// The two plates' rim table as shipped (module docs).
#[derive(Debug, Clone, Deserialize)]
pub struct RimTable {
    /// How and when it was built.
    pub provenance: String,
    /// κ's panels, in increasing w.
    pub kappa: Vec<Panel>,
    /// μ's panels, in increasing w.
    pub mu: Vec<Panel>,
}

/// The shipped rim table (parsed once).
pub fn table() -> &'static RimTable {
    static T: OnceLock<RimTable> = OnceLock::new();
    T.get_or_init(|| {
        let t: RimTable = serde_json::from_str(include_str!("data/near_rim.json"))
            .expect("src/table/data/near_rim.json is written by example 31");
        RimTable {
            kappa: t.kappa.into_iter().map(Panel::with_tails).collect(),
            mu: t.mu.into_iter().map(Panel::with_tails).collect(),
            ..t
        }
    })
}

/// δ = R_o(∞) − R_o(C) of two equal plates D thick (`d`) with hole `a`, uniform pressure to
/// `b`, Poisson's ratio `nu` and a free rim at `c`, given the infinite plates' `r_o` (module
/// docs), as a [`Value`] in the lengths' unit (converged: it carries no tolerance). Errors:
/// a ratio outside the rim table, or the rim within [`U_MIN`]·D of R_o.
pub fn two_plates_rim_shift(
    a: f64,
    b: f64,
    d: f64,
    nu: f64,
    c: f64,
    r_o: f64,
) -> Result<Value, InputError> {
    let (ad, w, u) = (a / d, (b - a) / d, (c - r_o) / d);
    check_domain(ad, w, nu)?;
    if w > W_MAX_TWO {
        return Err(InputError::Parameter {
            field: "(B − A)/D (rim table)",
            value: w,
            reason: "at most 4 for the two plates' rim table (B ≤ 8D)",
        });
    }
    if u.is_nan() || u < U_MIN {
        return Err(InputError::Parameter {
            field: "rim (C − R_o)/D (rim table)",
            value: u,
            reason: "at least 4 for the two plates' rim table",
        });
    }
    let t = table();
    let panel = |ps: &'static [Panel]| ps.iter().find(|p| w <= p.w_hi).or(ps.last());
    let (Some(pk), Some(pm)) = (panel(&t.kappa), panel(&t.mu)) else {
        return Err(InputError::Parameter {
            field: "rim table",
            value: 0.0,
            reason: "not built (example 31 writes src/table/data/near_rim.json)",
        });
    };
    let (kappa, e_kappa) = pk.y(ad, w, nu);
    let (mu, e_mu) = pm.y(ad, w, nu);
    let den = (c / d).powi(2) - mu;
    let delta = kappa / den;
    let error = e_kappa / den
        + kappa.abs() * e_mu / (den * den)
        + delta.abs() * (LAW_K / u.powi(3) + LAW_FLOOR);
    Ok(Value {
        value: d * delta,
        error: d * error,
        converged: true,
    })
}
