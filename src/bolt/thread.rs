//! ISO metric and Unified inch threads: the basic profile's diameters from the nominal diameter
//! d and the pitch P (ISO 724: d₂ = d − 0.649519 P, d₃ = d − 1.226869 P for the external
//! thread's root; the Unified form of ASME B1.1 has the same 60° profile), the stress area
//! (ISO 898-1: A_s = π/4 ((d₂ + d₃)/2)²; ASME B1.1: A_t = π/4 (d − 0.9743 P)²), and the
//! catalogue sizes: the coarse pitches of ISO 262 (`reference/bolts/iso262_coarse.csv`,
//! M3–M36), its fine pitches (`iso262_fine.csv`, M8×1 … M36×3) and the UNC/UNF series #4 to
//! 1-1/2 (`unified_inch.csv`, ASME B1.1). [`Thread::lookup`] reads "M10", "M10x1.25",
//! "1/2-13" or "1/2-13 UNC".
//!
//! Units: millimetres (the inch sizes converted at 25.4 mm/in).
//!
//! # Accuracy
//!
//! `tests/joint/bolt.rs`: A_s against ISO 898-1's Table 4 values for M3–M36 to their printed
//! digits; `tests/joint/catalogue.rs`: the fine pitches against ISO 898-1's Table 5 and the
//! Unified sizes' tabulated A_t against ASME B1.1's formula.
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

use super::table::{cell, rows, NotInCatalogue};
use crate::error::InputError;

/// The coarse-pitch table of ISO 262 (size, d, P).
const COARSE: &str = include_str!("../../reference/bolts/iso262_coarse.csv");
/// The fine-pitch table of ISO 262 (size, d, P).
const FINE: &str = include_str!("../../reference/bolts/iso262_fine.csv");
/// The UNC/UNF table of ASME B1.1 (size, series, d in, threads per inch, A_t in²).
pub const UNIFIED: &str = include_str!("../../reference/bolts/unified_inch.csv");

/// Millimetres per inch.
const MM_PER_INCH: f64 = 25.4;

/// The thread form, which fixes the stress area's formula.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Form {
    /// ISO metric (ISO 68-1, ISO 724): A_s = π/4 ((d₂ + d₃)/2)².
    #[default]
    Metric,
    /// Unified inch (ASME B1.1): A_t = π/4 (d − 0.9743 P)².
    Unified,
}

/// A screw thread (ISO metric or Unified inch; lengths in mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thread {
    /// Nominal diameter d, mm.
    pub d: f64,
    /// Pitch P, mm.
    pub pitch: f64,
    /// The form (metric unless made by [`Thread::unified`] or looked up as an inch size).
    pub form: Form,
}

/// The sizes a table lists, for messages.
fn names(table: &str) -> String {
    rows(table)
        .map(|f| f[0].to_string())
        .collect::<Vec<_>>()
        .join(", ")
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
        Ok(Self {
            d,
            pitch,
            form: Form::Metric,
        })
    }

    /// A Unified inch thread of major diameter `d` (mm) and pitch `pitch` (mm), 0 < P < d/4.
    pub fn unified(d: f64, pitch: f64) -> Result<Self, InputError> {
        Ok(Self {
            form: Form::Unified,
            ..Self::new(d, pitch)?
        })
    }

    /// The catalogue thread of `size`: "M10" (ISO 262 coarse), "M10x1.25" (ISO 262 fine; `×`
    /// or `x`), "1/2-13" or "1/2-13 UNC", "#10-32" (ASME B1.1 UNC/UNF). The error lists the
    /// sizes known.
    ///
    /// ```
    /// use boltzone::bolt::thread::{Form, Thread};
    /// let fine = Thread::lookup("M10x1.25")?;
    /// assert_eq!((fine.d, fine.pitch), (10.0, 1.25));
    /// let unc = Thread::lookup("1/2-13 UNC")?;
    /// assert_eq!(unc.form, Form::Unified);
    /// assert!((unc.d - 12.7).abs() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn lookup(size: &str) -> Result<Self, NotInCatalogue> {
        let key = size.trim().replace('×', "x");
        let bad = |e: InputError| NotInCatalogue::new("thread", size, &e.to_string());
        if key.contains('x') || key.contains('X') {
            for f in rows(FINE) {
                if f[0].eq_ignore_ascii_case(&key) {
                    return Self::new(cell(f[1]), cell(f[2])).map_err(bad);
                }
            }
            return Err(NotInCatalogue::new(
                "ISO 262 fine thread",
                size,
                &names(FINE),
            ));
        }
        if key.starts_with(['M', 'm']) {
            return Self::metric_coarse(&key)
                .map_err(|_| NotInCatalogue::new("ISO 262 coarse thread", size, &names(COARSE)));
        }
        let (name, series) = match key.split_once(' ') {
            Some((n, s)) => (n.trim(), Some(s.trim())),
            None => (key.as_str(), None),
        };
        for f in rows(UNIFIED) {
            if f[0] == name && series.is_none_or(|s| s.eq_ignore_ascii_case(f[1])) {
                return Self::unified(MM_PER_INCH * cell(f[2]), MM_PER_INCH / cell(f[3]))
                    .map_err(bad);
            }
        }
        Err(NotInCatalogue::new(
            "thread (ISO 262 coarse or fine, ASME B1.1 UNC/UNF)",
            size,
            &format!("M3 … M36, {}; {}", names(FINE), names(UNIFIED)),
        ))
    }

    /// The coarse thread of `size` ("M3" … "M36", ISO 262).
    pub fn metric_coarse(size: &str) -> Result<Self, InputError> {
        for f in rows(COARSE) {
            if f.len() == 3 && f[0].eq_ignore_ascii_case(size.trim()) {
                return Self::new(cell(f[1]), cell(f[2]));
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

    /// Stress area: metric A_s = π/4 ((d₂ + d₃)/2)², Unified A_t = π/4 (d − 0.9743 P)².
    pub fn stress_area(&self) -> f64 {
        let ds = match self.form {
            Form::Metric => 0.5 * (self.pitch_diameter() + self.minor_diameter()),
            Form::Unified => self.d - 0.9743 * self.pitch,
        };
        0.25 * std::f64::consts::PI * ds * ds
    }
}
