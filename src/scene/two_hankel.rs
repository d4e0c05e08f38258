//! The two-plate model by the semi-analytic routes for a scene, as `boltzone two --method
//! hankel` takes them: with a hole, [`crate::hankel::receding::holed`] (two equal plates,
//! infinite or with a rim C beyond B + D); without one (`hole.radius = 0`), the receding contact
//! of the two plates in series ([`Pair`]: equal or, in frictionless contact, unequal plates)
//! and, with a finite rim, [`rim_contact`] (equal plates). R_o and the interface pressure
//! only; what keeps a scene from the routes is [`blocker`] (the first blocking key, with the
//! CLI's limits), and the answer is in the scene's units.
//!
//! `method = "hankel"` asks for it; `method = "auto"` takes it, as `boltzone two --method auto`
//! does, where it applies and the tolerance is below [`AUTO_BELOW`] (above it the finite
//! elements reach the tolerance faster); where the route then declines the joint (an error of
//! the route, or a hole its modes leave unresolved, [`UNRESOLVED`]) the finite elements answer
//! and the plan says why (module [`super::run`]). Equal plates are symmetric about the
//! interface, which therefore carries no shear: welded, frictionless and frictional interfaces
//! are one problem, the plate on a frictionless rigid plane that the routes solve.
//!
//! ```
//! use boltzone::scene::{two_hankel, Scene};
//! let scene = Scene::parse(
//!     "model = \"two-plate\"\nmethod = \"hankel\"\n[hole]\nradius = 0.1\n\
//!      [load]\nouter_radius = 0.31\npressure = 1.0\n[[plates]]\nthickness = 0.1\n\
//!      material = { E = 3e7, nu = 0.3 }\n",
//! )?;
//! assert!(two_hankel::blocker(&scene).is_none());
//! // without a hole the receding contact; a fixed edge is the finite elements' alone
//! let text = "model = \"two-plate\"\nmethod = \"auto\"\n[hole]\nradius = 0.0\n\
//!             [load]\nouter_radius = 0.31\npressure = 1.0\n[[plates]]\nthickness = 0.1\n";
//! assert!(two_hankel::blocker(&Scene::parse(text)?).is_none());
//! let fixed = format!("{text}[joint]\nouter_radius = 1.54\nfixed_edge = true\n");
//! assert_eq!(two_hankel::blocker(&Scene::parse(&fixed)?).map(|b| b.0), Some("joint.fixed_edge"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Accuracy
//!
//! That of the route taken (its estimate is the scene's `r_o_error`; `converged` when it is
//! within `tolerance`); `tests/scene/two_hankel.rs` checks that the holed scene equals the
//! library call bit for bit, agrees with the finite elements within both error bars, and that
//! every blocking key is named with its line; `tests/scene/two_hankel_no_hole.rs` the same
//! without a hole (against the library call and the `two --method hankel --a 0` command).
//!
//! # Cost
//!
//! With a hole one semi-analytic solve, 0.06–0.11 s of CPU per Table 1 geometry at a
//! tolerance of 1e-3, 0.35–0.77 s at 1e-6 (module
//! [`crate::hankel::receding::holed`]'s Cost); the curve adds one evaluation per point.
//! Without a hole one receding solve, 0.1–0.2 s at B ≈ D; with a rim 0.1–0.3 s, twice with the
//! curve (its radii need R_o); timed by `tests/scene/two_hankel_no_hole.rs`.

use super::error::SceneError;
use super::file::{InterfaceKind, Model, Scene};
use super::si::joint_solved;
use super::solution::{InterfaceCurve, Solution};
use crate::contact::two_plate::{InterfaceModel, Loading};
use crate::hankel::receding::holed::two_plate_hole_to;
use crate::hankel::receding::rim::rim_contact;
use crate::hankel::receding::{Pair, RecedingParams};
use crate::joint::Joint;
use crate::route::two_plate::{self, HankelSolver, Key};

/// `method = "auto"` takes this route only below this tolerance (the route layer's choice).
pub use crate::route::two_plate::AUTO_BELOW;

/// Points of the interface curve (plus one), denser toward R_o where q ~ √(R_o − r).
const CURVE_POINTS: usize = 100;

/// The first scene key that keeps a two-plate scene from this route, with the reason; None
/// when the route applies: the route layer's [`two_plate::hankel_blocker`] on the scene's
/// question ([`question`]), its input named by the scene key. A scene whose joint cannot be
/// built is left to the scene's other checks.
pub fn blocker(scene: &Scene) -> Option<(&'static str, &'static str)> {
    if scene.model != Model::TwoPlate {
        return Some(("model", "the route is the two-plate model's"));
    }
    let (joint, nut) = joint_solved(scene).ok()?;
    let b = two_plate::hankel_blocker(&question(scene, &joint, nut))?;
    Some((scene_key(b.key), b.reason))
}

/// The first scene key that keeps a two-plate scene from the tables
/// ([`two_plate::table_answer`]), with the reason, as [`blocker`]; None when they answer.
pub fn table_blocker(scene: &Scene) -> Option<(&'static str, &'static str)> {
    if scene.model != Model::TwoPlate {
        return Some(("model", "the tables are the two-plate model's"));
    }
    let (joint, nut) = joint_solved(scene).ok()?;
    let b = two_plate::table_answer(&question(scene, &joint, nut)).err()?;
    Some((scene_key(b.key), b.reason))
}

/// The scene key of a route layer's [`Key`].
pub(super) fn scene_key(key: Key) -> &'static str {
    match key {
        Key::LowerThickness | Key::LowerModulus | Key::LowerPoisson | Key::Poisson => "plates",
        Key::LoadProfile => "load.profile",
        Key::Curve => "outputs.interface_pressure",
        Key::Interface => "joint.interface",
        Key::OuterRadius => "joint.outer_radius",
        Key::HoleRadius => "hole.radius",
        Key::LoadOuterRadius => "load.outer_radius",
        Key::NutOuterRadius => "load.nut_outer_radius",
        Key::NutDisplacement => "load.nut_displacement",
        Key::OuterEdge => "joint.fixed_edge",
        Key::Temperature => "temperature",
        Key::Field => "outputs.field",
        Key::Conductance => "outputs.conductance",
        Key::Stiffness => "outputs.stiffness",
        Key::Tolerance => "tolerance",
    }
}

/// Whether `method = "auto"` takes this route for `scene` (the route layer's choice,
/// [`two_plate::plan`]).
pub fn auto_takes(scene: &Scene) -> bool {
    let Ok((joint, nut)) = joint_solved(scene) else {
        return false;
    };
    let q = two_plate::Question {
        method: crate::route::Method::Auto,
        ..question(scene, &joint, nut)
    };
    scene.model == Model::TwoPlate
        && two_plate::plan(&q).is_ok_and(|p| p.method == crate::route::Method::Hankel)
}

/// The two-plate question of `scene` (its joint `joint` and nut displacement `nut` in the units
/// it is solved in, [`super::si::solved`]) for the route layer.
pub fn question<'a>(scene: &Scene, joint: &'a Joint, nut: Option<f64>) -> two_plate::Question<'a> {
    two_plate::Question {
        joint,
        interface: match scene.joint.interface {
            InterfaceKind::Welded => InterfaceModel::Welded,
            InterfaceKind::Frictionless => InterfaceModel::Frictionless,
            InterfaceKind::Friction => InterfaceModel::Friction {
                mu: scene.joint.mu.unwrap_or(0.0),
            },
        },
        loading: nut.map_or(Loading::Pressure, Loading::NutDisplacement),
        fixed_edge: scene.joint.fixed_edge,
        thermal: scene.temperature.is_some(),
        field: scene.outputs.field.is_some(),
        conductance: scene.outputs.conductance,
        stiffness: scene.outputs.stiffness || scene.bolt.is_some(),
        curve: scene.outputs.wants_curve(),
        method: scene.method,
        tolerance: scene.tolerance,
    }
}

/// Fills `out`'s R_o, error and `converged` from the tables ([`two_plate::table_answer`],
/// lengths in the scene's units: divided by `length`), for a scene they answer.
pub fn solve_table(scene: &Scene, joint: &Joint, length: f64, out: &mut Solution) -> bool {
    let Ok((_, nut)) = joint_solved(scene) else {
        return false;
    };
    match two_plate::table_answer(&question(scene, joint, nut)) {
        Ok(r) => {
            (out.r_o, out.r_o_error, out.converged) =
                (r.value / length, r.error / length, r.converged);
            out.full_contact = Some(false);
            true
        }
        Err(_) => false,
    }
}

/// The curve's radii as fractions of its span, denser toward R_o (q ~ √(R_o − r)).
fn curve_fractions() -> impl Iterator<Item = f64> {
    (0..=CURVE_POINTS).map(|k| 1.0 - (1.0 - k as f64 / CURVE_POINTS as f64).powi(2))
}

pub use crate::route::two_plate::UNRESOLVED;

/// Solves `joint` (in the solving units) by the route and fills `out`'s R_o, error, `converged` and, when asked,
/// the interface curve (scene units: lengths divided by `length`, pressures by `stress`);
/// returns whether the hole's modes met their residual target (always, without a hole).
/// Without a hole: the receding contact of the two plates ([`Pair::receding_contact`]), with a
/// finite rim [`rim_contact`], as `boltzone two --method hankel --a 0`.
pub fn solve(
    scene: &Scene,
    joint: &Joint,
    (length, stress): (f64, f64),
    out: &mut Solution,
) -> Result<bool, SceneError> {
    let curve_asked = scene.outputs.wants_curve();
    // `resolved`: the hole's modes met their target (always, without a hole)
    let (r_o, error, resolved, curve) = match two_plate::hankel_solver(joint) {
        HankelSolver::Holed => {
            let plate = joint
                .single_plate_substitute()
                .ok_or_else(|| SceneError::Invalid {
                    key: "plates".into(),
                    line: 1,
                    reason: "the Hankel route with a hole needs two equal plates".into(),
                })?;
            let at: Vec<f64> = match curve_asked {
                true => curve_fractions().collect(),
                false => Vec::new(),
            };
            let (h, curve) = two_plate_hole_to(&plate, scene.tolerance, &at)?;
            (h.r_o, h.info.r_o_error, h.info.hole_resolved, curve)
        }
        HankelSolver::Pair => {
            let (r_o, error, curve) = solve_pair(joint, curve_asked)?;
            (r_o, error, true, curve)
        }
        HankelSolver::Rim(c) => {
            let (r_o, error, curve) = solve_rim(scene.tolerance, joint, c, curve_asked)?;
            (r_o, error, true, curve)
        }
    };
    out.r_o = r_o / length;
    out.r_o_error = error / length;
    out.converged = resolved && crate::value::meets(r_o, error, scene.tolerance);
    out.full_contact = Some(false);
    if curve_asked {
        out.interface = Some(InterfaceCurve {
            radius: curve.iter().map(|&(r, _)| r / length).collect(),
            pressure: curve.iter().map(|&(_, q)| q / stress).collect(),
            gap: vec![0.0; curve.len()],
            shear: vec![0.0; curve.len()],
            slip: Vec::new(),
            state: Vec::new(),
        });
    }
    Ok(resolved)
}

/// R_o, its estimate and the interface curve (r, q), in the solving units.
type Answer = (f64, f64, Vec<(f64, f64)>);

/// The curve's radii on 0 ≤ r ≤ R_o when `curve` is asked.
fn radii(r_o: f64, curve: bool) -> Vec<f64> {
    match curve {
        true => curve_fractions().map(|f| r_o * f).collect(),
        false => Vec::new(),
    }
}

/// R_o, its estimate and (when `curve`) the interface pressure on 0 ≤ r ≤ R_o of two infinite
/// plates without a hole: the pair's receding contact.
fn solve_pair(joint: &Joint, curve: bool) -> Result<Answer, SceneError> {
    let pair = Pair::new(joint.upper(), joint.lower(), joint.load().clone());
    let s = pair.receding_contact(&RecedingParams::default())?;
    let q = radii(s.r_o, curve)
        .into_iter()
        .map(|r| (r, s.solution.pressure(r)))
        .collect();
    Ok((s.r_o, s.info.r_o_error, q))
}

/// The same with a rim `c` (equal plates, checked by [`blocker`]): `rim_contact` at `tolerance`.
fn solve_rim(tolerance: f64, joint: &Joint, c: f64, curve: bool) -> Result<Answer, SceneError> {
    let (d, m) = (joint.upper().thickness(), joint.upper().material());
    let params = RecedingParams::default();
    let rim = |at: &[f64]| rim_contact(d, m, joint.load(), c, &params, tolerance, at);
    let (s, _) = rim(&[])?;
    let q = match curve {
        true => rim(&radii(s.r_o, true))?.1,
        false => Vec::new(),
    };
    Ok((s.r_o, s.info.r_o_error, q))
}
