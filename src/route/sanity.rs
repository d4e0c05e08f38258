//! Plausibility of magnitudes: warnings for inputs that look like a unit slip — a modulus in
//! GPa typed where MPa was meant, SI numbers run in inches, a bearing pressure no metal carries
//! elastically, a deflection that is no longer small against the plate. The numbers are solved
//! as given (nothing is clamped or changed); a front end prints each warning naming its flag or
//! key, and `--strict` turns them into bad input (exit 2).
//!
//! The bounds are physical, in SI: Young's modulus of structural solids lies between about
//! 1 GPa (stiff polymers, wood across the grain) and 1.2 TPa (diamond); a bearing pressure above
//! 2 % of E strains the face beyond what any metal carries elastically (steel yields near 0.1–1 %);
//! a mean deflection under the nut beyond 1 % of the plate's thickness leaves small-strain
//! elasticity, on which every route rests.
//!
//! # Accuracy
//!
//! No numerics: thresholds; `tests/cli/sanity.rs` runs the slips the issue names.
//!
//! # Cost
//!
//! Nanoseconds.
//!
//! ```
//! use boltzone::route::sanity::{inputs, Slip};
//! use boltzone::units::UnitSystem;
//! // 210 typed as E in mm-MPa-N: 210 MPa, a modulus typed in GPa
//! let w = inputs(UnitSystem::MmMpaN, [210.0, 210.0], 100.0);
//! assert_eq!(w[0].slip, Slip::Modulus { plate: 0 });
//! assert!(w[0].message.contains("GPa"));
//! assert!(inputs(UnitSystem::MmMpaN, [210e3, 210e3], 100.0).is_empty());
//! ```

use crate::units::UnitSystem;

/// Which input a warning is about (each front end names it: a flag, a scene key).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slip {
    /// Young's modulus of plate 0 (upper) or 1 (lower).
    Modulus {
        /// 0 for the upper plate, 1 for the lower.
        plate: usize,
    },
    /// The bearing pressure (or the force that sets it).
    Pressure,
    /// The computed deflection under the nut (an output: the pressure or the modulus is
    /// suspect).
    Deflection,
}

/// One plausibility warning.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// The input it is about.
    pub slip: Slip,
    /// What looks wrong and the likely slip.
    pub message: String,
}

/// Smallest plausible Young's modulus of a clamped part, Pa.
pub const MIN_MODULUS: f64 = 1e9;
/// Largest plausible Young's modulus (diamond, about 1.05–1.2 TPa), Pa.
pub const MAX_MODULUS: f64 = 1.2e12;
/// Largest plausible bearing pressure relative to E.
pub const MAX_PRESSURE_OVER_MODULUS: f64 = 0.02;
/// Largest plausible mean deflection under the nut relative to the plate's thickness.
pub const MAX_DEFLECTION_OVER_THICKNESS: f64 = 0.01;

/// Warnings for the moduli `e` (upper, lower plate) and the mean bearing pressure `p`, both in
/// the stress unit of `units`.
pub fn inputs(units: UnitSystem, e: [f64; 2], p: f64) -> Vec<Warning> {
    let si = units.stress();
    let (_, st, _) = units.symbols();
    let mut out = Vec::new();
    // the lower plate is named only where its modulus differs from the upper plate's
    let plates = if e[1] == e[0] { &e[..1] } else { &e[..] };
    for (plate, &e) in plates.iter().enumerate() {
        let pa = e * si;
        let likely = if pa < MIN_MODULUS {
            Some(match units {
                UnitSystem::MmMpaN => {
                    "a modulus typed in GPa where MPa is meant (210 GPa = 210000 MPa)"
                }
                UnitSystem::MPaN => "a modulus typed in GPa or MPa where Pa is meant",
                UnitSystem::InPsiLbf => {
                    "a modulus typed in ksi or Msi where psi is meant (30 Msi = 30e6 psi)"
                }
            })
        } else if pa > MAX_MODULUS {
            Some(match units {
                UnitSystem::InPsiLbf => {
                    "SI numbers (Pa) run in inches and psi: add --units m-Pa-N (scene: units = \"m-Pa-N\")"
                }
                UnitSystem::MmMpaN => "a modulus typed in Pa where MPa is meant",
                UnitSystem::MPaN => "a modulus beyond diamond's: a typing slip",
            })
        } else {
            None
        };
        if let Some(likely) = likely {
            out.push(Warning {
                slip: Slip::Modulus { plate },
                message: format!(
                    "E = {e} {st} is {:.3e} Pa, outside the {:.0e}–{:.1e} Pa of structural solids; \
                     likely {likely}",
                    pa, MIN_MODULUS, MAX_MODULUS
                ),
            });
        }
    }
    let e_min = e[0].min(e[1]);
    if p > MAX_PRESSURE_OVER_MODULUS * e_min {
        out.push(Warning {
            slip: Slip::Pressure,
            message: format!(
                "the bearing pressure {p} {st} is {:.1} % of E = {e_min} {st}: no metal carries \
                 that elastically (a unit slip in the force, the pressure or E?)",
                100.0 * p / e_min
            ),
        });
    }
    out
}

/// A warning for the mean deflection `w` under the nut of a plate `d` thick (the same length
/// unit), or None.
pub fn deflection(w: f64, d: f64) -> Option<Warning> {
    (w.abs() > MAX_DEFLECTION_OVER_THICKNESS * d).then(|| Warning {
        slip: Slip::Deflection,
        message: format!(
            "the mean deflection under the nut, {:.3e}, is {:.1} % of the plate thickness {d}: \
             beyond small-strain elasticity (a unit slip in the pressure, the force or E?)",
            w.abs(),
            100.0 * w.abs() / d
        ),
    })
}
