//! `boltzone two --conductance`: the joint's interface conductance G = ∫ h_c(p(r)) 2πr dr over
//! the contact zone of the two-plate solution (report Chapter V; h_c by eq. 1.1 or a later
//! correlation), the scene's `[heat]` table and `[outputs] conductance = true` as flags.
//!
//! The flags translate into the scene's [`HeatSpec`] and the conductance is the scene's own
//! ([`boltzone::scene::heat::conductance`]), so `two` and `solve` give the same number;
//! conductivities in W/(m·K) (Btu/(hr·ft·°F) in in-psi-lbf), roughness in the `--units` length,
//! hardness in its stress, G in W/K (Btu/(hr·°F)).
//!
//! # Accuracy
//!
//! That of the contact solve and of [`boltzone::heat::joint`]'s nodal rule;
//! `tests/heat/cli.rs` checks a power law of exponent 1 against c (m/σ) k F/H (equilibrium)
//! and `two` against the same scene.
//!
//! # Cost
//!
//! One pass over the interface nodes (microseconds); the conductance asks the finite elements
//! (the route layer's [`boltzone::route::two_plate::Question::conductance`]).

use super::check::positive;
use super::exit::usage;
use boltzone::contact::two_plate::TwoPlateSolution;
use boltzone::scene::heat::{CorrelationSpec, HeatSpec, PowerLawSpec, CORRELATIONS};
use boltzone::scene::{SceneError, UnitSystem};
use boltzone::Joint;

/// The heat flags of `two`.
#[derive(Debug, Clone, clap::Args, serde::Serialize)]
pub struct HeatArgs {
    /// Also compute the joint's interface conductance ∫ h_c(p) dA (W/K; Btu/(hr·°F) in
    /// in-psi-lbf; JSON `joint_conductance`), from --conductivity, --roughness, --slope and
    /// --hardness. Needs the finite elements' interface pressure.
    #[arg(long, requires_all = ["conductivity", "roughness", "slope"])]
    pub conductance: bool,
    /// Contact conductance law: cmy1969 (the report's eq. 1.1), yovanovich1982 or
    /// mikic-elastic (E′ from the plates' E and ν).
    #[arg(
        long,
        default_value = "cmy1969",
        conflicts_with = "power_law",
        requires = "conductance"
    )]
    pub correlation: String,
    /// A power law h = c (m/σ) k (P/H)^n instead of --correlation: "c,n".
    #[arg(long, value_delimiter = ',', requires = "conductance")]
    pub power_law: Option<Vec<f64>>,
    /// Conductivities k₁,k₂ of the upper and lower plate (W/(m·K); Btu/(hr·ft·°F) in
    /// in-psi-lbf); one value: both.
    #[arg(long, value_delimiter = ',', num_args = 1..=2, requires = "conductance")]
    pub conductivity: Option<Vec<f64>>,
    /// RMS surface roughnesses σ₁,σ₂ (the --units length); one value: both.
    #[arg(long, value_delimiter = ',', num_args = 1..=2, requires = "conductance")]
    pub roughness: Option<Vec<f64>>,
    /// Mean absolute asperity slopes tan θ₁,tan θ₂; one value: both.
    #[arg(long, value_delimiter = ',', num_args = 1..=2, requires = "conductance")]
    pub slope: Option<Vec<f64>>,
    /// Hardness H of the softer surface (the --units stress; not used by mikic-elastic).
    #[arg(long, requires = "conductance")]
    pub hardness: Option<f64>,
}

/// The correlations `--correlation` names.
const NAMES: [&str; 3] = ["cmy1969", "yovanovich1982", "mikic-elastic"];

/// `values` as a pair (one value: both plates), each positive and finite, else refused naming
/// `flag` and `field`.
fn pair(flag: &str, field: &str, values: &[f64]) -> anyhow::Result<[f64; 2]> {
    for x in values {
        positive(flag, field, *x)?;
    }
    Ok([values[0], *values.last().unwrap_or(&values[0])])
}

impl HeatArgs {
    /// The scene's `[heat]` table of the flags (None without --conductance).
    fn spec(&self) -> anyhow::Result<Option<HeatSpec>> {
        if !self.conductance {
            return Ok(None);
        }
        let given = |v: &Option<Vec<f64>>| v.clone().unwrap_or_default();
        let correlation = match &self.power_law {
            Some(law) if law.len() != 2 => {
                let given = law
                    .iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(",");
                return usage("--power-law", given, "give two numbers c,n");
            }
            Some(law) => CorrelationSpec::Law(PowerLawSpec {
                coefficient: positive("--power-law", "coefficient c", law[0])?,
                exponent: positive("--power-law", "exponent n", law[1])?,
            }),
            None if NAMES.contains(&self.correlation.as_str()) => {
                CorrelationSpec::Name(self.correlation.clone())
            }
            None => {
                return usage(
                    "--correlation",
                    &self.correlation,
                    &format!("give one of {CORRELATIONS} (or --power-law c,n)"),
                )
            }
        };
        let hardness = match self.hardness {
            Some(h) => Some(positive("--hardness", "hardness H", h)?),
            None => None,
        };
        let spec = HeatSpec {
            correlation,
            conductivity: pair(
                "--conductivity",
                "conductivity k",
                &given(&self.conductivity),
            )?,
            roughness: pair("--roughness", "RMS roughness", &given(&self.roughness))?,
            slope: pair("--slope", "asperity slope", &given(&self.slope))?,
            hardness,
        };
        if spec.needs_hardness() && spec.hardness.is_none() {
            return usage(
                "--hardness",
                "(none)",
                &format!("the correlation needs it (all of {CORRELATIONS} but mikic-elastic)"),
            );
        }
        Ok(Some(spec))
    }

    /// Refuses bad heat flags before any solve (the conductance law built once on the unit
    /// joint's materials), naming the flag.
    pub(super) fn check(&self, units: UnitSystem, joint: &Joint) -> anyhow::Result<()> {
        if let Some(spec) = self.spec()? {
            let m = [joint.upper().material(), joint.lower().material()];
            if let Err(e) = spec.contact_solved_in(units, units, m) {
                return refused(e);
            }
        }
        Ok(())
    }

    /// The joint conductance of the solution `s` of `joint` in `units` (None without
    /// --conductance), in the conductance unit of `units`.
    pub(super) fn conductance(
        &self,
        units: UnitSystem,
        joint: &Joint,
        s: &TwoPlateSolution,
    ) -> anyhow::Result<Option<f64>> {
        let Some(spec) = self.spec()? else {
            return Ok(None);
        };
        let m = [joint.upper().material(), joint.lower().material()];
        match boltzone::scene::heat::conductance(Some(&spec), units, s, units, m) {
            Ok(g) => Ok(Some(g)),
            Err(e) => refused(e),
        }
    }
}

/// A heat law the flags cannot make (each flag was checked on its own: what is left is their
/// combination) as bad input naming the heat flags.
fn refused<T>(e: SceneError) -> anyhow::Result<T> {
    usage("--conductance", "(with its heat flags)", &e.to_string())
}

/// Adds `joint_conductance` and `conductance_unit` (the scene's keys) to the JSON `out`.
pub(super) fn add_json(out: &mut serde_json::Value, g: Option<f64>, units: UnitSystem) {
    if let Some(g) = g {
        out["joint_conductance"] = g.into();
        out["conductance_unit"] = units.heat_symbols().1.into();
    }
}

/// The text line of the conductance.
pub(super) fn line(g: f64, units: UnitSystem) -> String {
    format!(
        "joint conductance: {} {} (interface only)",
        super::exit::sig(g, 6),
        units.heat_symbols().1
    )
}
