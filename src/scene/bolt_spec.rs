//! The scene keys of a bolted joint: `[bolt]` (a catalogue bolt), `[washer]`, `[preload]` and
//! `[outputs] stiffness` — their TOML shape, how a bolt fills the hole radius A, the
//! bearing radius B and the nut's B₂ (two-plate scenes) where the scene leaves them out and a preload the bolt force
//! ([`resolve`]), and the answer's bolted-joint part in the scene's units ([`answer`]). The
//! route layer ([`crate::route::joint`]) decides how each number is computed.
//!
//! # Accuracy
//!
//! Translations only: `tests/joint/front_ends.rs` (the M10 example's scene and `two` line
//! agree bit for bit; bad keys are named with their line).
//!
//! # Cost
//!
//! Table look-ups; k_P is the route layer's.
//!
//! ```
//! let text = "units = \"mm-MPa-N\"\n[bolt]\nsize = \"M10\"\n[preload]\nforce = 20e3\n\
//!             [[plates]]\nthickness = 10.0\n";
//! let scene = boltzone::scene::Scene::parse(text)?;
//! assert_eq!((scene.hole.radius, scene.load.outer_radius), (5.5, 7.315)); // ISO 273, 4017
//! assert_eq!(scene.load.nut_outer_radius, Some(7.3)); // ISO 4032's d_w
//! assert_eq!(scene.load.force, Some(20e3));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::file::{line_of, Scene, Seg};
use crate::joint::Joint;
use crate::route::joint::{
    bolt_geometry, grade, preload_force, BoltGeometry, BoltQuestion, BoltSpec, JointAnswer,
    JointError, JointKey, Preload, Scale,
};
use crate::route::two_plate::Question;

fn k(s: &str) -> Seg {
    Seg::Key(s.into())
}

/// An error at the key `path` of `text` (its line, or 1).
fn at(text: &str, path: &[&str], reason: impl std::fmt::Display) -> SceneError {
    let segs: Vec<Seg> = path.iter().map(|s| k(s)).collect();
    SceneError::Invalid {
        key: path.join("."),
        line: line_of(text, &segs).unwrap_or(1),
        reason: reason.to_string(),
    }
}

/// The scene key of a route-layer bolt input.
fn key_of(key: JointKey) -> &'static [&'static str] {
    match key {
        JointKey::Size => &["bolt", "size"],
        JointKey::Grade => &["bolt", "grade"],
        JointKey::Washer => &["washer", "standard"],
        JointKey::Shank => &["bolt", "shank"],
        JointKey::Modulus => &["bolt", "E"],
        JointKey::LoadIntroduction => &["bolt", "load_introduction"],
        JointKey::Force => &["preload", "force"],
        JointKey::Torque => &["preload", "torque"],
        JointKey::MuThread => &["preload", "mu_thread"],
        JointKey::MuHead => &["preload", "mu_head"],
        JointKey::Utilisation => &["preload", "utilisation"],
        JointKey::LimitMaterial => &["preload", "limit_material"],
    }
}

/// A route-layer bolt error located at its scene key.
fn located(text: &str, e: JointError) -> SceneError {
    at(text, key_of(e.key), e.reason)
}

/// The route layer's bolt of `scene`, lengths and stresses scaled by `(length, stress)` (1 for
/// the scene's own units; its metres and pascals for SI).
fn spec(scene: &Scene, text: &str, (l, s): (f64, f64)) -> Result<Option<BoltSpec>, SceneError> {
    let Some(b) = &scene.bolt else {
        return Ok(None);
    };
    Ok(Some(BoltSpec {
        size: b.size.clone(),
        grade: match &b.grade {
            Some(g) => Some(grade(g).map_err(|e| located(text, e))?),
            None => None,
        },
        head: b.head,
        hole: b.hole,
        washer: scene.washer.as_ref().map(|w| w.standard),
        shank: b.shank * l,
        modulus: b.e.map(|e| e * s),
        load_introduction: b.load_introduction,
    }))
}

/// The preload of `[preload]`, forces scaled by `force` and lengths by `l`.
fn preload(
    scene: &Scene,
    text: &str,
    (l, force): (f64, f64),
) -> Result<Option<Preload>, SceneError> {
    let Some(p) = &scene.preload else {
        return Ok(None);
    };
    let given: Vec<&str> = [
        ("force", p.force.is_some()),
        ("torque", p.torque.is_some()),
        ("utilisation", p.utilisation.is_some()),
    ]
    .into_iter()
    .filter_map(|(n, g)| g.then_some(n))
    .collect();
    let need = |key: &str, v: Option<f64>, what: &str| {
        v.ok_or_else(|| at(text, &["preload", key], format!("missing: {what}")))
    };
    let mu_g = || need("mu_thread", p.mu_thread, "the thread friction mu_G");
    let unused = |key: &str, v: Option<f64>, why: &str| match v {
        Some(x) => Err(at(text, &["preload", key], format!("{x}: {why}"))),
        None => Ok(()),
    };
    match given.as_slice() {
        ["force"] => {
            unused(
                "mu_thread",
                p.mu_thread,
                "a given preload needs no friction",
            )?;
            unused("mu_head", p.mu_head, "a given preload needs no friction")?;
            Ok(Some(Preload::Force(p.force.unwrap_or(0.0) * force)))
        }
        ["torque"] => Ok(Some(Preload::Torque {
            torque: p.torque.unwrap_or(0.0) * force * l,
            mu_thread: mu_g()?,
            mu_head: need("mu_head", p.mu_head, "the head friction mu_K")?,
        })),
        ["utilisation"] => {
            unused(
                "mu_head",
                p.mu_head,
                "the utilisation needs the thread friction only",
            )?;
            Ok(Some(Preload::Utilisation {
                nu: p.utilisation.unwrap_or(0.0),
                mu_thread: mu_g()?,
            }))
        }
        [] => Err(at(
            text,
            &["preload"],
            "give one of force, torque (with mu_thread, mu_head) or utilisation (with mu_thread)",
        )),
        [.., last] => Err(at(
            text,
            &["preload", last],
            "give only one of force, torque or utilisation",
        )),
    }
}

/// Fills what `[bolt]` and `[preload]` put into the scene where it leaves them out: the hole
/// radius A = d_h/2, the bearing radius B (the head's d_w/2, or the washer's d2/2), the bolt
/// force (the preload). Errors name the key and its line in `text`; a scene with neither the
/// hole nor a bolt says the hole is missing.
pub fn resolve(scene: &mut Scene, text: &str) -> Result<(), SceneError> {
    if scene.washer.is_some() && scene.bolt.is_none() {
        return Err(at(text, &["washer"], "a washer needs a [bolt] (its size)"));
    }
    let spec = spec(scene, text, (1.0, 1.0))?;
    let scale = Scale::of(scene.units);
    let geometry = match &spec {
        Some(s) => Some(bolt_geometry(s, scale).map_err(|e| located(text, e))?),
        None => None,
    };
    let fill = |v: &mut f64, from: Option<f64>, path: &[&str], what: &str| {
        if v.is_nan() {
            *v = from.map(|d| 0.5 * d).ok_or_else(|| {
                let why = match geometry {
                    Some(_) => format!("missing: the catalogue has no {what} for this bolt"),
                    None => "missing".into(),
                };
                at(text, path, why)
            })?;
        }
        Ok::<(), SceneError>(())
    };
    let g = geometry.as_ref();
    // the nut's own face from the catalogue when the head's is too (a B given serves both)
    // (the single-plate and slab models press both faces alike: B alone)
    if scene.model == super::file::Model::TwoPlate
        && scene.load.outer_radius.is_nan()
        && scene.load.nut_outer_radius.is_none()
    {
        scene.load.nut_outer_radius = g.and_then(|g| g.nut_diameter).map(|d| 0.5 * d);
    }
    fill(
        &mut scene.hole.radius,
        g.and_then(|g| g.hole_diameter),
        &["hole", "radius"],
        "clearance hole",
    )?;
    fill(
        &mut scene.load.outer_radius,
        g.and_then(|g| g.head_diameter),
        &["load", "outer_radius"],
        "bearing diameter",
    )?;
    let l = &scene.load;
    let loaded = l.force.is_some() || l.pressure.is_some() || l.nut_displacement.is_some();
    let given = l.force;
    match (preload(scene, text, (1.0, 1.0))?, &spec, g) {
        (Some(_), None, _) => {
            return Err(at(
                text,
                &["preload"],
                "a preload needs a [bolt] (its thread)",
            ));
        }
        (Some(p), Some(s), Some(g)) => {
            let sizes = (2.0 * scene.hole.radius, 2.0 * scene.load.outer_radius);
            let f = preload_force(s, g, p, sizes, scale).map_err(|e| located(text, e))?;
            // the scene as understood (its JSON `inputs`) carries the force it filled in
            if loaded && given != Some(f) {
                return Err(at(
                    text,
                    &["preload"],
                    "the preload loads the joint: omit [load]'s force, pressure and \
                     nut_displacement",
                ));
            }
            scene.load.force = Some(f);
        }
        _ => {}
    }
    Ok(())
}

/// The bolted-joint part of `scene`'s answer on its joint `joint` in the units it is solved in
/// ([`super::si::solved`]; the route layer's [`crate::route::joint::answer`] there, converted to
/// the scene's units), with the contact
/// solution of the member-compliance study when k_P was asked. A bolt without `[preload]`
/// is tightened by `[load]`'s force (or pressure times the bearing area).
pub fn answer(
    scene: &Scene,
    joint: &Joint,
    q: &Question,
) -> Result<
    (
        JointAnswer,
        Option<crate::contact::compliance::MemberCompliance>,
    ),
    SceneError,
> {
    let to = super::si::solved(scene);
    let (l, f) = (to.length, to.force);
    let solving = Scale::of(to.units);
    let spec = spec(scene, "", (l, to.stress))?;
    let geometry: Option<BoltGeometry> = match &spec {
        Some(s) => Some(bolt_geometry(s, solving).map_err(|e| located("", e))?),
        None => None,
    };
    let preload = match preload(scene, "", (l, f))? {
        Some(p) => p,
        None => Preload::Force(joint.load().total_force()),
    };
    let limit = scene
        .preload
        .as_ref()
        .and_then(|p| p.limit_material.as_deref());
    let bolt = match (&spec, &geometry) {
        (Some(spec), Some(geometry)) => Some(BoltQuestion {
            spec,
            geometry,
            preload,
            limit_material: limit,
        }),
        _ => None,
    };
    let (a, m) = crate::route::joint::answer(q, bolt, solving).map_err(|e| match e {
        crate::route::joint::AnswerError::Bolt(e) => located("", e),
        crate::route::joint::AnswerError::Contact(e) => e.into(),
    })?;
    Ok((a.in_units(l, f), m))
}

/// The bolted-joint step of a two-plate scene that asks for it (`[outputs] stiffness` or a
/// `[bolt]`, whose load factor needs k_P): fills `out.joint`, records the step in `plan`, and returns the member-compliance
/// study (its contact solution answers R_o, [`super::two_fem::solve`]).
pub fn joint_step(
    scene: &Scene,
    joint: &Joint,
    nut: Option<f64>,
    out: &mut super::solution::Solution,
    plan: &mut Vec<super::solution::Step>,
) -> Result<Option<crate::contact::compliance::MemberCompliance>, SceneError> {
    let asked = scene.outputs.stiffness || scene.bolt.is_some();
    if scene.model != super::file::Model::TwoPlate || !asked {
        return Ok(None);
    }
    let t = std::time::Instant::now();
    let q = super::two_hankel::question(scene, joint, nut);
    let (a, member) = answer(scene, joint, &q)?;
    out.joint = a;
    plan.push(super::solution::Step {
        name: "member stiffness".into(),
        ran: true,
        note: "two-plate finite elements: delta_P by work from the contact solution (which \
               answers R_o too)"
            .into(),
        seconds: t.elapsed().as_secs_f64(),
    });
    Ok(member)
}
