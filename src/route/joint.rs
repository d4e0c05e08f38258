//! The bolted-joint engineer's questions on the route layer: how the member stiffness k_P of a
//! two-plate question is computed ([`stiffness`]), what a catalogue bolt puts into the joint
//! ([`bolt_geometry`]: the hole radius A, the bearing radius B, the grip), and the quantities
//! of the bolt beside it ([`bolted`]: the preload F_M, the bolt's resilience δ_S, the load
//! factor Φ and the bearing pressures under head and nut), with the stiffness rules beside the
//! exact k_P ([`stiffness_rules`]). Every front end (`boltzone two --bolt … --stiffness`, the
//! scene keys `[bolt]`, `[washer]`, `[preload]`, `[outputs] stiffness`) translates its input
//! into these and their answers back; none of them decides the route or the formulas.
//!
//! - **k_P**: the two-plate finite elements' member compliance δ_P
//!   ([`crate::contact::compliance::member_compliance`], defined by work there) with the
//!   question's interface, edge and tolerance; a face pressure gives the work-conjugate δ_P,
//!   a nut displacement (a rigid head and nut) the rigid approach. The semi-analytic routes
//!   answer R_o and the interface pressure only, so a question asking k_P goes to the finite
//!   elements ([`super::two_plate::Key::Stiffness`]); R_o is then that study's.
//! - **The catalogue bolt** ([`crate::bolt::catalogue`], [`crate::bolt::thread`]): A = d_h/2 of
//!   ISO 273's series, B = d_w/2 of the head (ISO 4014/4017 d_w,min; ISO 4762 d_k) or d2/2 of
//!   the washer (ISO 7089/7093) when one is given, and the nut's own B₂ = d_w/2 (ISO 4032; the
//!   washer's d2/2) on the lower plate ([`crate::Joint::with_nut_load`]: the same force over
//!   its own annulus); the washers (one under the head, one under
//!   the nut) are taken as rigid and add 2h to the clamp length l_K of δ_S. The rules take the
//!   bolt's d, the hole d_h and the bearing diameter; without a catalogue bolt d = d_h = 2A and
//!   the bearing diameter 2B.
//! - **The bolt's quantities**: δ_S by VDI 2230's sections
//!   ([`crate::bolt::compliance::bolt_resilience`]), Φ = n δ_P/(δ_S + δ_P) with δ_P's error
//!   carried (∂Φ/∂δ_P = n δ_S/(δ_S + δ_P)²), F_M given, from the torque (VDI 2230 R13/1) or from
//!   the utilisation ν of R_p0.2 (R7/1) ([`crate::bolt::preload`]); the bearing pressure on
//!   each plate face F/(π/4 (d_o² − d_i²)) with d_o the head's (or washer's) and the nut's
//!   (or washer's) bearing diameter and d_i the larger of the hole and the washer's bore,
//!   against VDI 2230's p_G of a named material.
//!
//! Units: any consistent set of the caller (lengths, stresses, forces = stress · length²);
//! [`Scale`] converts the catalogue's millimetres and megapascals into it.
//!
//! # Accuracy
//!
//! k_P: [`crate::contact::compliance`]'s (its exact limits and error estimates,
//! `tests/joint/compliance.rs`). The rest are closed forms and table values
//! (`tests/joint/bolt.rs`, `tests/joint/catalogue.rs`, `tests/joint/rules.rs`); the fronts'
//! agreement, bit for bit on the M10 example: `tests/joint/front_ends.rs`.
//!
//! # Cost
//!
//! k_P: that of R_o's FE study at the tolerance (an M10 joint to 0.05 % in about 0.1 s); the
//! rest microseconds.
//!
//! ```
//! use boltzone::route::joint::{bolt_geometry, BoltSpec, Scale};
//! let g = bolt_geometry(&BoltSpec::new("M10"), Scale::MM_MPA)?;
//! assert_eq!((g.hole_diameter, g.head_diameter), (Some(11.0), Some(14.63))); // ISO 273, 4017
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::two_plate::Question;
use crate::bolt::catalogue::{self, HeadKind, HoleSeries, NotInCatalogue, WasherSeries};
use crate::bolt::compliance::bolt_resilience;
use crate::bolt::preload::{
    bearing_pressure, preload_from_torque, preload_from_utilisation, PropertyClass,
};
use crate::bolt::thread::{Form, Thread};
use crate::contact::compliance::{member_compliance, ComplianceParams, Head, MemberCompliance};
use crate::contact::two_plate::Loading;
use crate::contact::ContactError;
use crate::joint::{Joint, OuterRadius};
use crate::rules::{shigley, vdi2230_stiffness, wileman};
use crate::units::UnitSystem;
use crate::value::Value;
use serde::Serialize;
use std::collections::BTreeMap;

/// The caller's units per catalogue unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// Length units per millimetre.
    pub mm: f64,
    /// Stress units per megapascal.
    pub mpa: f64,
}

impl Scale {
    /// Millimetres and megapascals (the catalogue's own).
    pub const MM_MPA: Scale = Scale { mm: 1.0, mpa: 1.0 };

    /// The scale of a unit system.
    pub fn of(units: UnitSystem) -> Self {
        Self {
            mm: 1e-3 / units.length(),
            mpa: 1e6 / units.stress(),
        }
    }

    /// Force units per newton (MPa · mm² = N).
    pub fn newton(self) -> f64 {
        self.mpa * self.mm * self.mm
    }
}

/// The input of a bolted-joint question that is wrong (each front end names it: a flag, a
/// scene key).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKey {
    /// The bolt's size.
    Size,
    /// The property class.
    Grade,
    /// The washer.
    Washer,
    /// The unthreaded shank length in the grip.
    Shank,
    /// The bolt's modulus.
    Modulus,
    /// The load-introduction factor n.
    LoadIntroduction,
    /// The preload force.
    Force,
    /// The tightening torque.
    Torque,
    /// The thread friction μ_G.
    MuThread,
    /// The head friction μ_K.
    MuHead,
    /// The utilisation ν of R_p0.2.
    Utilisation,
    /// The plate material whose p_G is looked up.
    LimitMaterial,
}

/// A bolted-joint input that is wrong, and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{reason}")]
pub struct JointError {
    /// The input.
    pub key: JointKey,
    /// Why (a sentence).
    pub reason: String,
}

fn fault(key: JointKey) -> impl Fn(String) -> JointError {
    move |reason| JointError { key, reason }
}

/// A catalogue bolt as a front end asks for it (lengths and stresses in the caller's units).
#[derive(Debug, Clone, PartialEq)]
pub struct BoltSpec {
    /// "M10", "M10x1.25", "1/2-13 UNC" ([`Thread::lookup`]).
    pub size: String,
    /// The property class (needed for a preload from a utilisation).
    pub grade: Option<PropertyClass>,
    /// The head's kind.
    pub head: HeadKind,
    /// ISO 273's clearance series.
    pub hole: HoleSeries,
    /// A plain washer under the head and under the nut.
    pub washer: Option<WasherSeries>,
    /// Unthreaded shank length l_1 inside the grip (default 0: threaded through the grip).
    pub shank: f64,
    /// Bolt and nut modulus E_S (default [`BOLT_MODULUS_MPA`] converted).
    pub modulus: Option<f64>,
    /// Load-introduction factor n (default 1: under head and nut).
    pub load_introduction: f64,
}

/// VDI 2230's modulus of a steel bolt, E_S = 205 000 MPa.
pub const BOLT_MODULUS_MPA: f64 = 205e3;

impl BoltSpec {
    /// The bolt of `size` with the defaults: hexagon head, medium holes, no washer, threaded
    /// through the grip, steel, n = 1, no property class.
    pub fn new(size: &str) -> Self {
        Self {
            size: size.into(),
            grade: None,
            head: HeadKind::Hex,
            hole: HoleSeries::Medium,
            washer: None,
            shank: 0.0,
            modulus: None,
            load_introduction: 1.0,
        }
    }
}

/// The parse of a property class name: "8.8", "10.9", "12.9".
pub fn grade(name: &str) -> Result<PropertyClass, JointError> {
    match name.trim() {
        "8.8" => Ok(PropertyClass::C8_8),
        "10.9" => Ok(PropertyClass::C10_9),
        "12.9" => Ok(PropertyClass::C12_9),
        other => Err(JointError {
            key: JointKey::Grade,
            reason: format!("\"{other}\" is not a property class of ISO 898-1 (8.8, 10.9, 12.9)"),
        }),
    }
}

/// What a catalogue bolt puts into the joint (caller's lengths). The hole and bearing
/// diameters are `None` for the inch sizes (the catalogue holds their threads only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoltGeometry {
    /// The thread, in millimetres (as the catalogue holds it).
    pub thread: Thread,
    /// The thread's nominal diameter d (caller's length).
    pub d: f64,
    /// The clearance hole d_h.
    pub hole_diameter: Option<f64>,
    /// The bearing diameter on the plate under the head: the head's, or the washer's d2.
    pub head_diameter: Option<f64>,
    /// The bearing diameter on the plate under the nut: the nut's, or the washer's d2.
    pub nut_diameter: Option<f64>,
    /// The head's own bearing diameter (on the washer, if any): the torque's friction diameter.
    pub head_face: Option<f64>,
    /// The washer's bore d1 (none: no washer).
    pub washer_bore: Option<f64>,
    /// The washers' thickness added to the clamp length (2h; 0 without washers).
    pub washers_thickness: f64,
}

/// The catalogue's dimensions of `spec` in the caller's units (module docs).
pub fn bolt_geometry(spec: &BoltSpec, scale: Scale) -> Result<BoltGeometry, JointError> {
    let size = fault(JointKey::Size);
    let thread = Thread::lookup(&spec.size).map_err(|e| size(e.to_string()))?;
    let metric = thread.form == Form::Metric;
    let mm = |x: Result<f64, NotInCatalogue>| -> Result<Option<f64>, JointError> {
        match (metric, x) {
            (false, _) => Ok(None),
            (true, Ok(v)) => Ok(Some(v * scale.mm)),
            (true, Err(e)) => Err(size(e.to_string())),
        }
    };
    let hole = mm(catalogue::clearance_hole(&spec.size, spec.hole))?;
    let head = mm(catalogue::head_bearing_diameter(&spec.size, spec.head))?;
    let nut = mm(catalogue::nut_bearing_diameter(&spec.size))?;
    let washer = match spec.washer {
        None => None,
        Some(_) if !metric => {
            return Err(fault(JointKey::Washer)(format!(
                "the catalogue's washers are metric (ISO 7089/7093); \"{}\" is an inch size",
                spec.size
            )))
        }
        Some(series) => Some(
            catalogue::washer(&spec.size, series)
                .map_err(|e| fault(JointKey::Washer)(e.to_string()))?,
        ),
    };
    let on_plate = |own: Option<f64>| washer.map(|w| w.d2 * scale.mm).or(own);
    Ok(BoltGeometry {
        thread,
        d: thread.d * scale.mm,
        hole_diameter: hole,
        head_diameter: on_plate(head),
        nut_diameter: on_plate(nut),
        head_face: head,
        washer_bore: washer.map(|w| w.d1 * scale.mm),
        washers_thickness: washer.map_or(0.0, |w| 2.0 * w.h * scale.mm),
    })
}

/// The thread `t` (mm) in the caller's lengths, for the closed forms in consistent units.
fn in_lengths(t: Thread, scale: Scale) -> Thread {
    Thread {
        d: t.d * scale.mm,
        pitch: t.pitch * scale.mm,
        form: t.form,
    }
}

/// The parameters of the member-compliance study that answers `q`'s k_P: a face pressure or
/// (a nut displacement asked) a rigid head and nut; the question's interface, edge and
/// tolerance.
pub fn compliance_params(q: &Question) -> ComplianceParams {
    ComplianceParams {
        head: match q.loading {
            Loading::Pressure => Head::Pressure,
            Loading::NutDisplacement(_) => Head::Rigid,
        },
        tolerance: q.tolerance,
        contact: q.fem_params(),
    }
}

/// The member compliance δ_P and stiffness k_P of `q`'s joint (module docs).
pub fn stiffness(q: &Question) -> Result<MemberCompliance, ContactError> {
    member_compliance(q.joint, &compliance_params(q))
}

/// How the head is tightened (caller's units: force, force · length).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Preload {
    /// The preload F_M itself.
    Force(f64),
    /// The tightening torque M_A with the thread and head friction μ_G, μ_K.
    Torque {
        /// M_A.
        torque: f64,
        /// μ_G.
        mu_thread: f64,
        /// μ_K.
        mu_head: f64,
    },
    /// The utilisation ν of the property class's R_p0.2, with μ_G.
    Utilisation {
        /// ν.
        nu: f64,
        /// μ_G.
        mu_thread: f64,
    },
}

/// The bearing pressures on the plate faces under the head and the nut (stress unit), and
/// VDI 2230's limit p_G when a material was named.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BearingPressure {
    /// Under the head (on the washer under it, if any).
    pub head: f64,
    /// Under the nut.
    pub nut: f64,
    /// VDI 2230's limiting surface pressure p_G of the named material.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub limit: Option<f64>,
}

/// The bolt's quantities beside k_P (module docs), in the caller's units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Bolted {
    /// The preload F_M (force unit).
    pub preload: f64,
    /// The bolt's resilience δ_S (length per force).
    pub bolt_compliance: f64,
    /// The clamp length l_K of δ_S: the plates and the washers (length unit).
    pub clamp_length: f64,
    /// Φ = n δ_P/(δ_S + δ_P), δ_P's error carried (when k_P was computed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_factor: Option<Value>,
    /// The bearing pressures under head and nut.
    pub bearing_pressure: BearingPressure,
}

/// The bolt's quantities of `joint` clamped by the bolt `spec` (its catalogue dimensions
/// `geometry`) tightened by `preload`, with the member compliance `member` when computed, and
/// the bearing pressures against the p_G of `limit_material` when named. Without a catalogue
/// diameter the joint's own stand in: the hole 2A, the bearing diameters 2B (head) and 2B₂
/// (nut, [`Joint::nut_load`]).
pub fn bolted(
    joint: &Joint,
    spec: &BoltSpec,
    geometry: &BoltGeometry,
    preload: Preload,
    member: Option<Value>,
    limit_material: Option<&str>,
    scale: Scale,
) -> Result<Bolted, JointError> {
    let (a2, b2) = (2.0 * joint.hole_radius(), 2.0 * joint.load().outer());
    let nut2 = 2.0 * joint.nut_load().outer();
    let d_h = geometry.hole_diameter.unwrap_or(a2);
    let t = geometry.thread;
    let e_s = spec.modulus.unwrap_or(BOLT_MODULUS_MPA * scale.mpa);
    let clamp = joint.upper().thickness() + joint.lower().thickness() + geometry.washers_thickness;
    let scaled = in_lengths(t, scale);
    let delta_s = bolt_resilience(&scaled, clamp, spec.shank, e_s, e_s).map_err(|e| {
        let key = match e {
            crate::error::InputError::Parameter { .. } => JointKey::Shank,
            _ => JointKey::Modulus,
        };
        fault(key)(e.to_string())
    })?;
    let n = spec.load_introduction;
    if !(n > 0.0 && n <= 1.0) {
        return Err(fault(JointKey::LoadIntroduction)(format!(
            "the load-introduction factor n = {n} must lie in (0, 1]"
        )));
    }
    let force = preload_force(spec, geometry, preload, (a2, b2), scale)?;
    let bore = geometry.washer_bore.unwrap_or(d_h);
    let inner = bore.max(d_h);
    let pressure =
        |outer: Option<f64>, own: f64| bearing_pressure(force, outer.unwrap_or(own), inner);
    let limit = match limit_material {
        Some(m) => Some(
            catalogue::limiting_pressure(m)
                .map_err(|e| fault(JointKey::LimitMaterial)(e.to_string()))?
                * scale.mpa,
        ),
        None => None,
    };
    Ok(Bolted {
        preload: force,
        bolt_compliance: delta_s,
        clamp_length: clamp,
        load_factor: member.map(|m| load_factor(delta_s, m, n)),
        bearing_pressure: BearingPressure {
            head: pressure(geometry.head_diameter, b2),
            nut: pressure(geometry.nut_diameter, nut2),
            limit,
        },
    })
}

/// Φ = n δ_P/(δ_S + δ_P) with δ_P's error carried to first order.
pub fn load_factor(delta_s: f64, delta_p: Value, n: f64) -> Value {
    let sum = delta_s + delta_p.value;
    Value {
        value: n * delta_p.value / sum,
        error: n * delta_s / (sum * sum) * delta_p.error,
        converged: delta_p.converged,
    }
}

/// One stiffness rule beside the exact k_P: its k_P and its error against the exact one in
/// percent, or why it was left out.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StiffnessRule {
    /// The rule's k_P (force per length; absent when left out).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// (k_rule − k_P)/k_P·100 with k_P's error carried.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_percent: Option<Value>,
    /// Why the rule was left out.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub left_out: Option<String>,
}

/// The diameters the stiffness rules take (caller's lengths): the bolt's d, the hole d_h and
/// the bearing diameters d_W of the head and of the nut.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RuleDiameters {
    /// The bolt's nominal diameter d.
    pub d: f64,
    /// The hole d_h.
    pub hole: f64,
    /// The head's bearing diameter d_W.
    pub bearing: f64,
    /// The nut's bearing diameter d_W (the head's when they are alike).
    pub nut_bearing: f64,
}

impl RuleDiameters {
    /// Without a catalogue bolt: d = d_h = 2A, d_W = 2B under the head and 2B₂ under the nut.
    pub fn of_joint(joint: &Joint) -> Self {
        let a2 = 2.0 * joint.hole_radius();
        Self {
            d: a2,
            hole: a2,
            bearing: 2.0 * joint.load().outer(),
            nut_bearing: 2.0 * joint.nut_load().outer(),
        }
    }

    /// With a catalogue bolt: its d, and the hole and the head's and the nut's bearing
    /// diameters (or the washer's) where the catalogue holds them (the joint's 2A, 2B and 2B₂
    /// otherwise).
    pub fn of_bolt(joint: &Joint, g: &BoltGeometry) -> Self {
        let own = Self::of_joint(joint);
        Self {
            d: g.d,
            hole: g.hole_diameter.unwrap_or(own.hole),
            bearing: g.head_diameter.unwrap_or(own.bearing),
            nut_bearing: g.nut_diameter.unwrap_or(own.nut_bearing),
        }
    }
}

/// The JSON key `rules_member_stiffness`: `vdi2230`, `shigley`, `wileman`, `cornwell`.
pub type StiffnessRules = BTreeMap<&'static str, StiffnessRule>;

/// Why Cornwell's joint-constant fit is left out.
pub const CORNWELL_LEFT_OUT: &str = "Cornwell's joint-constant fit (J. Mech. Des. 130, 2008) is \
     not implemented: its fitted coefficients and published check were not at hand";

/// The four rules' k_P for `joint` with the diameters `dia`, each against the exact `k_p`
/// (module docs): VDI 2230's cone and sleeve (one material, finite rim D_A = 2C, a hole; each
/// side's body from its own d_W, [`vdi2230_stiffness::resilience_sides`]), Shigley's frusta
/// per member (Eq. 8-20, each frustum from its own face, [`shigley::members_sides`]),
/// Wileman's fit (one material; the constants of the material nearest in ν; it takes d and
/// the grip, no bearing diameter), Cornwell's (left out, [`CORNWELL_LEFT_OUT`]).
pub fn stiffness_rules(joint: &Joint, dia: RuleDiameters, k_p: Value) -> StiffnessRules {
    let (up, lo) = (joint.upper(), joint.lower());
    let (e1, e2) = (
        up.material().youngs_modulus(),
        lo.material().youngs_modulus(),
    );
    let one_material = up.material() == lo.material();
    let grip = up.thickness() + lo.thickness();
    let entry = |k: Result<f64, String>| match k {
        Ok(k) => StiffnessRule {
            stiffness: Some(k),
            error_percent: Some(Value::exact(k).percent_difference(k_p)),
            left_out: None,
        },
        Err(reason) => StiffnessRule {
            stiffness: None,
            error_percent: None,
            left_out: Some(reason),
        },
    };
    let one = |what: &str| format!("{what} takes one plate material; the plates differ");
    let vdi = match (one_material, joint.outer_radius()) {
        (false, _) => Err(one("VDI 2230's cone")),
        (true, OuterRadius::Infinite) => Err(
            "VDI 2230's cone angle needs a finite outside diameter D_A = 2C, and the plates \
             are infinite"
                .into(),
        ),
        (true, OuterRadius::Finite(c)) => vdi2230_stiffness::resilience_sides(
            [dia.bearing, dia.nut_bearing],
            dia.hole,
            grip,
            2.0 * c,
            e1,
        )
        .map(|r| r.stiffness)
        .map_err(|e| e.to_string()),
    };
    let shigley = shigley::members_sides(
        &[(up.thickness(), e1), (lo.thickness(), e2)],
        dia.d,
        [dia.bearing, dia.nut_bearing],
    )
    .map_err(|e| e.to_string());
    let wileman = match one_material {
        false => Err(one("Wileman's fit")),
        true => wileman::member_stiffness(
            wileman::Material::nearest(up.material().poisson_ratio()),
            e1,
            dia.d,
            grip,
        )
        .map_err(|e| e.to_string()),
    };
    BTreeMap::from([
        ("vdi2230", entry(vdi)),
        ("shigley", entry(shigley)),
        ("wileman", entry(wileman)),
        ("cornwell", entry(Err(CORNWELL_LEFT_OUT.into()))),
    ])
}

/// The bolt of a question: the catalogue bolt, its dimensions, how it is tightened and the
/// plate material whose p_G is looked up.
#[derive(Debug, Clone, Copy)]
pub struct BoltQuestion<'a> {
    /// The bolt.
    pub spec: &'a BoltSpec,
    /// Its catalogue dimensions ([`bolt_geometry`]).
    pub geometry: &'a BoltGeometry,
    /// How it is tightened.
    pub preload: Preload,
    /// VDI 2230's material name for p_G (none: no limit).
    pub limit_material: Option<&'a str>,
}

/// The bolted-joint answer in one unit system (JSON keys `member_stiffness`,
/// `member_compliance`, `rules_member_stiffness`, `preload`, `bolt_compliance`,
/// `clamp_length`, `load_factor`, `bearing_pressure`; each only when computed).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct JointAnswer {
    /// k_P (force per length).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub member_stiffness: Option<Value>,
    /// δ_P (length per force).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub member_compliance: Option<Value>,
    /// The four rules' k_P beside it.
    #[serde(
        rename = "rules_member_stiffness",
        skip_serializing_if = "Option::is_none"
    )]
    pub rules: Option<StiffnessRules>,
    /// The preload F_M (force unit).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub preload: Option<f64>,
    /// δ_S (length per force).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bolt_compliance: Option<f64>,
    /// The clamp length l_K of δ_S (length unit).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clamp_length: Option<f64>,
    /// Φ (with k_P and a bolt).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_factor: Option<Value>,
    /// Under head and nut (stress unit; with a bolt).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bearing_pressure: Option<BearingPressure>,
}

impl JointAnswer {
    /// The answer with lengths divided by `length` and forces by `force` (from SI to a scene's
    /// units: the units' metres and newtons per unit).
    pub fn in_units(self, length: f64, force: f64) -> Self {
        let (stiff, comp, stress) = (length / force, force / length, length * length / force);
        let rule = |mut r: StiffnessRule| {
            r.stiffness = r.stiffness.map(|k| k * stiff);
            r
        };
        Self {
            member_stiffness: self.member_stiffness.map(|v| v.scaled(stiff)),
            member_compliance: self.member_compliance.map(|v| v.scaled(comp)),
            rules: self
                .rules
                .map(|r| r.into_iter().map(|(k, v)| (k, rule(v))).collect()),
            preload: self.preload.map(|f| f / force),
            bolt_compliance: self.bolt_compliance.map(|d| d * comp),
            clamp_length: self.clamp_length.map(|l| l / length),
            load_factor: self.load_factor,
            bearing_pressure: self.bearing_pressure.map(|p| BearingPressure {
                head: p.head * stress,
                nut: p.nut * stress,
                limit: p.limit.map(|x| x * stress),
            }),
        }
    }
}

/// Why a bolted-joint question was not answered.
#[derive(Debug, thiserror::Error)]
pub enum AnswerError {
    /// The contact study failed.
    #[error(transparent)]
    Contact(#[from] ContactError),
    /// A bolt input is wrong.
    #[error(transparent)]
    Bolt(#[from] JointError),
}

/// The bolted-joint answer of `q` (k_P when `q.stiffness`, with the rules beside it) and of its
/// bolt (when given), in `q`'s units (module docs); with the member-compliance study, whose
/// contact solution answers R_o too.
pub fn answer(
    q: &Question,
    bolt: Option<BoltQuestion>,
    scale: Scale,
) -> Result<(JointAnswer, Option<MemberCompliance>), AnswerError> {
    let member = if q.stiffness {
        Some(stiffness(q)?)
    } else {
        None
    };
    let mut out = JointAnswer::default();
    if let Some(m) = &member {
        out.member_stiffness = Some(m.stiffness);
        out.member_compliance = Some(m.compliance);
        let dia = match bolt {
            Some(b) => RuleDiameters::of_bolt(q.joint, b.geometry),
            None => RuleDiameters::of_joint(q.joint),
        };
        out.rules = Some(stiffness_rules(q.joint, dia, m.stiffness));
    }
    if let Some(b) = bolt {
        let delta_p = member.as_ref().map(|m| m.compliance);
        let done = bolted(
            q.joint,
            b.spec,
            b.geometry,
            b.preload,
            delta_p,
            b.limit_material,
            scale,
        )?;
        out.preload = Some(done.preload);
        out.bolt_compliance = Some(done.bolt_compliance);
        out.clamp_length = Some(done.clamp_length);
        out.load_factor = done.load_factor;
        out.bearing_pressure = Some(done.bearing_pressure);
    }
    Ok((out, member))
}

/// The preload F_M of `preload` (module docs); the joint's 2A and 2B (`a2`, `b2`) stand for
/// the catalogue's missing hole and head diameters. A front end that loads the joint by the
/// preload calls it before the joint is built.
pub fn preload_force(
    spec: &BoltSpec,
    geometry: &BoltGeometry,
    preload: Preload,
    (a2, b2): (f64, f64),
    scale: Scale,
) -> Result<f64, JointError> {
    let t = geometry.thread;
    let scaled = in_lengths(t, scale);
    let d_h = geometry.hole_diameter.unwrap_or(a2);
    // the torque's friction annulus under the head: its own face over the hole (or the bore
    // of the washer it turns on)
    let face = geometry.head_face.unwrap_or(b2);
    let bore = geometry.washer_bore.unwrap_or(d_h);
    let force = match preload {
        Preload::Force(f) if f > 0.0 && f.is_finite() => f,
        Preload::Force(f) => {
            return Err(fault(JointKey::Force)(format!(
                "the preload {f} must be positive"
            )))
        }
        Preload::Torque {
            torque,
            mu_thread,
            mu_head,
        } => {
            let key = |e: &crate::error::InputError| match e.to_string() {
                s if s.contains("mu_G") => JointKey::MuThread,
                s if s.contains("mu_K") => JointKey::MuHead,
                _ => JointKey::Torque,
            };
            preload_from_torque(&scaled, torque, mu_thread, mu_head, face, bore)
                .map_err(|e| fault(key(&e))(e.to_string()))?
        }
        Preload::Utilisation { nu, mu_thread } => {
            let class = spec.grade.ok_or_else(|| {
                fault(JointKey::Grade)(
                    "a preload from a utilisation of R_p0.2 needs the property class".into(),
                )
            })?;
            let key = |e: &crate::error::InputError| match e.to_string() {
                s if s.contains("mu_G") => JointKey::MuThread,
                _ => JointKey::Utilisation,
            };
            // in newtons on the catalogue's millimetres (R_p0.2 in MPa), then converted
            preload_from_utilisation(&t, class, nu, mu_thread)
                .map_err(|e| fault(key(&e))(e.to_string()))?
                * scale.newton()
        }
    };
    Ok(force)
}
