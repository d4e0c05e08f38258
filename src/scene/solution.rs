//! The answer to a scene, in the scene's units: R_o with its error and `converged`, the route
//! and the plan it followed, and the outputs asked (interface curve, field, midplane σ_z, heat).
//! The JSON of `boltzone solve --json` is this type serialized. Types only, apart from the run
//! ([`super::run`]) so that the routes that fill it ([`super::from_heat`],
//! [`super::two_hankel`]) need not import the run that calls them.
//!
//! ```
//! use boltzone::scene::run::InterfaceCurve;
//! let c = InterfaceCurve::default();
//! assert!(c.radius.is_empty());
//! ```
//!
//! # Accuracy
//!
//! Types only: `tests/io/json_out.rs` (every JSON object's keys) and `tests/scene/`.
//!
//! # Cost
//!
//! None.

use super::field::MidplaneStress;
use super::file::{Method, Model, Scene};
use super::units::UnitSystem;
use crate::io::vtu::Grid;
use serde::Serialize;

/// One step of the plan: a route that ran or was skipped, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Step {
    /// What the step computes.
    pub name: String,
    /// Whether it ran.
    pub ran: bool,
    /// Why it ran or was skipped.
    pub note: String,
    /// Wall time, seconds (0 when skipped).
    pub seconds: f64,
}

/// The interface curve of the two-plate model (scene units).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct InterfaceCurve {
    /// Radii of the interface nodes.
    pub radius: Vec<f64>,
    /// Interface pressure (stress unit, compression > 0).
    pub pressure: Vec<f64>,
    /// Gap between the plates (length unit).
    pub gap: Vec<f64>,
    /// Interface shear τ on the upper plate (stress unit; 0 in the frictionless model).
    pub shear: Vec<f64>,
    /// With friction: the slip s = u_upper − u_lower of each node (length unit, outward > 0);
    /// empty otherwise.
    pub slip: Vec<f64>,
    /// With friction: each node's state, 0 open, 1 stick, 2 slip; empty otherwise.
    pub state: Vec<f64>,
}

/// What friction adds to the answer (`joint.interface = "friction"`, the keys of `two
/// --interface friction --json`): μ, the stick and slip zones as [r₁, r₂] node to node and the
/// largest slip inside the contact zone (length unit).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionSummary {
    /// The friction coefficient μ.
    pub mu: f64,
    /// Stick zones [r₁, r₂] (length unit).
    pub stick_zones: Vec<[f64; 2]>,
    /// Slip zones [r₁, r₂] (length unit).
    pub slip_zones: Vec<[f64; 2]>,
    /// Largest |slip| inside the contact zone (length unit).
    pub max_slip: f64,
}

/// The answer to a scene, in the scene's units (the JSON of `boltzone solve --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Solution {
    /// Separation radius R_o (length unit).
    pub r_o: f64,
    /// Its estimated absolute error (length unit).
    pub r_o_error: f64,
    /// Whether `r_o_error` met the tolerance relative to R_o.
    pub converged: bool,
    /// The scene's unit system.
    pub units: UnitSystem,
    /// The length unit of `r_o`, `r_o_error` (and of every length in `inputs`).
    pub length_unit: &'static str,
    /// The model.
    pub model: Model,
    /// The method that ran (`fem`, `hankel` or `table`; what `auto` picked).
    pub method: Method,
    /// boltzone's version.
    pub version: &'static str,
    /// The scene as understood, defaults filled in.
    pub inputs: Scene,
    /// Whether the plates touch out to the rim (two-plate; R_o = C).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub full_contact: Option<bool>,
    /// Mean axial displacement under the nut (two-plate; length unit, negative toward the
    /// interface).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_deflection: Option<f64>,
    /// The joint's interface conductance ∫ h_c dA (two-plate, `[outputs] conductance = true`;
    /// W/K, Btu/(hr·°F) in in-psi-lbf).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub joint_conductance: Option<f64>,
    /// The unit of `joint_conductance`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conductance_unit: Option<&'static str>,
    /// Thermal passes of `[temperature] from_heat` ([`super::from_heat`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heat_passes: Option<usize>,
    /// Heat flow through the joint with `from_heat` (`heat_flow_unit`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heat_flow: Option<f64>,
    /// The unit of `heat_flow` (W; Btu/hr in in-psi-lbf).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heat_flow_unit: Option<&'static str>,
    /// The rules of thumb beside R_o (the route layer's [`crate::route::rules_beside`]: 45°,
    /// VDI 2230, the 30° cone, each with its radius in the length unit and its error against
    /// R_o in percent; JSON `rules`), and the rules left out with the reason
    /// (`rules_left_out`).
    #[serde(flatten)]
    pub rules: crate::route::rules_beside::Rules,
    /// With friction: μ, the stick and slip zones and the largest slip (JSON `mu`,
    /// `stick_zones`, `slip_zones`, `max_slip`, as `two`'s).
    #[serde(flatten)]
    pub friction: Option<FrictionSummary>,
    /// The bolted-joint answer (`[outputs] stiffness`, `[bolt]`): k_P, δ_P, the stiffness rules,
    /// the preload, δ_S, Φ, the bearing pressures ([`crate::route::joint::JointAnswer`]; its
    /// keys only when computed).
    #[serde(flatten)]
    pub joint: crate::route::joint::JointAnswer,
    /// The plan: routes that ran and were skipped, time per step.
    pub plan: Vec<Step>,
    /// Interface curve (two-plate; written as CSV, not printed).
    #[serde(skip)]
    pub interface: Option<InterfaceCurve>,
    /// The finest mesh's field in the scene's units (`[outputs] field`; written as VTU).
    #[serde(skip)]
    pub field: Option<Grid>,
    /// The midplane σ_z(r) in the scene's units (`[outputs] midplane`; written as CSV).
    #[serde(skip)]
    pub midplane: Option<MidplaneStress>,
}
