//! R_o of a table [`Model`] with a hole (two equal infinite plates with a frictionless
//! interface, or the single plate 2D thick; uniform pressure on A ≤ r ≤ B, C = ∞) from the
//! tables: the near table ([`super::near`]) and the far table ([`super::far`]), whichever
//! answers with the smaller bar.
//!
//! **Method.** Both tables are looked up where they apply (the near one over A/D ∈ [0.25, 4],
//! (B − A)/D ∈ [0.15, 5], ν ∈ [0, 0.5]; the far one for B/D ≥ 2, A/D ≤ 4 and the contact edge at
//! least 2D beyond the hole, any B/D); the answer is the one with the smaller bar. Where
//! neither applies the error is the near table's (it names the ratio outside it), or, without
//! a hole, the far table's.
//!
//! # Accuracy
//!
//! Each table's own (`tests/table/near.rs`, `tests/table/far.rs`); the handover between them
//! against the FE and the 1e-8 route: `tests/table/two_plates.rs`.
//!
//! # Cost
//!
//! Two lookups, about a microsecond (`benches/table.rs`).
//!
//! ```
//! use boltzone::table::{lookup::separation_radius, Model};
//! // Table 1's first row at C = ∞ (A/D = 1, B/A = 3.1) and the same plates pressed to B = 30D
//! let near = separation_radius(Model::TwoPlates, 0.1, 0.31, 0.1, 0.3, 1e-3)?;
//! let far = separation_radius(Model::TwoPlates, 0.1, 3.0, 0.1, 0.3, 1e-6)?;
//! assert!(near.converged && far.converged && far.value > 3.0);
//! // the single plate 2D thick: its contact reaches further
//! let single = separation_radius(Model::SinglePlate, 0.1, 0.31, 0.1, 0.3, 1e-3)?;
//! assert!(single.converged && single.value > near.value);
//! # Ok::<(), boltzone::InputError>(())
//! ```

use super::{far, near, Model};
use crate::error::InputError;
use crate::value::Value;

/// R_o of `model` (module docs) with hole `a`, load outer radius `b`, plate thickness `d` (one
/// plate; the single plate is 2D thick), Poisson's ratio `nu`, converged when the bar is within
/// `tol`·R_o.
pub fn separation_radius(
    model: Model,
    a: f64,
    b: f64,
    d: f64,
    nu: f64,
    tol: f64,
) -> Result<Value, InputError> {
    if !(0.0..=near::NU_MAX).contains(&nu) {
        return Err(InputError::Parameter {
            field: "Poisson's ratio (tables)",
            value: nu,
            reason: "within 0..0.5 for the tables (the far table's handover bound is measured \
                     at 0, 0.3 and 0.45)",
        });
    }
    let near = if a > 0.0 {
        Some(near::separation_radius(model, a, b, d, nu, tol))
    } else {
        None
    };
    let far = far::separation_radius(model, a, b, d, tol);
    match (near, far) {
        (Some(Ok(n)), Ok(f)) => Ok(if f.error < n.error { f } else { n }),
        (Some(Ok(n)), Err(_)) => Ok(n),
        (_, Ok(f)) => Ok(f),
        (Some(Err(e)), Err(_)) | (None, Err(e)) => Err(e),
    }
}
