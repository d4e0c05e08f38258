//! The assembly preload F_M of a bolt: from the tightening torque by VDI 2230 Part 1 (2015)
//! Eq. (R13/1), M_A = F_M (0.16 P + 0.58 d₂ μ_G + D_Km/2 μ_K) with D_Km = (d_W + d_h)/2 the
//! friction diameter under the head; or from the utilisation ν of the yield point R_p0.2 by
//! Eq. (R7/1), F_M,zul = A_0 ν R_p0.2 / √(1 + 3[3/2 · d₂/d₀ · (P/(π d₂) + 1.155 μ_G)]²) with
//! A_0 = A_s and d₀ = (d₂ + d₃)/2; and the bearing pressure F/(π/4 (d_W² − d_h²)).
//! R_p0.2 of the property classes (ISO 898-1 minimum values): 8.8 640 MPa (d ≤ 16 mm) and
//! 660 MPa (d > 16 mm), 10.9 940 MPa, 12.9 1100 MPa.
//!
//! Units: mm, N, N·mm, MPa.
//!
//! # Accuracy
//!
//! `tests/joint/bolt.rs`: the M10 joint by hand from the same equations.
//!
//! # Cost
//!
//! O(1).
//!
//! ```
//! use boltzone::bolt::{preload::preload_from_torque, thread::Thread};
//! let f = preload_from_torque(&Thread::metric_coarse("M10")?, 40e3, 0.12, 0.12, 14.63, 11.0)?;
//! assert!(f > 20e3 && f < 30e3); // N
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::thread::Thread;
use crate::error::{positive, InputError};
use std::f64::consts::PI;

/// A property class of ISO 898-1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PropertyClass {
    /// 8.8.
    C8_8,
    /// 10.9.
    C10_9,
    /// 12.9.
    C12_9,
}

impl PropertyClass {
    /// The minimum R_p0.2 (MPa) for a bolt of diameter `d` (mm).
    pub fn yield_point(self, d: f64) -> f64 {
        match self {
            Self::C8_8 if d <= 16.0 => 640.0,
            Self::C8_8 => 660.0,
            Self::C10_9 => 940.0,
            Self::C12_9 => 1100.0,
        }
    }
}

/// F_M from the torque `torque` (N·mm) with thread and head friction `mu_g`, `mu_k`, bearing
/// diameter `dw` and hole `dh` (module docs).
pub fn preload_from_torque(
    thread: &Thread,
    torque: f64,
    mu_g: f64,
    mu_k: f64,
    dw: f64,
    dh: f64,
) -> Result<f64, InputError> {
    positive("tightening torque M_A", torque)?;
    positive("thread friction mu_G", mu_g)?;
    positive("head friction mu_K", mu_k)?;
    positive("hole diameter d_h", dh)?;
    if dw.partial_cmp(&dh) != Some(std::cmp::Ordering::Greater) {
        return Err(InputError::Parameter {
            field: "bearing diameter d_W",
            value: dw,
            reason: "must exceed the hole diameter d_h",
        });
    }
    let dkm = 0.5 * (dw + dh);
    let lever = 0.16 * thread.pitch + 0.58 * thread.pitch_diameter() * mu_g + 0.5 * dkm * mu_k;
    Ok(torque / lever)
}

/// F_M,zul at the utilisation `nu` (0 < ν ≤ 1) of the class's yield point (module docs).
pub fn preload_from_utilisation(
    thread: &Thread,
    class: PropertyClass,
    nu: f64,
    mu_g: f64,
) -> Result<f64, InputError> {
    if !(nu > 0.0 && nu <= 1.0) {
        return Err(InputError::Parameter {
            field: "utilisation nu",
            value: nu,
            reason: "must lie in (0, 1]",
        });
    }
    positive("thread friction mu_G", mu_g)?;
    let d2 = thread.pitch_diameter();
    let d0 = 0.5 * (d2 + thread.minor_diameter());
    let t = 1.5 * d2 / d0 * (thread.pitch / (PI * d2) + 1.155 * mu_g);
    Ok(thread.stress_area() * nu * class.yield_point(thread.d) / (1.0 + 3.0 * t * t).sqrt())
}

/// The bearing pressure of `force` on the annulus d_h..d_W.
pub fn bearing_pressure(force: f64, dw: f64, dh: f64) -> f64 {
    force / (0.25 * PI * (dw * dw - dh * dh))
}
