//! A scene's `[heat]` table and its `[outputs] conductance = true`: the joint's interface
//! conductance G = ∫ h_c(p(r)) 2πr dr over the contact zone of the two-plate solution (report
//! Chapter V; h_c by eq. 1.1 or a later correlation, [`crate::heat::correlation`], integrated by
//! [`crate::heat::joint::joint_conductance`]).
//!
//! ```toml
//! [heat]
//! correlation = "cmy1969"     # | "yovanovich1982" | "mikic-elastic" | { coefficient = c, exponent = n }
//! conductivity = [k1, k2]     # W/(m·K); Btu/(hr·ft·°F) in in-psi-lbf
//! roughness = [s1, s2]        # RMS, the scene's length unit
//! slope = [m1, m2]            # mean absolute slopes tan θ, combined by eq. 1.4
//! hardness = H                # the scene's stress unit (not used by "mikic-elastic")
//! [outputs]
//! conductance = true          # adds joint_conductance (W/K; Btu/(hr·°F) in in-psi-lbf)
//! ```
//!
//! Units: conductivity and conductance follow the scene's system ([`UnitSystem::conductivity`],
//! [`UnitSystem::conductance`]); lengths and stresses are the scene's own. `"mikic-elastic"`
//! takes E′ from the plates' materials ([`crate::heat::correlation::effective_modulus`]).
//!
//! # Accuracy
//!
//! That of the contact solve and of the nodal rule of [`crate::heat::joint`]; `tests/scene/heat.rs`
//! checks that a power law of exponent 1 gives c (m/σ) k F/H (F the bolt force: equilibrium) to
//! 1e-9 for three load profiles and an unequal pair, that the same joint in three unit systems
//! gives the same conductance to 1e-12, and that the Chapter V scene equals the library calls (R_o
//! bit for bit, G to 1e-14: the rounding of the Btu factor).
//!
//! # Cost
//!
//! One pass over the interface nodes after the contact solve (microseconds; `boltzone solve
//! --explain` prints it; `examples/18_heat_speed.rs` times it with the contact solve); the Chapter
//! V scene is `examples/scenes/chapter5_lap.toml`.
//!
//! ```
//! let text = "[hole]\nradius = 0.1\n[load]\nouter_radius = 0.13\nforce = 1000.0\n\
//!     [[plates]]\nthickness = 0.1\nmaterial = { E = 1.0e7, nu = 0.33 }\n[joint]\nouter_radius = 1.54\n\
//!     [heat]\ncorrelation = \"cmy1969\"\nconductivity = [100.0, 100.0]\n\
//!     roughness = [50e-6, 50e-6]\nslope = [0.0707, 0.0707]\nhardness = 150000.0\n\
//!     [outputs]\nconductance = true\n";
//! let s = boltzone::solve(&boltzone::scene::Scene::parse(text)?)?;
//! let g = s.joint_conductance.ok_or("no conductance")?;
//! assert!(g > 50.0 && g < 200.0, "{g} Btu/(hr·°F)"); // Chapter V: the report's 4 × 28.9
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::units::UnitSystem;
use crate::contact::two_plate::TwoPlateSolution;
use crate::heat::correlation::{effective_modulus, ContactConductance, Correlation, Surfaces};
use crate::heat::joint::{joint_conductance, JointParams};
use crate::heat::units::{Conductivity, Length, Pressure};
use crate::material::Material;
use serde::{Deserialize, Serialize};

/// The names `correlation` accepts.
pub const CORRELATIONS: &str = "\"cmy1969\", \"yovanovich1982\", \"mikic-elastic\"";

/// A user power law h = c (m/σ) k (P/H)^n.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PowerLawSpec {
    /// The coefficient c (> 0).
    pub coefficient: f64,
    /// The exponent n (> 0).
    pub exponent: f64,
}

/// `correlation`: a name or a power law.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum CorrelationSpec {
    /// One of [`CORRELATIONS`].
    Name(String),
    /// `{ coefficient = c, exponent = n }`.
    Law(PowerLawSpec),
}

fn cmy1969() -> CorrelationSpec {
    CorrelationSpec::Name("cmy1969".into())
}

/// `[heat]`: the surfaces and the contact conductance law (module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeatSpec {
    /// The law (default the report's eq. 1.1, `"cmy1969"`).
    #[serde(default = "cmy1969")]
    pub correlation: CorrelationSpec,
    /// Conductivities k₁, k₂ (W/(m·K); Btu/(hr·ft·°F) in in-psi-lbf).
    pub conductivity: [f64; 2],
    /// RMS roughnesses σ₁, σ₂ (the scene's length unit).
    pub roughness: [f64; 2],
    /// Mean absolute slopes tan θ₁, tan θ₂.
    pub slope: [f64; 2],
    /// Hardness H of the softer surface (the scene's stress unit; not used by mikic-elastic).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hardness: Option<f64>,
}

fn invalid(key: &str, reason: String) -> SceneError {
    SceneError::Invalid {
        key: key.into(),
        line: 1,
        reason,
    }
}

impl HeatSpec {
    /// The correlation and surfaces in SI units; `materials` are the top and bottom plates'
    /// (for E′). Errors name the key (line 1: [`crate::scene::check`] locates them in a file).
    pub fn contact(
        &self,
        units: UnitSystem,
        materials: [Material; 2],
    ) -> Result<ContactConductance, SceneError> {
        let hardness = self.hardness.unwrap_or(1.0) * units.stress();
        let law = match &self.correlation {
            CorrelationSpec::Name(n) => match n.as_str() {
                "cmy1969" => Correlation::Cmy1969,
                "yovanovich1982" => Correlation::Yovanovich1982,
                "mikic-elastic" => Correlation::MikicElastic {
                    modulus: effective_modulus(
                        materials.map(|m| Pressure::from_si(m.youngs_modulus())),
                        materials.map(|m| m.poisson_ratio()),
                    )?,
                },
                other => {
                    return Err(invalid(
                        "heat.correlation",
                        format!(
                        "\"{other}\": give one of {CORRELATIONS} or {{ coefficient, exponent }}"
                    ),
                    ))
                }
            },
            CorrelationSpec::Law(l) => Correlation::PowerLaw {
                coefficient: l.coefficient,
                exponent: l.exponent,
            },
        };
        let surfaces = Surfaces::new(
            self.conductivity
                .map(|k| Conductivity::from_si(k * units.conductivity())),
            self.roughness.map(|s| Length::from_si(s * units.length())),
            self.slope,
            Pressure::from_si(hardness),
        )?;
        Ok(ContactConductance::new(law, surfaces)?)
    }

    /// [`Self::contact`] with the plates' `materials` in the stresses of `solved_in` (the units
    /// the joint was solved in: a scene's, [`super::si::solved`], or `boltzone two`'s `--units`).
    pub fn contact_solved_in(
        &self,
        units: UnitSystem,
        solved_in: UnitSystem,
        materials: [Material; 2],
    ) -> Result<ContactConductance, SceneError> {
        let si =
            |m: Material| Material::new(m.youngs_modulus() * solved_in.stress(), m.poisson_ratio());
        self.contact(units, [si(materials[0])?, si(materials[1])?])
    }

    /// Whether the law needs `hardness`.
    pub fn needs_hardness(&self) -> bool {
        !matches!(&self.correlation, CorrelationSpec::Name(n) if n == "mikic-elastic")
    }
}

/// The joint conductance of a scene's `[heat]` table `spec` (None: an error, the table is
/// needed) from its solved two-plate joint `sol` and the top and bottom plates' `materials`,
/// both in the lengths and stresses of `solved_in` (a scene and `boltzone two` solve in their
/// own units, [`super::si::solved`]), in the conductance unit of `units` (the table's own).
pub fn conductance(
    spec: Option<&HeatSpec>,
    units: UnitSystem,
    sol: &TwoPlateSolution,
    solved_in: UnitSystem,
    materials: [Material; 2],
) -> Result<f64, SceneError> {
    let spec =
        spec.ok_or_else(|| invalid("outputs.conductance", "true: needs a [heat] table".into()))?;
    let mut params = JointParams::new(spec.contact_solved_in(units, solved_in, materials)?);
    params.length_unit = Length::from_si(solved_in.length());
    params.pressure_unit = Pressure::from_si(solved_in.stress());
    let g = joint_conductance(sol, &params)?;
    Ok(g.total.si() / units.conductance())
}
