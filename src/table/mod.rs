//! Instant answers from tables built offline, with honest error bars.
//!
//! - [`decay`]: the decay law of the hole's disturbance along the contact zone, its fit, and
//!   the handover rate;
//! - [`far`]: the far region, R_o = B + D·g(B/D) from the no-hole tables (`data/far.json`,
//!   written by example 25) plus the handover bound.
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
pub mod near;
pub mod two_plates;
