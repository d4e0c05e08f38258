//! ISO metric threads: the basic profile's diameters from the nominal diameter d and the pitch
//! P (ISO 724: d₂ = d − 0.649519 P, d₃ = d − 1.226869 P for the external thread's root), the
//! stress area A_s = π/4 ((d₂ + d₃)/2)² (ISO 898-1), and the coarse pitches of ISO 262
//! (`reference/bolts/iso262_coarse.csv`, M3–M36).
//!
//! Units: millimetres.
//!
//! # Accuracy
//!
//! `tests/joint/bolt.rs`: A_s against ISO 898-1's Table 4 values for M3–M36 to their printed
//! digits.
//!
//! # Cost
//!
//! A table look-up.
//!
//! ```
//! use boltzone::bolt::thread::Thread;
//! let t = Thread::metric_coarse("M12")?;
//! assert_eq!((t.d, t.pitch), (12.0, 1.75));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::InputError;

/// The coarse-pitch table of ISO 262 (size, d, P).
const COARSE: &str = include_str!("../../reference/bolts/iso262_coarse.csv");

/// An ISO metric thread.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thread {
    /// Nominal diameter d, mm.
    pub d: f64,
    /// Pitch P, mm.
    pub pitch: f64,
}

impl Thread {
    /// A thread of diameter `d` and pitch `pitch` (mm), 0 < P < d/4.
    pub fn new(d: f64, pitch: f64) -> Result<Self, InputError> {
        crate::error::positive("thread diameter d", d)?;
        if !(pitch > 0.0 && pitch < 0.25 * d) {
            return Err(InputError::Parameter {
                field: "thread pitch P",
                value: pitch,
                reason: "must lie in (0, d/4)",
            });
        }
        Ok(Self { d, pitch })
    }

    /// The coarse thread of `size` ("M3" … "M36", ISO 262).
    pub fn metric_coarse(size: &str) -> Result<Self, InputError> {
        for line in COARSE.lines().skip(1).filter(|l| !l.starts_with('#')) {
            let f: Vec<&str> = line.split(',').collect();
            if f.len() == 3 && f[0].eq_ignore_ascii_case(size.trim()) {
                let num = |s: &str| s.parse::<f64>().unwrap_or(f64::NAN);
                return Self::new(num(f[1]), num(f[2]));
            }
        }
        Err(InputError::Parameter {
            field: "bolt size",
            value: f64::NAN,
            reason: "not an ISO 262 coarse size M3 … M36 (M3, M4, M5, M6, M8, M10, M12, M14, M16, M18, M20, M22, M24, M27, M30, M33, M36)",
        })
    }

    /// Pitch diameter d₂ = d − 0.649519 P.
    pub fn pitch_diameter(&self) -> f64 {
        self.d - 0.649519 * self.pitch
    }

    /// Minor diameter of the bolt's thread d₃ = d − 1.226869 P.
    pub fn minor_diameter(&self) -> f64 {
        self.d - 1.226869 * self.pitch
    }

    /// Stress area A_s = π/4 ((d₂ + d₃)/2)².
    pub fn stress_area(&self) -> f64 {
        let ds = 0.5 * (self.pitch_diameter() + self.minor_diameter());
        0.25 * std::f64::consts::PI * ds * ds
    }
}
