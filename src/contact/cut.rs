//! Where the two-plate study cuts plates wider than its mesh can hold ([`cut_at`]), the bound
//! on R_o of what the cut leaves out ([`cut_error`]), and the plates that must be meshed whole
//! ([`check_cut_allowed`]). Beyond the cut the free layer's exact exterior
//! ([`crate::fem::exterior`]) carries the plate to its rim; the cut leaves out only the
//! decaying Papkovich–Fadle modes (Timoshenko & Goodier §25: sin 2x + 2x = 0, slowest
//! e^(−4.21 (C′ − R_o)/D) for a layer D thick).
//!
//! # Accuracy
//!
//! The bound is below 1e-40 of R_o at the cuts chosen; the FE against the semi-analytic
//! routes on infinite plates (`tests/hankel/grid_study.rs`, `tests/contact/receding_vs_fe.rs`).
//!
//! # Cost
//!
//! None of its own; it bounds the meshes' width, and so their cost (example 04).
//!
//! ```
//! // Internal to the study; reached through its entry point:
//! use boltzone::contact::two_plate::{solve, TwoPlateParams};
//! let _ = (solve, TwoPlateParams::default());
//! ```

use super::error::ContactError;
use super::params::{EdgeSupport, TwoPlateParams};
use super::refine::MeshLayout;
use crate::error::InputError;
use crate::joint::{Joint, OuterRadius};

/// Widest free annulus C − B meshed, in thicknesses of the thinner plate. The bending stiffness
/// of a free annulus L long falls like (D/L)⁴ against the element stiffnesses: beyond
/// L/D ≈ 10⁴ the stiffness matrix is numerically indefinite in f64, and already at 2000 the
/// finest levels' R_o scattered by ±3e-5 relative (A = 0, B = D: the receding-contact value as
/// reference), where at 500 they settle within 1e-5 of it.
const C_MAX_OVER_D: f64 = 500.0;

/// Where to cut plates wider than the mesh can hold: at C itself when C ≤ B + [`C_MAX_OVER_D`]·D
/// (meshed whole), else at C′ = min(10B + 10(D₁ + D₂), B + ½[`C_MAX_OVER_D`]·D) with the exact
/// exterior of the free layer out to the rim C on the cut ([`crate::fem::exterior`]; returned
/// as the rim, `f64::INFINITY` for infinite plates). The cut leaves out only the decaying
/// Papkovich–Fadle modes ([`cut_error`]). A fixed edge or a temperature field needs the plate
/// meshed whole: the exterior is that of a free rim at the reference temperature.
///
/// (Before, the cut face was left free and R_o carried an error ∝ C′⁻², estimated from two
/// coarse levels at C′ and 2C′; on a 10 × 10 grid of infinite plates the FE then sat below the
/// semi-analytic route by up to 1.6× its estimate at 1e-5: `tests/hankel/grid_study.rs`.)
pub(super) fn cut_at(g: &MeshLayout, c: f64) -> (f64, Option<f64>) {
    let c_max = widest_meshed(g.b, g.d[0].min(g.d[1]));
    if c <= c_max {
        return (c, None);
    }
    let cut = (10.0 * g.b + 10.0 * (g.d[0] + g.d[1])).min(g.b + 0.5 * (c_max - g.b));
    (cut, Some(c))
}

/// The widest plate meshed whole, B + [`C_MAX_OVER_D`]·D (D of the thinner plate).
fn widest_meshed(b: f64, d_min: f64) -> f64 {
    b + C_MAX_OVER_D * d_min
}

/// Refuses a plate that [`cut_at`] would cut when its outer edge is fixed or it carries
/// temperatures (in the joint's own units, so that the message quotes them).
pub(super) fn check_cut_allowed(
    joint: &Joint,
    params: &TwoPlateParams,
    thermal: bool,
) -> Result<(), ContactError> {
    let d = joint.upper().thickness().min(joint.lower().thickness());
    let c = match joint.outer_radius() {
        OuterRadius::Finite(c) => c,
        OuterRadius::Infinite => f64::INFINITY,
    };
    if c <= widest_meshed(joint.widest_bearing(), d) {
        return Ok(());
    }
    let reason = if params.edge == EdgeSupport::Fixed {
        "a fixed edge is meshed whole: C must not exceed B + 500 D (D of the thinner plate)"
    } else if thermal {
        "plates with temperatures are meshed whole: C must not exceed B + 500 D (D of the thinner plate)"
    } else {
        return Ok(());
    };
    let field = if c.is_finite() {
        "plate outer radius C"
    } else {
        "plate outer radius C (none given: an infinite plate)"
    };
    Err(InputError::Parameter {
        field,
        value: c,
        reason,
    }
    .into())
}

/// The cut's error bound in R_o: the slowest Papkovich–Fadle mode left out decays like
/// e^(−4.21 (C′ − R_o)/D) from the contact's edge to the cut ([`crate::fem::exterior`]), D the
/// thicker plate; relative to R_o. Below 1e-40 at the cuts of [`cut_at`]; it grows only when
/// R_o nears the cut.
pub(super) fn cut_error(cut: f64, r_o: f64, d_max: f64) -> f64 {
    r_o * (-4.21 * (cut - r_o).max(0.0) / d_max).exp()
}
