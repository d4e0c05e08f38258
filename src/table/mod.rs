//! Instant answers from tables built offline, with honest error bars.
//!
//! - [`decay`]: the decay law of the hole's disturbance along the contact zone, its fit, and
//!   the handover rate;
//! - [`far`]: the far region, R_o = B + D·g(B/D) from the no-hole tables (`data/far.json`,
//!   written by example 25) plus the handover bound;
//! - [`near`]: the near region, R_o/D over (A/D, (B − A)/D, ν) from tensor Chebyshev tables
//!   built by the holed routes at 1e-8 (`data/near.json`, `data/near_single.json`, written by
//!   example 27);
//! - [`lookup`]: R_o of a [`Model`] from whichever of the two answers with the smaller bar;
//! - [`rim`]: the bound a free rim adds to the single plate's answers.
//!
//! # Accuracy
//!
//! `tests/table/` (the tables against fresh solves not used to build them; the decay study).
//!
//! # Cost
//!
//! Microseconds per answer (`benches/table.rs`).
pub mod decay;
pub mod far;
pub mod lookup;
pub mod near;
pub mod rim;

/// Which model a table answers for (both infinite, C = ∞, uniform pressure on A..B, D one
/// plate's thickness).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Model {
    /// Two equal plates D thick, frictionless interface (the report's model, Ch. II.B).
    TwoPlates,
    /// The single plate 2D thick, both faces pressed (Fernlund's substitution, Ch. II.A).
    SinglePlate,
}
