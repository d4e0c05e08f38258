//! Shigley's 30° frusta for the member stiffness k_m (Budynas & Nisbett, *Shigley's Mechanical
//! Engineering Design*, 9th ed., McGraw-Hill 2011, §8-5): each member's compression is that of
//! hollow cone frusta of half-angle 30° spreading from each bearing face to the middle of the
//! grip, in series (Eq. 8-18, 1/k_m = Σ 1/k_i).
//!
//! - Eq. 8-20, one frustum of thickness t, smaller diameter D (the bearing face, or where the
//!   frustum enters a member), bolt diameter d, modulus E:
//!   k = 0.5774 π E d / ln[(1.155 t + D − d)(D + d) / ((1.155 t + D + d)(D − d))]
//!   (the printed constants 0.5774 ≈ tan 30°, 1.155 ≈ 2 tan 30° are kept so that the book's
//!   numbers come out digit for digit);
//! - Eq. 8-22, two members of one material, grip l, washer face D = 1.5 d:
//!   k_m = 0.5774 π E d / (2 ln[5 (0.5774 l + 0.5 d)/(0.5774 l + 2.5 d)]);
//! - [`members`]: any stack of members: the two frusta from head and nut to l/2, each cut where
//!   it crosses a member boundary, its diameter there D + 1.155 x (2 tan 30° as printed, so that
//!   cutting a frustum leaves its stiffness unchanged; the book's procedure, Example 8-2).
//!
//! Units: any consistent set; k in force per length.
//!
//! # Accuracy
//!
//! `tests/joint/rules.rs`: the book's solutions to Problems 8-22 and 8-28 and Example 8-2 (b)
//! to their printed digits.
//!
//! # Cost
//!
//! O(members).
//!
//! ```
//! use boltzone::rules::shigley::{frustum, two_equal_members};
//! // a frustum from a 1.5 d washer face through half the grip is Eq. 8-22's half
//! let (e, d, l) = (30e6, 0.5, 1.345);
//! let half = frustum(e, d, 1.5 * d, l / 2.0)?;
//! assert!((half / 2.0 / two_equal_members(e, d, l)? - 1.0).abs() < 1e-3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};

/// tan 30° as printed in Eqs. 8-20 and 8-22.
const TAN30: f64 = 0.5774;

/// Eq. 8-20: one 30° frustum (module docs); needs D > d.
pub fn frustum(e: f64, d: f64, dw: f64, t: f64) -> Result<f64, InputError> {
    positive("modulus E", e)?;
    positive("bolt diameter d", d)?;
    positive("frustum thickness t", t)?;
    wider("frustum diameter D", dw, d)?;
    let num = (1.155 * t + dw - d) * (dw + d);
    let den = (1.155 * t + dw + d) * (dw - d);
    Ok(TAN30 * std::f64::consts::PI * e * d / (num / den).ln())
}

/// Eq. 8-22: two members of one material, grip `l`, bolt diameter `d` (washer face 1.5 d).
pub fn two_equal_members(e: f64, d: f64, l: f64) -> Result<f64, InputError> {
    positive("modulus E", e)?;
    positive("bolt diameter d", d)?;
    positive("grip l", l)?;
    let r = 5.0 * (TAN30 * l + 0.5 * d) / (TAN30 * l + 2.5 * d);
    Ok(TAN30 * std::f64::consts::PI * e * d / (2.0 * r.ln()))
}

/// The member stiffness of a stack of `members` (thickness, modulus), head side first, clamped
/// by bearing faces of diameter `dw` over a bolt of diameter `d` (module docs).
pub fn members(members: &[(f64, f64)], d: f64, dw: f64) -> Result<f64, InputError> {
    members_sides(members, d, [dw, dw])
}

/// [`members`] with the head's and the nut's own bearing diameters `dw` = [head, nut]: each
/// frustum starts from its own face and runs to l/2 (the book's construction, each side its
/// own D).
///
/// ```
/// use boltzone::rules::shigley::{members, members_sides};
/// let stack = [(0.5, 30e6), (0.5, 30e6)];
/// assert_eq!(members_sides(&stack, 0.5, [0.75, 0.75])?, members(&stack, 0.5, 0.75)?);
/// // a wider nut face stiffens the nut's frustum only
/// let (k, k2) = (members(&stack, 0.5, 0.75)?, members_sides(&stack, 0.5, [0.75, 0.9])?);
/// assert!(k2 > k && k2 < members(&stack, 0.5, 0.9)?);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn members_sides(members: &[(f64, f64)], d: f64, dw: [f64; 2]) -> Result<f64, InputError> {
    if members.is_empty() {
        return Err(InputError::Parameter {
            field: "members",
            value: 0.0,
            reason: "need at least one member",
        });
    }
    let l: f64 = members.iter().map(|m| m.0).sum();
    let mut compliance = 0.0;
    // head side: members in order; nut side: in reverse; each frustum runs to l/2
    for order in [false, true] {
        let mut x = 0.0; // distance from the bearing face
        let list: Vec<(f64, f64)> = if order {
            members.iter().rev().copied().collect()
        } else {
            members.to_vec()
        };
        for (t, e) in list {
            let piece = t.min(0.5 * l - x);
            if piece <= 0.0 {
                break;
            }
            let k = frustum(e, d, dw[usize::from(order)] + 1.155 * x, piece)?;
            compliance += 1.0 / k;
            x += piece;
        }
    }
    Ok(1.0 / compliance)
}

fn wider(field: &'static str, value: f64, than: f64) -> Result<(), InputError> {
    if value > than && value.is_finite() {
        Ok(())
    } else {
        Err(InputError::Parameter {
            field,
            value,
            reason: "must be finite and larger than the bolt diameter d",
        })
    }
}
