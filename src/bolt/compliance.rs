//! The bolt's resilience δ_S by VDI 2230 Part 1 (2015) §5.1.1 (through-bolted joint, hexagon
//! head and nut), and the load factor.
//!
//! δ_S = δ_SK + δ_1 + δ_Gew + δ_G + δ_M with, for the modulus E_S (bolt) and E_M (nut),
//! A_N = π d²/4 and A_d3 = π d₃²/4:
//! - head: δ_SK = 0.5 d/(E_S A_N) (hexagon head);
//! - unthreaded shank in the grip: δ_1 = l_1/(E_S A_N);
//! - free loaded thread: δ_Gew = (l_K − l_1)/(E_S A_d3);
//! - engaged thread: δ_G = 0.5 d/(E_S A_d3); nut: δ_M = 0.4 d/(E_M A_N).
//!
//! The load factor of an axial load introduced under the head and nut: Φ_K = δ_P/(δ_S + δ_P);
//! introduced inside the plates at the load-introduction factor n: Φ_n = n Φ_K.
//!
//! Units: mm, N (any consistent set); δ in length per force.
//!
//! # Accuracy
//!
//! `tests/joint/bolt.rs`: the sections summed by hand from VDI 2230's formulas for M10.
//!
//! # Cost
//!
//! O(1).
//!
//! ```
//! use boltzone::bolt::{compliance::bolt_resilience, thread::Thread};
//! let d = bolt_resilience(&Thread::metric_coarse("M10")?, 20.0, 0.0, 205e3, 205e3)?;
//! assert!(d > 0.0 && d < 1e-5); // mm/N
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::thread::Thread;
use crate::error::{positive, InputError};
use std::f64::consts::PI;

/// δ_S of `thread` through the clamp length `lk` with an unthreaded shank `l1` (0 ≤ l₁ ≤ l_K)
/// inside the grip, bolt modulus `es`, nut modulus `em` (module docs).
pub fn bolt_resilience(
    thread: &Thread,
    lk: f64,
    l1: f64,
    es: f64,
    em: f64,
) -> Result<f64, InputError> {
    positive("clamp length l_K", lk)?;
    positive("bolt modulus E_S", es)?;
    positive("nut modulus E_M", em)?;
    if !(l1 >= 0.0 && l1 <= lk) {
        return Err(InputError::Parameter {
            field: "shank length l_1",
            value: l1,
            reason: "must lie in [0, l_K]",
        });
    }
    let d = thread.d;
    let an = 0.25 * PI * d * d;
    let ad3 = 0.25 * PI * thread.minor_diameter().powi(2);
    let head = 0.5 * d / (es * an);
    let shank = l1 / (es * an);
    let free = (lk - l1) / (es * ad3);
    let engaged = 0.5 * d / (es * ad3);
    let nut = 0.4 * d / (em * an);
    Ok(head + shank + free + engaged + nut)
}

/// Φ_K = δ_P/(δ_S + δ_P) times the load-introduction factor `n` (0 < n ≤ 1; 1: under head and
/// nut).
pub fn load_factor(bolt: f64, members: f64, n: f64) -> Result<f64, InputError> {
    positive("bolt resilience delta_S", bolt)?;
    positive("member resilience delta_P", members)?;
    if !(n > 0.0 && n <= 1.0) {
        return Err(InputError::Parameter {
            field: "load-introduction factor n",
            value: n,
            reason: "must lie in (0, 1]",
        });
    }
    Ok(n * members / (bolt + members))
}
