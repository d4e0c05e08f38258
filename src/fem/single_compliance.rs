//! The member compliance δ_P of the single-plate substitute (a plate 2D thick, both faces
//! pressed over A..B; [`super::single`]) by finite elements, to compare with the two-plate
//! model's ([`crate::contact::compliance`], where δ_P is defined). The single plate is the
//! two-plate joint with its interface welded everywhere, out to the rim: more material carries
//! the load, so its k_P bounds the two-plate one from above.
//!
//! **Method.** The half plate 0 ≤ z ≤ D on the midplane roller of [`super::single`], on the
//! graded levels of [`super::single_levels::level_spacings`] (element size halved at A, B and
//! the load's knots per level). A face pressure: δ_P = 2 f·u/F² (f the consistent load vector
//! of the upper face; the lower face is its mirror); a rigid nut: δ_P = 2δ/F with F the
//! reaction under it. A plate wider than B + 30D (or infinite) is meshed to C' = B + 30D
//! ([`super::single_levels::level_spacings`]); beyond the Papkovich–Fadle decay its free rim
//! differs from the wider plate's by a uniform in-plane stress in the disk, whose Poisson
//! strain moves the faces: δ_P(C) = δ_P(∞) + 2Dν²/(πE(C² − A²)) (the membrane part of the
//! sleeve limit of [`crate::contact::compliance`], exact once C ≫ D), so the mesh's value is
//! shifted from C' to C. The estimate from the levels is [`super::compliance_estimate::estimate`]
//! (the same two error models as the two-plate study: level changes for a pressure, the
//! rate-1 extrapolation of the punch edge for a rigid head).
//!
//! Units: the plate's; δ_P in length per force.
//!
//! # Accuracy
//!
//! `tests/joint/compliance.rs`: against the Hankel slab without a hole
//! ([`crate::hankel::slab_compliance`]) within both estimates, and ≥ the two-plate δ_P.
//!
//! # Cost
//!
//! One factorization per level, 3–8 levels; a Table 1 plate to 0.05 % in milliseconds.
//!
//! ```
//! use boltzone::fem::single_compliance::single_plate_compliance;
//! use boltzone::fem::compliance_estimate::Head;
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let plate = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1, Material::unit(0.3)?,
//!     FaceLoad::uniform(0.1, 0.31, 1.0)?)?;
//! let d = single_plate_compliance(&plate, Head::Pressure, 1e-3)?;
//! assert!(d.compliance.converged && d.compliance.value > 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::compliance_estimate::{estimate, Head};
use super::error::FemError;
use super::recover::internal_forces;
use super::single::{solve_half_plate_with, FaceCondition, SingleParams};
use super::single_levels::{level_spacings, MAX_LEVELS};
use crate::error::InputError;
use crate::joint::{OuterRadius, SinglePlate, FAR_RIM};
use crate::value::Value;

/// δ_P of a single plate with the compliance of each level.
#[derive(Debug, Clone, PartialEq)]
pub struct SingleCompliance {
    /// δ_P, length per force.
    pub compliance: Value,
    /// δ_P of each level, coarse to fine.
    pub levels: Vec<f64>,
}

/// δ_P of `plate` under a face pressure or rigid nut (`head`) to the relative `tolerance`, on
/// at least four and at most [`MAX_LEVELS`] levels (module docs).
pub fn single_plate_compliance(
    plate: &SinglePlate,
    head: Head,
    tolerance: f64,
) -> Result<SingleCompliance, FemError> {
    if !(tolerance > 0.0 && tolerance < 1.0) {
        return Err(InputError::Parameter {
            field: "single-plate compliance tolerance",
            value: tolerance,
            reason: "must lie in (0, 1)",
        }
        .into());
    }
    let params = SingleParams {
        loading: match head {
            Head::Pressure => FaceCondition::Pressure,
            Head::Rigid => FaceCondition::UniformDisplacement,
        },
        tolerance,
        ..SingleParams::default()
    };
    let mut levels = Vec::new();
    let mut result = (f64::NAN, f64::INFINITY);
    for level in 0..MAX_LEVELS as u32 {
        let (radial, axial) = level_spacings(plate, &params, level, None)?;
        let h = solve_half_plate_with(plate, &params, &radial, &axial, None)?;
        let top = h.mesh.top(0);
        levels.push(match head {
            Head::Pressure => {
                let work: f64 = top
                    .iter()
                    .map(|&n| h.loads.forces()[n][1] * h.u[n][1])
                    .sum();
                let f = plate.load().total_force();
                2.0 * work / (f * f)
            }
            Head::Rigid => {
                let ku = internal_forces(&h.mesh, &h.materials, &h.u)?;
                let b = plate.load().outer();
                let (force, delta) = top
                    .iter()
                    .filter(|&&n| h.mesh.nodes()[n][0] <= b * (1.0 + 1e-12))
                    .fold((0.0, 0.0f64), |(f, d), &n| {
                        (f - ku[n][1], d.max(-h.u[n][1]))
                    });
                2.0 * delta / force
            }
        });
        result = estimate(&levels, head);
        if levels.len() >= 4 && result.1 <= tolerance * result.0.abs() {
            break;
        }
    }
    // the mesh's rim (module docs): its membrane correction replaced by the plate's own
    let (a, d) = (plate.hole_radius(), plate.half_thickness());
    let cut = plate.load().outer() + FAR_RIM * d;
    let rim = |c: f64| {
        let m = plate.material();
        2.0 * d * m.poisson_ratio().powi(2)
            / (std::f64::consts::PI * m.youngs_modulus() * (c * c - a * a))
    };
    let shift = match plate.outer_radius() {
        OuterRadius::Finite(c) if c <= cut => 0.0,
        OuterRadius::Finite(c) => rim(c) - rim(cut),
        OuterRadius::Infinite => -rim(cut),
    };
    let value = result.0 + shift;
    let error = result.1;
    Ok(SingleCompliance {
        compliance: Value::with_tolerance(value, error, tolerance),
        levels,
    })
}
