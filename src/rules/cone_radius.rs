//! Cone rules for the contact radius of a bolted joint: cones of pressure spreading from the
//! edge of the bearing face (radius B) through the plate to the interface.
//!
//! - Rötscher's 45° cone (Rötscher 1927, report Fig. 2 and Chapter I): for two equal plates the
//!   plates separate where the interface meets the 45° cone from the bearing face's edge,
//!   R = B + D·tan 45° = B + D.
//! - Any cone of half-angle φ: R = B + D·tan φ; the 30° cone is a common alternative.
//! - VDI 2230 Part 1 (2003), §5.1.2.2, substitute deformation cone of a through-bolted joint (DSV):
//!   tan φ_D = 0.362 + 0.032 ln(β_L/2) + 0.153 ln y, with β_L = l_K/d_W (clamp length over the
//!   bearing-face diameter) and y = D′_A/d_W (substitute outside diameter of the clamped parts at
//!   the interface over d_W). For a round plate pair, l_K = D₁ + D₂, d_W = 2B and D′_A = 2C. If the
//!   cone reaches the plate's rim (B + D tan φ ≥ C) VDI replaces it by a sleeve; then the contact
//!   radius is C and [`ConeRadius::truncated`] says so.
//!
//! Units: lengths in any one unit; angles in radians unless the name says degrees.
//!
//! # Accuracy
//!
//! Closed forms; the unit tests here check an exact identity (tan 30° = 1/√3), the correlation's
//! derivatives by finite differences, and the truncation at C; and `tests/compare/tables.rs` checks
//! that the 45° cone overpredicts the two-plate R_o.
//!
//! # Cost
//!
//! O(1).
//!
//! ```
//! use boltzone::rules::cone_radius::{cone_radius, vdi2230_tan_phi};
//! let r = cone_radius(0.31, 0.1, 45f64.to_radians(), f64::INFINITY)?;
//! assert!((r.radius - 0.41).abs() < 1e-15);
//! // β_L = 2, y = 1: the logarithms vanish and tan φ = 0.362.
//! assert!((vdi2230_tan_phi(2.0, 1.0)? - 0.362).abs() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};
use serde::Serialize;

/// A cone rule's contact radius at the interface.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ConeRadius {
    /// Contact radius R at the interface.
    pub radius: f64,
    /// Half-angle of the cone, radians.
    pub half_angle: f64,
    /// Whether the cone reached the plate's rim C (the radius is then C).
    pub truncated: bool,
}

/// The contact radius of a cone of half-angle `half_angle` (radians, in (0, π/2)) from the bearing
/// edge at radius `b` through a plate `d` thick, limited by the plate radius `c` (∞ allowed).
pub fn cone_radius(b: f64, d: f64, half_angle: f64, c: f64) -> Result<ConeRadius, InputError> {
    positive("load outer radius B", b)?;
    positive("plate thickness D", d)?;
    if !(half_angle > 0.0 && half_angle < std::f64::consts::FRAC_PI_2) {
        return Err(InputError::Parameter {
            field: "cone half-angle",
            value: half_angle,
            reason: "must lie in (0, pi/2) radians",
        });
    }
    if c.is_nan() || c <= b {
        return Err(InputError::OuterRadius { b, c });
    }
    let r = b + d * half_angle.tan();
    Ok(ConeRadius {
        radius: r.min(c),
        half_angle,
        truncated: r >= c,
    })
}

/// Rötscher's 45° rule for two equal plates `d` thick under a bearing face of radius `b`.
pub fn roetscher(b: f64, d: f64, c: f64) -> Result<ConeRadius, InputError> {
    cone_radius(b, d, std::f64::consts::FRAC_PI_4, c)
}

/// VDI 2230 (2003) tan φ_D of the substitute deformation cone of a through-bolted joint, from
/// β_L = l_K/d_W and y = D′_A/d_W (both > 0).
pub fn vdi2230_tan_phi(beta_l: f64, y: f64) -> Result<f64, InputError> {
    positive("VDI 2230 beta_L = l_K/d_W", beta_l)?;
    positive("VDI 2230 y = D'_A/d_W", y)?;
    Ok(0.362 + 0.032 * (beta_l / 2.0).ln() + 0.153 * y.ln())
}

/// The VDI 2230 cone's contact radius for plates `d1` (under the head) and `d2` thick clamped by a
/// bearing face of radius `b`, plates of radius `c` (finite: VDI's y needs the outside diameter).
/// The cone runs from the head's bearing edge through the upper plate: R = B + D₁ tan φ_D.
pub fn vdi2230(b: f64, d1: f64, d2: f64, c: f64) -> Result<ConeRadius, InputError> {
    positive("load outer radius B", b)?;
    positive("plate thickness D", d1)?;
    positive("second plate thickness D2", d2)?;
    positive("plate outer radius C", c)?;
    if !c.is_finite() {
        return Err(InputError::Parameter {
            field: "plate outer radius C",
            value: c,
            reason: "VDI 2230's cone angle needs a finite outside diameter D'_A = 2C",
        });
    }
    let tan_phi = vdi2230_tan_phi((d1 + d2) / (2.0 * b), c / b)?;
    if tan_phi <= 0.0 {
        return Err(InputError::Parameter {
            field: "VDI 2230 tan(phi)",
            value: tan_phi,
            reason: "the correlation gives no cone for this geometry (y or beta_L too small)",
        });
    }
    cone_radius(b, d1, tan_phi.atan(), c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cones_widen_with_angle_and_thickness() {
        let r30 = cone_radius(0.211, 0.253, 30f64.to_radians(), 2.0).unwrap();
        let r45 = roetscher(0.211, 0.253, 2.0).unwrap();
        assert!(r30.radius < r45.radius);
        // tan 30° = 1/√3 exactly: an identity independent of the code's tan().
        assert!((r30.radius - (0.211 + 0.253 / 3f64.sqrt())).abs() < 1e-15);
        let thick = roetscher(0.211, 2.0, 2.0).unwrap();
        assert!(thick.truncated && thick.radius == 2.0);
    }

    #[test]
    fn vdi_angle_grows_with_clamp_length_and_plate_size() {
        // ∂tanφ/∂ln β_L = 0.032 and ∂tanφ/∂ln y = 0.153: finite differences of the correlation.
        let t = |b, y| vdi2230_tan_phi(b, y).unwrap();
        let h = 1e-6;
        assert!(((t(1.0 * (1.0 + h), 3.0) - t(1.0, 3.0)) / h - 0.032).abs() < 1e-6);
        assert!(((t(1.0, 3.0 * (1.0 + h)) - t(1.0, 3.0)) / h - 0.153).abs() < 1e-6);
        // Table 2's 1/4 in pair: VDI's cone is narrower than 45°.
        let v = vdi2230(0.211, 0.253, 0.256, 2.0).unwrap();
        assert!(v.half_angle < std::f64::consts::FRAC_PI_4);
    }

    #[test]
    fn bad_input_is_named() {
        assert!(cone_radius(0.2, 0.1, 1.6, 1.0)
            .unwrap_err()
            .to_string()
            .contains("half-angle"));
        assert!(vdi2230(0.2, 0.1, 0.1, f64::INFINITY)
            .unwrap_err()
            .to_string()
            .contains("outer radius C"));
        assert!(roetscher(0.2, -0.1, 1.0)
            .unwrap_err()
            .to_string()
            .contains("thickness D"));
    }
}
