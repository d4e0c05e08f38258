//! Adapters to the single-plate models for the comparison: R_o to a wanted relative accuracy.
//!
//! - [`single_fem`]: the FE model of [`crate::fem::single`] (Q9, half plate with a midplane
//!   roller, finite rim C) on its refinement levels (element size halved at A, B and the
//!   previous R_o) until the error estimate of [`crate::numerics::convergence::level_estimate`] (the
//!   largest of the last three changes shrunk at rate 2 per level; no extrapolation) falls
//!   below the tolerance; at least three levels. [`crate::fem::single::single_plate_r_o`] runs the
//!   same levels and estimate with a fixed number of levels.
//! - [`single_hankel`]: the Hankel-transform plate with the hole correction
//!   ([`crate::hankel::hole::single_plate_separation`]), an infinite plate: R_o with the error
//!   estimate of that module (bracket, slab quadrature and hole residual).
//!
//! # Accuracy
//!
//! Every R_o to the tolerance asked by its own estimate: `tests/compare/tables.rs`
//! (`fe_level_estimate_covers_an_overshooting_sequence`, `table1_end_to_end`); the FE and
//! Hankel routes agree within their estimates in `tests/fem/hole_agreement.rs`.
//!
//! # Cost
//!
//! Example 16 (error bars) and example 13 (per map point); `cargo bench --bench contact`.
//!
//! ```
//! use boltzone::compare::{single::single_fem, Geometry};
//! use boltzone::OuterRadius;
//! let g = Geometry::from_ratios(0.1, 1.0, 3.1, 1.54, 0.3)?;
//! let (r, info) = single_fem(&g.single_plate(OuterRadius::Finite(1.54))?, 1e-3)?;
//! assert!(r.error <= 1e-3 * r.value && info.levels >= 3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::fem::single::{solve, SingleParams};
use crate::fem::FemError;
use crate::hankel::hole::{single_plate_separation, HoleParams};
use crate::hankel::separation::{SeparationError, SeparationParams};
use crate::joint::SinglePlate;
use crate::value::Value;

/// Sizes of the FE study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FemStudy {
    /// Levels solved.
    pub levels: usize,
    /// Equations of the finest level.
    pub dofs: usize,
}

/// Single-plate R_o by FE to relative accuracy `tolerance` (module docs).
pub fn single_fem(plate: &SinglePlate, tolerance: f64) -> Result<(Value, FemStudy), FemError> {
    // The FE defaults (first elements 0.5 D at the foci, growth 1.25 radially and 1.5 axially)
    // were the cheapest for 0.1 % over 68 map points among first sizes 0.35/0.5, radial
    // growths 1.15/1.25/1.35 and axial growths 1.3/1.5 (worst actual error 1.5e-4 against
    // nested uniform references; the growth 1.35 needed a fifth level at 10 points).
    let params = SingleParams {
        tolerance,
        levels: crate::fem::single::MAX_LEVELS,
        ..SingleParams::default()
    };
    let s = solve(plate, &params)?;
    Ok((
        Value {
            value: s.r_o,
            error: s.r_o_error,
            converged: s.converged,
        },
        FemStudy {
            levels: s.info.levels.len(),
            dofs: s.info.dofs,
        },
    ))
}

/// Single-plate R_o by Hankel transforms with the hole correction (infinite plate; module docs).
pub fn single_hankel(plate: &SinglePlate, tolerance: f64) -> Result<Value, SeparationError> {
    crate::error::positive("single-plate tolerance", tolerance)?;
    // The search's own tolerance far below the wanted one; the hole's doubling stops when R_o
    // moves by less than a tenth of it.
    let sep = SeparationParams {
        rel_tol: 1e-3 * tolerance,
        ..Default::default()
    };
    let hole = HoleParams {
        r_o_tolerance: 0.1 * tolerance,
        ..Default::default()
    };
    let (s, _) = single_plate_separation(plate, &sep, &hole)?;
    Ok(Value::with_tolerance(s.r_o, s.r_o_error, tolerance))
}
