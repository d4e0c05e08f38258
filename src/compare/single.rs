//! Adapters to the single-plate models for the comparison: R_o to a wanted relative accuracy.
//!
//! - [`single_fem`]: the FE model of [`crate::fem::single`] (Q9, half plate with a midplane
//!   roller, finite rim C), refined by halving every element (nested meshes) until the error
//!   estimate of [`last_level_estimate`] (the larger of the last change and a quarter of the
//!   one before; no extrapolation) falls below the tolerance; at least three levels. This is an
//!   adapter: [`crate::fem::single::single_plate_r_o`] runs a fixed number of levels, which
//!   costs 4× per unneeded level on a design map, and extrapolates, which the irregular
//!   convergence documented at [`last_level_estimate`] makes unsafe.
//! - [`single_hankel`]: the Hankel-transform plate with the hole correction
//!   ([`crate::hankel::hole::single_plate_separation`]), an infinite plate: R_o with the error
//!   estimate of that module (bracket, slab quadrature and hole residual).
//!
//! ```
//! use boltzone::compare::{single::single_fem, Geometry};
//! use boltzone::OuterRadius;
//! let g = Geometry::from_ratios(0.1, 1.0, 3.1, 1.54, 0.3).unwrap();
//! let (r, info) = single_fem(&g.single_plate(OuterRadius::Finite(1.54)).unwrap(), 1e-3).unwrap();
//! assert!(r.error <= 1e-3 * r.value && info.levels >= 3);
//! ```

use super::Value;
use crate::fem::single::{crossing_levels, SingleParams};
use crate::fem::FemError;
use crate::hankel::hole::{single_plate_separation, HoleParams};
use crate::hankel::separation::{SeparationError, SeparationParams};
use crate::joint::SinglePlate;

/// Most FE levels [`single_fem`] tries (the finest has 4⁶ times the coarsest's elements).
pub const MAX_FEM_LEVELS: usize = 7;

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
    crate::error::positive("single-plate tolerance", tolerance)?;
    // The FE defaults (first element 0.5 D at A and B, growth 1.15) were the cheapest for
    // 0.1 % over the map's range among coarse sizes 0.35/0.5/0.7 and growths 1.15/1.3.
    let params = SingleParams::default();
    let mut values: Vec<f64> = Vec::new();
    for (l, level) in crossing_levels(plate, &params)?
        .take(MAX_FEM_LEVELS)
        .enumerate()
    {
        let level = level?;
        values.push(level.r_o);
        if let Some(v) = last_level_estimate(&values) {
            if v.error <= tolerance * v.value || l + 1 == MAX_FEM_LEVELS {
                return Ok((
                    v,
                    FemStudy {
                        levels: values.len(),
                        dofs: level.dofs,
                    },
                ));
            }
        }
    }
    unreachable!("the last level returns")
}

/// The error of the last of a halving sequence: max(|d₂|, |d₁|/4) with d₂, d₁ the last two
/// changes; `None` with fewer than three values. The value is not extrapolated: on the map's
/// range the single-plate R_o converges irregularly (observed orders from −4 to 10 between
/// levels, overshoots such as 0.21874, 0.22189, 0.22235, 0.22225, 0.22223 for A/D = 1,
/// B/A = 1.3, where Richardson on the first three levels moved the value away from the limit).
/// The last change bounds the remaining error when the rate is at least 1; |d₁|/4, what the
/// last change would be at rate 2, guards against a last change that is small by accident.
pub fn last_level_estimate(v: &[f64]) -> Option<Value> {
    let n = v.len();
    if n < 3 {
        return None;
    }
    let (d1, d2) = (v[n - 2] - v[n - 3], v[n - 1] - v[n - 2]);
    Some(Value {
        value: v[n - 1],
        error: d2.abs().max(0.25 * d1.abs()),
    })
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
    Ok(Value {
        value: s.r_o,
        error: s.error,
    })
}
