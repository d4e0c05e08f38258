//! VDI 2230 Part 1 (2015), §5.1.2.2: the resilience δ_P of the clamped parts of a through-bolted
//! joint (DSV) from the substitute deformation cone with sleeve, and k_P = 1/δ_P.
//!
//! With the bearing diameter d_W, the hole d_h, the clamp length l_K, the outside diameter
//! D_A and the modulus E_P (one material; w = 1 for a through-bolted joint):
//! tan φ_D = 0.362 + 0.032 ln(β_L/2) + 0.153 ln y, β_L = l_K/d_W, y = D_A/d_W
//! ([`super::cone_radius::vdi2230_tan_phi`]), and the limiting diameter D_A,Gr = d_W + w l_K tan φ.
//!
//! - D_A ≥ D_A,Gr (cones only): δ_P = 2 ln[(d_W + d_h)(D_A,Gr − d_h) / ((d_W − d_h)(D_A,Gr + d_h))]
//!   / (w E_P π d_h tan φ);
//! - d_W < D_A < D_A,Gr (cones and sleeve): δ_P = [2/(w d_h tan φ) ·
//!   ln((d_W + d_h)(D_A − d_h) / ((d_W − d_h)(D_A + d_h))) + 4/(D_A² − d_h²) ·
//!   (l_K − (D_A − d_W)/(w tan φ))] / (E_P π);
//! - D_A ≤ d_W (sleeve only): δ_P = 4 l_K / (E_P π (D_A² − d_h²)).
//!
//! Each cone is ∫ dz / (E_P π (r(z)² − d_h²/4)) with r(z) = d_W/2 + z tan φ from the bearing
//! face to the middle (or to where it reaches D_A/2, the sleeve beyond); the three cases are
//! continuous at D_A = d_W and D_A = D_A,Gr.
//!
//! Units: any consistent set; δ_P in length per force.
//!
//! # Accuracy
//!
//! `tests/joint/rules.rs`: the closed forms against a Gauss quadrature of the cone and sleeve
//! integral, and continuity between the cases. VDI 2230's own calculation example was not at
//! hand to reproduce (see the change's report).
//!
//! # Cost
//!
//! A few logarithms.
//!
//! ```
//! use boltzone::rules::vdi2230_stiffness::{resilience, Case};
//! // M10 through two 10 mm steel plates, d_W = 16 mm, d_h = 11 mm, D_A = 40 mm
//! let r = resilience(16.0, 11.0, 20.0, 40.0, 210e3)?;
//! assert_eq!(r.case, Case::Cone);
//! assert!(r.stiffness > 1e6 && r.stiffness < 3e6); // N/mm
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::cone_radius::vdi2230_tan_phi;
use crate::error::{positive, InputError};
use serde::Serialize;
use std::f64::consts::PI;

/// Which of VDI 2230's three cases applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Case {
    /// D_A ≥ D_A,Gr: the cones fit in the plates.
    Cone,
    /// d_W < D_A < D_A,Gr: cones reaching the outside diameter, a sleeve between them.
    ConeAndSleeve,
    /// D_A ≤ d_W: a sleeve only.
    Sleeve,
}

/// The resilience of the clamped parts by VDI 2230 (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Vdi2230Resilience {
    /// δ_P, length per force.
    pub compliance: f64,
    /// k_P = 1/δ_P.
    pub stiffness: f64,
    /// tan φ_D.
    pub tan_phi: f64,
    /// D_A,Gr.
    pub limiting_diameter: f64,
    /// The case that applied.
    pub case: Case,
}

/// δ_P with the head's and the nut's own bearing diameters `dw` = [head, nut]: the DSV's two
/// substitute bodies (cone, or cone and sleeve, from each bearing face to the middle of the
/// grip) are in series, and each is half of [`resilience`]'s symmetric body of its own d_W
/// (tan φ_D from its own β_L = l_K/d_W and y = D_A/d_W), so δ_P = (δ_P(d_W,head) +
/// δ_P(d_W,nut))/2. VDI 2230's formula is written for one d_W; this split is the equal-sides
/// formula applied per side (our reading, exact when the sides are equal). The `case` and
/// `tan_phi` returned are the head side's; `limiting_diameter` the wider of the two.
///
/// ```
/// use boltzone::rules::vdi2230_stiffness::{resilience, resilience_sides};
/// let one = resilience(16.0, 11.0, 20.0, 40.0, 210e3)?;
/// assert_eq!(resilience_sides([16.0, 16.0], 11.0, 20.0, 40.0, 210e3)?.compliance, one.compliance);
/// let two = resilience_sides([16.0, 14.6], 11.0, 20.0, 40.0, 210e3)?;
/// assert!(two.stiffness < one.stiffness); // the narrower nut face is softer
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn resilience_sides(
    dw: [f64; 2],
    dh: f64,
    lk: f64,
    da: f64,
    e: f64,
) -> Result<Vdi2230Resilience, InputError> {
    let head = resilience(dw[0], dh, lk, da, e)?;
    if dw[1] == dw[0] {
        return Ok(head);
    }
    let nut = resilience(dw[1], dh, lk, da, e)?;
    let compliance = 0.5 * (head.compliance + nut.compliance);
    Ok(Vdi2230Resilience {
        compliance,
        stiffness: 1.0 / compliance,
        limiting_diameter: head.limiting_diameter.max(nut.limiting_diameter),
        ..head
    })
}

/// δ_P of a through-bolted joint (DSV, w = 1): bearing diameter `dw`, hole `dh`, clamp length
/// `lk`, outside diameter `da` (finite), modulus `e`.
pub fn resilience(
    dw: f64,
    dh: f64,
    lk: f64,
    da: f64,
    e: f64,
) -> Result<Vdi2230Resilience, InputError> {
    positive("hole diameter d_h", dh)?;
    positive("clamp length l_K", lk)?;
    positive("modulus E_P", e)?;
    if !(dw > dh && dw.is_finite()) {
        return Err(InputError::Parameter {
            field: "bearing diameter d_W",
            value: dw,
            reason: "must be finite and larger than the hole diameter d_h",
        });
    }
    if !(da > dh && da.is_finite()) {
        return Err(InputError::Parameter {
            field: "outside diameter D_A",
            value: da,
            reason: "VDI 2230's cone needs a finite outside diameter larger than the hole",
        });
    }
    let tan_phi = vdi2230_tan_phi(lk / dw, da / dw)?;
    if tan_phi <= 0.0 {
        return Err(InputError::Parameter {
            field: "VDI 2230 tan(phi)",
            value: tan_phi,
            reason: "the correlation gives no cone for this geometry",
        });
    }
    let w = 1.0;
    let gr = dw + w * lk * tan_phi;
    let cone = |outer: f64| {
        2.0 / (w * dh * tan_phi) * ((dw + dh) * (outer - dh) / ((dw - dh) * (outer + dh))).ln()
    };
    let (compliance, case) = if da >= gr {
        (cone(gr) / (e * PI), Case::Cone)
    } else if da > dw {
        let sleeve = 4.0 / (da * da - dh * dh) * (lk - (da - dw) / (w * tan_phi));
        ((cone(da) + sleeve) / (e * PI), Case::ConeAndSleeve)
    } else {
        (4.0 * lk / (e * PI * (da * da - dh * dh)), Case::Sleeve)
    };
    Ok(Vdi2230Resilience {
        compliance,
        stiffness: 1.0 / compliance,
        tan_phi,
        limiting_diameter: gr,
        case,
    })
}
