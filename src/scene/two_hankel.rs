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
//! tolerance of 1e-3, 0.35–0.77 s at 1e-6 (2026-11-25, module
//! [`crate::hankel::receding::holed`]'s Cost); the curve adds one evaluation per point.
//! Without a hole one receding solve, 0.1–0.2 s at B ≈ D; with a rim 0.1–0.3 s, twice with the
//! curve (its radii need R_o); timed by `tests/scene/two_hankel_no_hole.rs`.

use super::error::SceneError;
use super::file::{InterfaceKind, Model, Scene};
use super::solution::{InterfaceCurve, Solution};
use crate::hankel::receding::holed::two_plate_hole_to;
use crate::hankel::receding::rim::rim_contact;
use crate::hankel::receding::{Pair, RecedingParams, MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
use crate::joint::{Joint, OuterRadius, Plate};
use crate::load::FaceLoad;
use crate::material::Material;

/// `method = "auto"` takes this route only below this tolerance (its reasons where it is
/// defined, beside the route's other limits).
pub use crate::hankel::receding::AUTO_BELOW;

/// Points of the interface curve (plus one), denser toward R_o where q ~ √(R_o − r).
const CURVE_POINTS: usize = 100;

/// The first scene key that keeps a two-plate scene from this route, with the reason; None
/// when the route applies. The limits are `boltzone two --method hankel`'s, flag for key: with
/// a hole two equal plates, A ≥ 0.04 D, B ≤ 16 D; without one two plates of any thickness and
/// material in frictionless contact (equal plates with any interface: they carry no shear),
/// B + 2D of the thicker plate within the receding solver's reach; a finite rim (equal plates)
/// with C − B > D and B ≤ 8 D; a pressure load, a free rim, R_o and the interface curve only.
pub fn blocker(scene: &Scene) -> Option<(&'static str, &'static str)> {
    let equal = match scene.plates.as_slice() {
        [_] => true,
        [up, lo] => up.thickness == lo.thickness && scene.material_of(0) == scene.material_of(1),
        _ => false,
    };
    let holed = scene.hole.radius > 0.0;
    let d = scene.plates.first().map_or(0.0, |p| p.thickness);
    let b = scene.load.outer_radius;
    let rim = scene.joint.outer_radius;
    let o = &scene.outputs;
    [
        (
            scene.model != Model::TwoPlate,
            "model",
            "the route is the two-plate model's",
        ),
        (
            holed && !equal,
            "plates",
            "with a hole the route needs two equal plates",
        ),
        (
            !holed && !equal && scene.joint.interface != InterfaceKind::Frictionless,
            "joint.interface",
            "without a hole the route takes two unequal plates in frictionless contact only \
             (equal plates carry no interface shear: any interface)",
        ),
        (
            !holed && !equal && rim.is_some(),
            "joint.outer_radius",
            "the route's finite rim takes two equal plates, with or without a hole",
        ),
        (
            holed && scene.hole.radius < MIN_A_OVER_D * d,
            "hole.radius",
            "the route takes holes of at least 0.04 plate thicknesses (smaller ones left \
             residual tractions of 1e1-1e4 P on the hole); or a hole radius 0 (the receding \
             contact, within A² of it)",
        ),
        (
            holed && b > MAX_B_OVER_D * d,
            "load.outer_radius",
            "with a hole the route takes loads up to 16 plate thicknesses wide (its cost grows \
             like (B/D)²: 4.7 s and 0.6 GB at 16)",
        ),
        (
            !holed && rim.is_none() && !pair_reaches(scene),
            "load.outer_radius",
            "without a hole the route takes B + 2D of the thicker plate up to 64 thicknesses \
             of the thinner",
        ),
        (
            rim.is_some() && b > MAX_B_OVER_D_RIM * d,
            "load.outer_radius",
            "with a finite joint.outer_radius the route takes loads up to 8 plate thicknesses \
             wide (the rim's cost grows like (B/D)²: with a hole 10.5 s at 8, without one 1.6 s)",
        ),
        (
            rim.is_some_and(|c| c <= b + d),
            "joint.outer_radius",
            "the route's finite rim needs C beyond B by more than D (or omit outer_radius)",
        ),
        (
            scene.load.nut_displacement.is_some(),
            "load.nut_displacement",
            "the route loads the plates by a pressure",
        ),
        (
            scene.joint.fixed_edge,
            "joint.fixed_edge",
            "the route's rim is free (a fixed edge is in the finite-element model only)",
        ),
        (
            scene.temperature.is_some(),
            "temperature",
            "thermal strains are in the finite-element model only",
        ),
        (
            o.field.is_some(),
            "outputs.field",
            "the field comes from the finite elements",
        ),
        (
            o.conductance,
            "outputs.conductance",
            "the conductance integrates the finite elements' interface pressure",
        ),
    ]
    .into_iter()
    .find_map(|(blocks, key, reason)| blocks.then_some((key, reason)))
}

/// Whether the receding solver of two plates without a hole reaches the scene's load width
/// ([`Pair::basis_size`]; it depends on B and the thicknesses only). Plates that cannot be
/// built are left to the scene's other checks.
fn pair_reaches(scene: &Scene) -> bool {
    let plate = |i: usize| {
        let t = scene.plates.get(i).or(scene.plates.first())?.thickness;
        Plate::new(t, Material::unit(0.3).ok()?).ok()
    };
    let load = FaceLoad::uniform(0.0, scene.load.outer_radius, 1.0).ok();
    match (plate(0), plate(1), load) {
        (Some(up), Some(lo), Some(load)) => Pair::new(up, lo, load)
            .basis_size(&RecedingParams::default())
            .is_ok(),
        _ => true,
    }
}

/// Whether `method = "auto"` takes this route for `scene`.
pub fn auto_takes(scene: &Scene) -> bool {
    scene.tolerance < AUTO_BELOW && blocker(scene).is_none()
}

/// The curve's radii as fractions of its span, denser toward R_o (q ~ √(R_o − r)).
fn curve_fractions() -> impl Iterator<Item = f64> {
    (0..=CURVE_POINTS).map(|k| 1.0 - (1.0 - k as f64 / CURVE_POINTS as f64).powi(2))
}

/// Why `method = "auto"` leaves a holed run whose modes stopped short of their residual target
/// to the finite elements: its ± is then no bound, where the FE's is.
pub const UNRESOLVED: &str =
    "the hole modes stopped short of their residual target, so its estimate is not trusted";

/// Solves `joint` (SI) by the route and fills `out`'s R_o, error, `converged` and, when asked,
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
    let curve_asked = scene.outputs.interface_pressure.is_some();
    // `resolved`: the hole's modes met their target (always, without a hole)
    let (r_o, error, resolved, curve) = if joint.hole_radius() <= 0.0 {
        let (r_o, error, curve) = solve_no_hole(scene.tolerance, joint, curve_asked)?;
        (r_o, error, true, curve)
    } else {
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
        });
    }
    Ok(resolved)
}

/// R_o, its estimate and the interface curve (r, q), SI.
type Answer = (f64, f64, Vec<(f64, f64)>);

/// R_o, its estimate and (when `curve`) the interface pressure on 0 ≤ r ≤ R_o of two plates
/// without a hole: infinite, the pair's receding contact; with a rim C, `rim_contact` at
/// `tolerance` (equal plates, checked by [`blocker`]).
fn solve_no_hole(tolerance: f64, joint: &Joint, curve: bool) -> Result<Answer, SceneError> {
    let params = RecedingParams::default();
    let radii = |r_o: f64| -> Vec<f64> {
        match curve {
            true => curve_fractions().map(|f| r_o * f).collect(),
            false => Vec::new(),
        }
    };
    match joint.outer_radius() {
        OuterRadius::Infinite => {
            let pair = Pair::new(joint.upper(), joint.lower(), joint.load().clone());
            let s = pair.receding_contact(&params)?;
            let q = radii(s.r_o)
                .into_iter()
                .map(|r| (r, s.solution.pressure(r)))
                .collect();
            Ok((s.r_o, s.info.r_o_error, q))
        }
        OuterRadius::Finite(c) => {
            let (d, m) = (joint.upper().thickness(), joint.upper().material());
            let rim = |at: &[f64]| rim_contact(d, m, joint.load(), c, &params, tolerance, at);
            let (s, _) = rim(&[])?;
            let q = match curve {
                true => rim(&radii(s.r_o))?.1,
                false => Vec::new(),
            };
            Ok((s.r_o, s.info.r_o_error, q))
        }
    }
}
