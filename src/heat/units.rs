//! Quantities of heat transfer that cannot be mixed up: each is a newtype holding its SI value
//! (W, m, K, Pa), built and read only through named units.
//!
//! The report mixes feet and inches (σ = 5.9 × 10⁻⁶ ft for 50 µin surfaces, k in Btu/hr·ft·°F,
//! pressures in psi, radii in inches); here a value is always entered as `Length::inches(0.1)`
//! or `Conductivity::btu_per_hr_ft_f(100.0)` and read back as `.si()` or in a named unit.
//!
//! Conversion factors (all exact by definition, NIST Special Publication 811, 2008, Appendix B):
//! 1 in = 0.0254 m; 1 ft = 0.3048 m; 1 lbf = 0.45359237 kg × 9.80665 m/s² = 4.4482216152605 N;
//! 1 Btu (International Table) = 1055.05585262 J; 1 h = 3600 s; a temperature difference of
//! 1 °F = 5/9 K. Derived: 1 psi = 6894.757293168… Pa; 1 Btu/(hr·ft·°F) = 1.730735 W/(m·K)
//! (SP 811 lists 1.730 735 E+00); 1 Btu/(hr·ft²·°F) = 5.678263 W/(m²·K) (SP 811: 5.678 263 E+00).
//!
//! # Accuracy
//!
//! Round trips and the SP 811 values are checked in `tests/heat/correlation.rs`.
//!
//! # Cost
//!
//! One multiplication.
//!
//! ```
//! use boltzone::heat::units::{Conductivity, Length};
//! let sigma = Length::micro_inches(50.0);
//! assert!((sigma.to_feet() - 4.1667e-6).abs() < 1e-9);
//! let k = Conductivity::btu_per_hr_ft_f(100.0);
//! assert!((k.si() - 173.0735).abs() < 1e-3);
//! ```

use serde::Serialize;

/// The exact factors, defined once at the bottom layer ([`crate::units`]).
pub use crate::units::{BTU, FAHRENHEIT_DEGREE, FOOT, HOUR, INCH, POUND_FORCE, PSI};

macro_rules! quantity {
    ($(#[$doc:meta])* $name:ident, $si:literal, $( $(#[$udoc:meta])* ($from:ident, $to:ident, $factor:expr) ),* ) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Default, Serialize)]
        pub struct $name(f64);

        impl $name {
            #[doc = concat!("From its SI value (", $si, ").")]
            pub const fn from_si(value: f64) -> Self {
                Self(value)
            }

            #[doc = concat!("Its SI value (", $si, ").")]
            pub const fn si(self) -> f64 {
                self.0
            }

            $(
                $(#[$udoc])*
                pub fn $from(value: f64) -> Self {
                    Self(value * ($factor))
                }

                $(#[$udoc])*
                pub fn $to(self) -> f64 {
                    self.0 / ($factor)
                }
            )*
        }
    };
}

quantity!(
    /// A length (SI: m).
    Length, "m",
    /// Inches.
    (inches, to_inches, INCH),
    /// Feet.
    (feet, to_feet, FOOT),
    /// Micro-inches (µin, the roughness unit of the report).
    (micro_inches, to_micro_inches, 1e-6 * INCH),
    /// Micrometres.
    (micrometres, to_micrometres, 1e-6)
);

quantity!(
    /// A pressure or hardness (SI: Pa).
    Pressure, "Pa",
    /// Pounds-force per square inch.
    (psi, to_psi, PSI),
    /// Megapascals.
    (megapascals, to_megapascals, 1e6)
);

quantity!(
    /// A thermal conductivity (SI: W/(m·K)).
    Conductivity, "W/(m·K)",
    /// Btu/(hr·ft·°F).
    (btu_per_hr_ft_f, to_btu_per_hr_ft_f, BTU / HOUR / FOOT / FAHRENHEIT_DEGREE)
);

quantity!(
    /// A heat transfer coefficient, e.g. a contact conductance per area (SI: W/(m²·K)).
    Coefficient, "W/(m²·K)",
    /// Btu/(hr·ft²·°F).
    (btu_per_hr_ft2_f, to_btu_per_hr_ft2_f, BTU / HOUR / (FOOT * FOOT) / FAHRENHEIT_DEGREE)
);

quantity!(
    /// A thermal conductance (SI: W/K).
    Conductance, "W/K",
    /// Btu/(hr·°F).
    (btu_per_hr_f, to_btu_per_hr_f, BTU / HOUR / FAHRENHEIT_DEGREE)
);

quantity!(
    /// A thermal resistance (SI: K/W).
    Resistance, "K/W",
    /// °F·hr/Btu.
    (f_hr_per_btu, to_f_hr_per_btu, FAHRENHEIT_DEGREE * HOUR / BTU)
);

quantity!(
    /// A heat flow (SI: W).
    Power, "W",
    /// Btu/hr.
    (btu_per_hr, to_btu_per_hr, BTU / HOUR)
);

quantity!(
    /// A temperature difference (SI: K).
    TemperatureDifference, "K",
    /// Degrees Fahrenheit of difference.
    (fahrenheit_degrees, to_fahrenheit_degrees, FAHRENHEIT_DEGREE)
);
