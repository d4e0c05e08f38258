//! Unit systems of a scene: `in-psi-lbf` (the report's, the default), `mm-MPa-N`, `m-Pa-N`.
//! Each is consistent (stress = force / length²). A scene is converted to SI (m, Pa, N) on the
//! way in and every result back to the scene's own system on the way out.
//!
//! The factors are the exact definitions: 1 in = 0.0254 m, 1 lbf = 4.4482216152605 N (the
//! international avoirdupois pound times standard gravity 9.80665 m/s²), 1 psi = 1 lbf/in².
//!
//! # Accuracy
//!
//! Exact factors; `tests/scene/units.rs` solves one joint in all three systems and finds the same
//! R_o to 1e-12 relative.
//!
//! # Cost
//!
//! A multiplication per number.
//!
//! ```
//! use boltzone::scene::UnitSystem;
//! let psi = UnitSystem::InPsiLbf.stress();
//! assert!((psi - 6894.757293168361).abs() < 1e-9);
//! assert_eq!(UnitSystem::MmMpaN.symbols(), ("mm", "MPa", "N"));
//! ```

use serde::{Deserialize, Serialize};

/// One inch in metres (exact by definition).
pub const INCH: f64 = 0.0254;
/// One pound-force in newtons (exact by definition: 0.45359237 kg × 9.80665 m/s²).
pub const POUND_FORCE: f64 = 4.4482216152605;
/// Metres per foot (exact).
pub const FOOT: f64 = 0.3048;
/// Pascals per psi (lbf/in²).
pub const PSI: f64 = POUND_FORCE / (INCH * INCH);
/// Joules per International Table Btu (exact).
pub const BTU: f64 = 1_055.055_852_62;
/// Seconds per hour.
pub const HOUR: f64 = 3600.0;
/// Kelvin per degree Fahrenheit of temperature difference (exact).
pub const FAHRENHEIT_DEGREE: f64 = 5.0 / 9.0;

/// `x` rounded to 12 significant digits: an input derived by one division or unit conversion
/// (B/A = 0.31/0.1, 0.1 in in mm) as its user typed it, without the last bits of the
/// rounding (3.1, not 3.1000000000000005). For printing inputs only; computed results are
/// printed in full (shortest round-trip form).
///
/// ```
/// assert_eq!(boltzone::units::as_entered(0.31 / 0.1), 3.1);
/// assert_eq!(boltzone::units::as_entered(f64::INFINITY), f64::INFINITY);
/// ```
pub fn as_entered(x: f64) -> f64 {
    if x.is_finite() {
        format!("{x:.11e}").parse().unwrap_or(x)
    } else {
        x
    }
}

/// A consistent system of length, stress and force units.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum UnitSystem {
    /// Inches, psi, pounds-force (the report's units; the default).
    #[default]
    #[serde(rename = "in-psi-lbf")]
    InPsiLbf,
    /// Millimetres, megapascals, newtons.
    #[serde(rename = "mm-MPa-N")]
    MmMpaN,
    /// Metres, pascals, newtons (SI).
    #[serde(rename = "m-Pa-N")]
    MPaN,
}

impl UnitSystem {
    /// Metres per length unit.
    pub fn length(self) -> f64 {
        match self {
            Self::InPsiLbf => INCH,
            Self::MmMpaN => 1e-3,
            Self::MPaN => 1.0,
        }
    }

    /// Newtons per force unit.
    pub fn force(self) -> f64 {
        match self {
            Self::InPsiLbf => POUND_FORCE,
            Self::MmMpaN | Self::MPaN => 1.0,
        }
    }

    /// Pascals per stress unit (force unit / length unit²).
    pub fn stress(self) -> f64 {
        match self {
            Self::InPsiLbf => POUND_FORCE / (INCH * INCH),
            Self::MmMpaN => 1e6,
            Self::MPaN => 1.0,
        }
    }

    /// W/(m·K) per conductivity unit: Btu/(hr·ft·°F) in in-psi-lbf, W/(m·K) otherwise.
    pub fn conductivity(self) -> f64 {
        match self {
            Self::InPsiLbf => BTU / HOUR / FOOT / FAHRENHEIT_DEGREE,
            Self::MmMpaN | Self::MPaN => 1.0,
        }
    }

    /// W/K per thermal conductance unit: Btu/(hr·°F) in in-psi-lbf, W/K otherwise.
    pub fn conductance(self) -> f64 {
        match self {
            Self::InPsiLbf => BTU / HOUR / FAHRENHEIT_DEGREE,
            Self::MmMpaN | Self::MPaN => 1.0,
        }
    }

    /// Symbols of (conductivity, conductance).
    pub fn heat_symbols(self) -> (&'static str, &'static str) {
        match self {
            Self::InPsiLbf => ("Btu/(hr·ft·°F)", "Btu/(hr·°F)"),
            Self::MmMpaN | Self::MPaN => ("W/(m·K)", "W/K"),
        }
    }

    /// The system's name as written in a scene.
    pub fn name(self) -> &'static str {
        match self {
            Self::InPsiLbf => "in-psi-lbf",
            Self::MmMpaN => "mm-MPa-N",
            Self::MPaN => "m-Pa-N",
        }
    }

    /// Symbols of (length, stress, force).
    pub fn symbols(self) -> (&'static str, &'static str, &'static str) {
        match self {
            Self::InPsiLbf => ("in", "psi", "lbf"),
            Self::MmMpaN => ("mm", "MPa", "N"),
            Self::MPaN => ("m", "Pa", "N"),
        }
    }
}

impl std::str::FromStr for UnitSystem {
    type Err = String;

    /// A system by its scene name (`in-psi-lbf`, `mm-MPa-N`, `m-Pa-N`).
    fn from_str(s: &str) -> Result<Self, String> {
        [Self::InPsiLbf, Self::MmMpaN, Self::MPaN]
            .into_iter()
            .find(|u| u.name() == s)
            .ok_or_else(|| format!("\"{s}\": give in-psi-lbf, mm-MPa-N or m-Pa-N"))
    }
}
