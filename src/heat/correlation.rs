//! Contact conductance h_c of two rough surfaces pressed together, from the local interface
//! pressure P (report Chapter I), and the conductance of what fills or bridges a gap.
//!
//! Every correlation here is one power law
//!
//! h_c = c · (m/σ) · k · (P/P_ref)^n,
//!
//! with the combined surface data of eq. (1.2)–(1.5): k = 2k₁k₂/(k₁+k₂) (1.2),
//! σ = (σ₁² + σ₂²)^½ (1.3), m = tan θ = (tan²θ₁ + tan²θ₂)^½ (1.4) ([`Surfaces`]):
//!
//! | [`Correlation`] | c | n | P_ref | source |
//! |---|---|---|---|---|
//! | `Cmy1969` | 1.45 | 0.985 | H | the report's eq. (1.1): Cooper, Mikic & Yovanovich, *Thermal contact conductance*, Int. J. Heat Mass Transfer 12 (1969) 279–300; plastic asperities, Gaussian heights |
//! | `Yovanovich1982` | 1.25 | 0.95 | H (H_c, the microhardness) | Yovanovich, *Thermal contact correlations*, AIAA Paper 81-1164 (1981), Progress in Astronautics and Aeronautics 83 (1982) 83–95 |
//! | `MikicElastic` | 1.54 | 0.94 | m E′/√2 | Mikic, *Thermal contact conductance; theoretical considerations*, Int. J. Heat Mass Transfer 17 (1974) 205–214; elastic asperities, 1/E′ = (1−ν₁²)/E₁ + (1−ν₂²)/E₂ ([`effective_modulus`]) |
//! | `PowerLaw` | user | user | H | a fit of one's own |
//!
//! P is the local interface pressure (compression positive here, σ_z = −P), H the hardness of the
//! softer body. In a gas add h_f = k_f/δ of an interstitial fluid over the mean distance δ between
//! the surfaces (eq. 1.6, [`fluid_gap`]); across an open gap g, h = k_gas/(g + M) with the
//! rarefaction (temperature-jump) length M ([`gas_gap`]); between facing grey surfaces the
//! linearised radiation coefficient h_r = 4 σ_SB T³ / (1/ε₁ + 1/ε₂ − 1) ([`radiation`], σ_SB =
//! 5.670374419 × 10⁻⁸ W/(m²·K⁴), CODATA 2018, exact in the 2019 SI).
//!
//! Units: SI values in the [`super::units`] newtypes; the report's units by their named
//! constructors.
//!
//! # Accuracy
//!
//! Closed forms evaluated in f64 (a few ulp). `tests/heat/correlation.rs` checks eq. (1.1) against
//! a value computed by hand, the identities of (1.2)–(1.4), that the four laws agree where their
//! parameters coincide, and that bad input names its field.
//!
//! # Cost
//!
//! One `powf` per evaluation; the Chapter V example (`examples/15_lap_joint_heat.rs`) evaluates it
//! 16 times per contact cell of its networks and prints their times.
//!
//! ```
//! use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
//! use boltzone::heat::units::{Conductivity, Length, Pressure};
//! // Chapter V: aluminium, 50 µin surfaces, tan θ = 0.1 each side combined to 0.1.
//! let s = Surfaces::new(
//!     [Conductivity::btu_per_hr_ft_f(100.0); 2],
//!     [Length::micro_inches(50.0); 2],
//!     [0.1 / 2f64.sqrt(); 2],
//!     Pressure::psi(150_000.0),
//! )?;
//! let h = ContactConductance::new(Correlation::Cmy1969, s)?;
//! let hc = h.coefficient(Pressure::psi(27_900.0))?;
//! assert!((hc.to_btu_per_hr_ft2_f() / 469_000.0 - 1.0).abs() < 0.01);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::units::{Coefficient, Conductivity, Length, Pressure};
use crate::error::{finite, non_negative, positive, InputError};
use serde::Serialize;

/// Stefan–Boltzmann constant, W/(m²·K⁴) (CODATA 2018; exact in the 2019 SI).
pub const STEFAN_BOLTZMANN: f64 = 5.670_374_419e-8;

/// Which contact conductance law (module docs for the sources).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Correlation {
    /// The report's eq. (1.1), Cooper, Mikic & Yovanovich 1969: 1.45 (m/σ) k (P/H)^0.985.
    Cmy1969,
    /// Yovanovich 1982: 1.25 (m/σ) k (P/H_c)^0.95.
    Yovanovich1982,
    /// Mikic 1974, elastic asperities: 1.54 (m/σ) k (√2 P/(m E′))^0.94.
    MikicElastic {
        /// The effective modulus E′ ([`effective_modulus`]).
        modulus: Pressure,
    },
    /// h = c (m/σ) k (P/H)^n.
    PowerLaw {
        /// The coefficient c (> 0).
        coefficient: f64,
        /// The exponent n (> 0).
        exponent: f64,
    },
}

/// The two surfaces in contact, combined by eq. (1.2)–(1.4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Surfaces {
    conductivity: [Conductivity; 2],
    roughness: [Length; 2],
    slope: [f64; 2],
    hardness: Pressure,
}

impl Surfaces {
    /// Conductivities k₁, k₂ (> 0), RMS roughnesses σ₁, σ₂ (≥ 0, not both 0), mean absolute
    /// slopes tan θ₁, tan θ₂ (≥ 0, not both 0) and the softer body's hardness H (> 0).
    pub fn new(
        conductivity: [Conductivity; 2],
        roughness: [Length; 2],
        slope: [f64; 2],
        hardness: Pressure,
    ) -> Result<Self, InputError> {
        positive("conductivity k1", conductivity[0].si())?;
        positive("conductivity k2", conductivity[1].si())?;
        non_negative("roughness sigma1", roughness[0].si())?;
        non_negative("roughness sigma2", roughness[1].si())?;
        non_negative("slope tan(theta1)", slope[0])?;
        non_negative("slope tan(theta2)", slope[1])?;
        positive("hardness H", hardness.si())?;
        let s = Self {
            conductivity,
            roughness,
            slope,
            hardness,
        };
        positive("combined roughness sigma", s.roughness().si())?;
        positive("combined slope tan(theta)", s.slope())?;
        Ok(s)
    }

    /// k = 2k₁k₂/(k₁+k₂) (eq. 1.2, the harmonic mean).
    pub fn conductivity(&self) -> Conductivity {
        let [a, b] = self.conductivity.map(Conductivity::si);
        Conductivity::from_si(2.0 * a * b / (a + b))
    }

    /// σ = (σ₁² + σ₂²)^½ (eq. 1.3).
    pub fn roughness(&self) -> Length {
        let [a, b] = self.roughness.map(Length::si);
        Length::from_si(a.hypot(b))
    }

    /// m = tan θ = (tan²θ₁ + tan²θ₂)^½ (eq. 1.4).
    pub fn slope(&self) -> f64 {
        self.slope[0].hypot(self.slope[1])
    }

    /// The softer body's hardness H.
    pub fn hardness(&self) -> Pressure {
        self.hardness
    }
}

/// 1/E′ = (1−ν₁²)/E₁ + (1−ν₂²)/E₂: the effective modulus of two elastic bodies (E > 0,
/// −1 < ν < 0.5).
pub fn effective_modulus(e: [Pressure; 2], nu: [f64; 2]) -> Result<Pressure, InputError> {
    positive("Young's modulus E1", e[0].si())?;
    positive("Young's modulus E2", e[1].si())?;
    for (field, v) in [
        ("Poisson's ratio nu1", nu[0]),
        ("Poisson's ratio nu2", nu[1]),
    ] {
        if !(v > -1.0 && v < 0.5) {
            return Err(InputError::Parameter {
                field,
                value: v,
                reason: "Poisson's ratio lies in the open interval (-1, 0.5)",
            });
        }
    }
    let c = (1.0 - nu[0] * nu[0]) / e[0].si() + (1.0 - nu[1] * nu[1]) / e[1].si();
    Ok(Pressure::from_si(1.0 / c))
}

/// A correlation bound to its surfaces: h_c as a function of the local pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactConductance {
    correlation: Correlation,
    surfaces: Surfaces,
    /// c (m/σ) k in W/(m²·K), the factor in front of (P/P_ref)^n.
    scale: f64,
    exponent: f64,
    reference: f64,
}

impl ContactConductance {
    /// Checks the correlation's own parameters.
    pub fn new(correlation: Correlation, surfaces: Surfaces) -> Result<Self, InputError> {
        let m = surfaces.slope();
        let (c, n, reference) = match correlation {
            Correlation::Cmy1969 => (1.45, 0.985, surfaces.hardness.si()),
            Correlation::Yovanovich1982 => (1.25, 0.95, surfaces.hardness.si()),
            Correlation::MikicElastic { modulus } => {
                let e = positive("effective modulus E'", modulus.si())?;
                (1.54, 0.94, m * e / 2f64.sqrt())
            }
            Correlation::PowerLaw {
                coefficient,
                exponent,
            } => (
                positive("power-law coefficient c", coefficient)?,
                positive("power-law exponent n", exponent)?,
                surfaces.hardness.si(),
            ),
        };
        let scale = c * m / surfaces.roughness().si() * surfaces.conductivity().si();
        Ok(Self {
            correlation,
            surfaces,
            scale: finite("contact conductance scale c (m/sigma) k", scale)?,
            exponent: n,
            reference,
        })
    }

    /// The law and its surfaces.
    pub fn correlation(&self) -> Correlation {
        self.correlation
    }

    /// The surfaces.
    pub fn surfaces(&self) -> &Surfaces {
        &self.surfaces
    }

    /// The exponent n of (P/P_ref)^n.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// h_c at the local interface pressure P ≥ 0 (0 at P = 0).
    pub fn coefficient(&self, pressure: Pressure) -> Result<Coefficient, InputError> {
        let p = non_negative("interface pressure P", pressure.si())?;
        Ok(Coefficient::from_si(self.coefficient_si(p)))
    }

    /// h_c in W/(m²·K) at a checked pressure in Pa (≥ 0).
    pub(crate) fn coefficient_si(&self, p: f64) -> f64 {
        if p > 0.0 {
            self.scale * (p / self.reference).powf(self.exponent)
        } else {
            0.0
        }
    }
}

/// h_f = k_f / δ: an interstitial fluid of conductivity k_f between surfaces a mean distance δ
/// apart (eq. 1.6), to be added to h_c.
pub fn fluid_gap(conductivity: Conductivity, distance: Length) -> Result<Coefficient, InputError> {
    let k = non_negative("fluid conductivity k_f", conductivity.si())?;
    let d = positive("mean distance between the surfaces", distance.si())?;
    Ok(Coefficient::from_si(k / d))
}

/// h = k_gas / (g + M): gas conduction across an open gap g ≥ 0 with the rarefaction length M ≥ 0
/// (the sum of both surfaces' temperature-jump distances; M = 0 is the continuum limit; g + M > 0).
pub fn gas_gap(
    conductivity: Conductivity,
    gap: Length,
    rarefaction: Length,
) -> Result<Coefficient, InputError> {
    let k = non_negative("gas conductivity k_gas", conductivity.si())?;
    let g = non_negative("gap g", gap.si())?;
    let m = non_negative("rarefaction length M", rarefaction.si())?;
    positive("gap plus rarefaction length g + M", g + m)?;
    Ok(Coefficient::from_si(k / (g + m)))
}

/// h_r = 4 σ_SB T³ / (1/ε₁ + 1/ε₂ − 1): radiation between two facing grey parallel surfaces of
/// emissivities 0 < ε ≤ 1 at a mean absolute temperature T (kelvin), linearised in ΔT.
pub fn radiation(emissivity: [f64; 2], kelvin: f64) -> Result<Coefficient, InputError> {
    for (field, e) in [
        ("emissivity e1", emissivity[0]),
        ("emissivity e2", emissivity[1]),
    ] {
        positive(field, e)?;
        if e > 1.0 {
            return Err(InputError::Parameter {
                field,
                value: e,
                reason: "an emissivity lies in (0, 1]",
            });
        }
    }
    let t = positive("mean temperature T (K)", kelvin)?;
    let f = 1.0 / emissivity[0] + 1.0 / emissivity[1] - 1.0;
    Ok(Coefficient::from_si(4.0 * STEFAN_BOLTZMANN * t.powi(3) / f))
}
