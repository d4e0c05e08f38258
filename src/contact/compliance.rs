//! The clamped parts' compliance δ_P (member compliance) of a bolted joint from the two-plate
//! contact solution, and the member stiffness k_P = 1/δ_P: the number a VDI 2230 calculation
//! needs (the load factor Φ_K = δ_P/(δ_S + δ_P)), computed exactly instead of from a cone.
//!
//! **Definition.** δ_P is the relative approach of the head's and the nut's bearing faces per
//! unit clamp force F. For a prescribed face pressure p(r) on both bearing faces (the joint's
//! [`crate::FaceLoad`], uniform or triangular) the approach is the work-conjugate one,
//!
//! δ_P = ∫ p (w_head − w_nut) dA / F² (w_head, w_nut the axial displacements of the two loaded
//! faces toward the interface; in finite elements f·u / F² with f the consistent load vector of
//! both bearing faces), and for a rigid frictionless head and nut it is their rigid approach
//! over the force they carry, δ_P = 2δ/F (each face displaced δ over A ≤ r ≤ B, radial motion
//! free). Both are differences of the two faces' displacements: a rigid motion of the stack
//! changes neither (the face loads are in equilibrium), so the welded, frictionless and
//! friction μ = 0 models of two equal plates give the same δ_P, and the symmetric model (one
//! plate on a frictionless rigid plane, the plane being the symmetry plane) gives twice its
//! one face's work. The deflection under the nut alone
//! ([`super::two_plate::TwoPlateSolution::nut_deflection`]) has no such reference.
//!
//! **Method.** Each mesh level of [`super::two_plate::solve`] yields δ_P from its
//! displacements (the level record [`super::two_plate::TwoPlateInfo::compliance`]); the last
//! level's value is returned with the error max(|d₃|, |d₂|/4, |d₁|/16) of the last three changes
//! ([`crate::numerics::convergence::level_estimate`]; the changes shrink about 3× per level).
//! Under a rigid head the pressure is singular at the punch's edge (∝ ρ^(−1/2)), the energy
//! error is first order in the element size there, and the changes halve per level (observed
//! ratios 1.97–2.08 from the fourth level on): the levels are extrapolated at that rate
//! ([`estimate`]). For a prescribed pressure δ_P is the
//! complementary energy of the contact solution, stationary in the contact set: the error of
//! R_o moves δ_P at second order only, and it is in the level changes anyway. When the levels
//! that meet R_o's tolerance do not yet meet it for δ_P, or R_o's study stopped short of it
//! (a tolerance below R_o's floor, as in full contact at 5e-6), the study is repeated with the
//! levels that a halving estimate needs (up to `max_levels`); δ_P is `converged` only if R_o's
//! study converged too.
//!
//! **Exact limits** (tests in `tests/joint/`, with the observed rate of approach):
//! - *Thick plates* (D ≫ B, C = ∞, A → 0): two elastic half-spaces in series. A uniform
//!   pressure p on a disk of radius B on a half-space has the mean displacement
//!   (16/3π)(1 − ν²) p B/E (Johnson, *Contact Mechanics*, §3.4), so the work per face is
//!   F²·16(1 − ν²)/(3π² E B) and for the pair k_P (1 − ν²)/(E B) = 3π²/32; a rigid flat punch
//!   sinks F(1 − ν²)/(2 E B) (Boussinesq), so k_P (1 − ν²)/(E B) = 1 for a rigid head and nut.
//! - *Thin plates / wide heads* (D ≪ B − A): the loaded annulus A..B is a short sleeve, σ_z = −p
//!   through the thickness, its Poisson expansion held by the unloaded ring B..C (plane stress,
//!   Lamé in both). With σ_r + σ_θ = 2α₁ in the annulus, σ_r(A) = σ_r(C) = 0 and u, σ_r
//!   continuous at B, 2α₁ = −ν p (C² − B²)/(C² − A²); the axial strain −(p + 2να₁)/E is uniform
//!   over the annulus (so pressure and rigid head agree), and for the stack 2D thick
//!   k_P = πE(B² − A²) / (2D·(1 − ν²(C² − B²)/(C² − A²))) (the issue's formula, confirmed).
//! - *Thin plates, head and nut of their own* (B₁ < B₂, say; equal plates). A rigid head and
//!   nut squeeze the stack over A..B₁ only: the nut's face beyond B₁ presses plates that are
//!   free above, which would have to bend to take load (a stiffness O(D³) against the sleeve's
//!   O(1/D)), so k_P tends to the sleeve above with B = min(B₁, B₂), the ring B₁..C holding its
//!   expansion. Face pressures do not balance through the thickness: q = p₁χ(A..B₁) −
//!   p₂χ(A..B₂) is self-equilibrated and bends the stack, whose compliance is O(1/D³), far above
//!   the sleeve's O(D). The two plates, frictionless, bend alike (the interface pressure is then
//!   (p₁χ₁ + p₂χ₂)/2 ≥ 0, so they stay in contact) as one Kirchhoff plate of rigidity
//!   2·E D³/(12(1 − ν²)) free at A and C, and δ_P → ∫ q w dA/F² of that plate: there is no
//!   sleeve limit for unequal pressed faces. The next terms are O(D/(B₁ − A)) (rigid, the edge
//!   layer) and O((D/L)²) (pressures, transverse shear).
//!
//! Units: the joint's; δ_P in length per force, k_P in force per length.
//!
//! # Accuracy
//!
//! `tests/joint/compliance.rs`: the two limits with their observed rates, the symmetric model
//! against both plates meshed (welded, frictionless, friction μ = 0), the orderings (uniform ≤
//! rigid, two-plate ≤ single-plate) and the error estimate against runs of a 100× tighter
//! tolerance over random joints (and the ignored 200-joint study).
//!
//! # Cost
//!
//! That of R_o's study ([`super::two_plate`]; the δ_P of a level is one dot product), plus a
//! repeat with the levels δ_P still needs when it converges later than R_o. Measured (2 busy
//! cores): a Table 1 joint to 0.05 % in 0.03 s (pressure) and 0.12 s (rigid head).
//!
//! ```
//! use boltzone::contact::compliance::{member_compliance, ComplianceParams, Head};
//! use boltzone::{Joint, Material, OuterRadius};
//! let steel = Material::new(210e3, 0.3)?; // N/mm²
//! let joint = Joint::symmetric(5.5, 8.0, 10.0, steel)?.with_outer_radius(OuterRadius::Finite(40.0))?;
//! let params = ComplianceParams { head: Head::Pressure, tolerance: 1e-3, ..Default::default() };
//! let m = member_compliance(&joint, &params)?;
//! assert!(m.converged() && m.stiffness.value > 1e5 && m.stiffness.value < 1e7); // N/mm
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use super::params::{Loading, TwoPlateParams};
use super::two_plate::{solve, TwoPlateSolution};
use crate::error::InputError;
pub use crate::fem::compliance_estimate::{estimate, Head};
use crate::joint::Joint;
use crate::value::Value;
use serde::Serialize;
use std::time::Instant;

/// Knobs of [`member_compliance`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComplianceParams {
    /// Pressure or rigid head (default pressure).
    pub head: Head,
    /// Wanted relative error of δ_P (default 5e-4); also R_o's tolerance of the contact study.
    pub tolerance: f64,
    /// The contact study's other knobs (interface model, edge, element, levels); its
    /// `loading` and `tolerance` are set from `head` and `tolerance`.
    pub contact: TwoPlateParams,
}

impl Default for ComplianceParams {
    fn default() -> Self {
        Self {
            head: Head::Pressure,
            tolerance: 5e-4,
            contact: TwoPlateParams::default(),
        }
    }
}

/// The member compliance and stiffness of a joint (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MemberCompliance {
    /// δ_P, length per force.
    pub compliance: Value,
    /// k_P = 1/δ_P, force per length (error propagated to first order).
    pub stiffness: Value,
    /// δ_P of each level, coarse to fine.
    pub levels: Vec<f64>,
    /// The contact solution of the last study (R_o, interface curves, its levels).
    #[serde(skip)]
    pub contact: TwoPlateSolution,
    /// Wall time of all studies, seconds.
    pub seconds: f64,
}

impl MemberCompliance {
    /// Whether δ_P met its tolerance.
    pub fn converged(&self) -> bool {
        self.compliance.converged
    }
}

/// δ_P and k_P of `joint` from the two-plate contact solution (module docs).
pub fn member_compliance(
    joint: &Joint,
    params: &ComplianceParams,
) -> Result<MemberCompliance, ContactError> {
    let start = Instant::now();
    let tol = params.tolerance;
    if !(tol > 0.0 && tol < 1.0) {
        return Err(InputError::Parameter {
            field: "ComplianceParams::tolerance",
            value: tol,
            reason: "must lie in (0, 1)",
        }
        .into());
    }
    let thinner = joint.upper().thickness().min(joint.lower().thickness());
    let mut contact = TwoPlateParams {
        tolerance: tol,
        loading: match params.head {
            Head::Pressure => Loading::Pressure,
            // any δ: the problem is linear in it (1e-3 D keeps the solver's numbers of order 1)
            Head::Rigid => Loading::NutDisplacement(1e-3 * thinner),
        },
        ..params.contact
    };
    let mut solved = 0;
    loop {
        let s = solve(joint, &contact)?;
        let levels = s.info.compliance.clone();
        let n = levels.len();
        let (value, error) = estimate(&levels, params.head);
        let met = error <= tol * value.abs();
        // (R_o's study may stop before δ_P has its levels, e.g. in full contact at a tolerance
        // below R_o's floor: it is asked for more levels, as long as it gives them)
        if met || n >= contact.max_levels || n <= solved {
            let compliance = Value {
                value,
                error,
                converged: met && s.converged,
            };
            return Ok(MemberCompliance {
                compliance,
                stiffness: reciprocal(compliance),
                levels,
                contact: s,
                seconds: start.elapsed().as_secs_f64(),
            });
        }
        // the levels still needed if the estimate keeps halving (at least one more)
        // (an infinite estimate, too few levels for one: one level more)
        let ratio = error / (tol * value.abs());
        let more = if ratio.is_finite() {
            ratio.log2().ceil().clamp(1.0, 14.0) as usize
        } else {
            1
        };
        contact.min_levels = (n + more).min(contact.max_levels);
        solved = n;
    }
}

/// 1/x with the first-order error e/x².
pub(crate) fn reciprocal(x: Value) -> Value {
    Value {
        value: 1.0 / x.value,
        error: x.error / (x.value * x.value),
        converged: x.converged,
    }
}
