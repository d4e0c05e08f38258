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
//! **Two plates.** Their rim is not bounded this way, so the two-plate tables refuse a rim.
//! A free rim relaxes the infinite plates' bending moment (M_r ∝ 1/r² beyond R_o), which bends
//! the plates uniformly and moves R_o algebraically: on Table 1's first row (A = D = 0.1 in,
//! B = 0.31 in, ν 0.3) the holed route at 1e-8 gives R_o(∞) − R_o(C) = 7.1e-5, 1.78e-5 and
//! 4.47e-6 in at C = 3, 6 and 12 in. That is 0.64 D³/C² to 1 %, and 2.65e-4 in (7.5e-4 of
//! R_o) at Table 1's C = 1.54 in.
//!
//! # Accuracy
//!
//! The slope's floor: example 30's `slopes` (the near domain's corners and random plates over
//! the near and far domains, `docs/tables.md`) found the smallest slope 0.0145 P/D, at the
//! near domain's corner A/D = 0.25, (B − A)/D = 0.15, ν = 0 (the narrowest load carries the
//! least force); [`SINGLE_PLATE_SLOPE_MIN`] is half of it. The bound itself was at least 24×
//! the actual shift of R_o with the slope the route measured
//! ([`crate::hankel::hole::rim`]). The tables' rimmed answers against the Hankel route with
//! the rim: example 30's `check` and `tests/table/rim.rs`.
//!
//! # Cost
//!
//! One exponential.
//!
//! ```
//! use boltzone::table::rim::single_plate_rim_bound;
//! // Table 1's first row with its rim: C = 1.54 in, R_o ≈ 0.4032 in, D = 0.1 in
//! assert!(single_plate_rim_bound(1.54, 0.4032, 0.1) < 1e-8);
//! // a rim a thickness beyond R_o bounds nothing useful
//! assert!(single_plate_rim_bound(0.5032, 0.4032, 0.1) > 1e-2);
//! ```

use crate::hankel::hole::rim::rim_bound;

/// The smallest |∂σ_z/∂r| at R_o over the tables' domain, in P/D (mean pressure P, one plate's
/// thickness D): half the smallest measured (module docs).
pub const SINGLE_PLATE_SLOPE_MIN: f64 = 0.007;

/// The bound (module docs) on |R_o(C) − R_o(∞)| for the single plate 2D thick with a free rim
/// at `c`, the infinite plate's separation radius `r_o` (the top of its bar) and one plate's
/// thickness `d`, in their length unit; infinite when C ≤ R_o.
pub fn single_plate_rim_bound(c: f64, r_o: f64, d: f64) -> f64 {
    rim_bound(c, r_o, d, SINGLE_PLATE_SLOPE_MIN / d, 1.0)
}
