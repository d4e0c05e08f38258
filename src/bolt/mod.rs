//! The bolt of a bolted joint: its thread ([`thread`]), its resilience δ_S by VDI 2230's
//! sections ([`compliance`]), the load factor Φ and the preload from a tightening torque or a
//! utilisation of the yield point ([`preload`]).
//!
//! # Accuracy
//!
//! Closed forms of VDI 2230 Part 1 (2015) and ISO 724 / ISO 898-1; `tests/joint/bolt.rs` checks
//! them against hand calculations from the standards' formulas and the M10 joint end to end.
//!
//! # Cost
//!
//! O(1).
//!
//! ```
//! use boltzone::bolt::thread::Thread;
//! let m10 = Thread::metric_coarse("M10")?;
//! assert_eq!(m10.pitch, 1.5);
//! assert!((m10.stress_area() - 58.0).abs() < 0.1); // mm², ISO 898-1 Table 4
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod catalogue;
pub mod compliance;
pub mod preload;
mod table;
pub mod thread;
