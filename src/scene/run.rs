//! Answers one scene: builds the library objects in the units it is solved in (its own, SI with
//! temperatures: [`super::si::solved`]), runs the one route that serves the outputs asked, and
//! converts the results back to the scene's units.
//!
//! # Accuracy
//!
//! The route's own; `tests/scene/examples.rs` finds R_o bit for bit equal to the library call on
//! every example scene a solver answers, and within the bars where the tables answer.
//!
//! # Cost
//!
//! The route's (`boltzone solve --explain` prints it per step).
//!
//! ```
//! let text = "model = \"single-plate\"\n[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\n\
//!             force = 100.0\n[[plates]]\nthickness = 0.1\n";
//! let s = boltzone::solve(&boltzone::scene::Scene::parse(text)?)?;
//! // auto: R_o alone of an infinite plate inside the tables, whose bar meets the default 1e-3
//! assert_eq!(s.method, boltzone::scene::Method::Table);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::field;
use super::file::{Method, Model, Scene};
use crate::fem::single::{self as fem_single, FaceCondition, SingleParams};
use crate::hankel::hole::single_plate_separation;
use crate::hankel::{SeparationParams, Slab};
use crate::joint::Joint;
use crate::route::{single_plate, two_plate};
use std::time::Instant;

pub use super::si::{joint_si, joint_solved, solved};
pub use super::solution::{FrictionSummary, InterfaceCurve, Solution, Step};
pub use super::two_fem::two_plate_params;

pub use crate::route::single_plate::hankel_params;

/// What `method` resolves to for `scene`, and why: the route layer's choice
/// ([`two_plate::plan`], [`single_plate::plan`]) on the scene's question.
pub fn pick(scene: &Scene) -> (Method, &'static str) {
    let plan = match scene.model {
        Model::Slab => return (Method::Hankel, "Hankel transforms: the slab's exact route"),
        Model::SinglePlate => {
            let plate = joint_solved(scene)
                .ok()
                .and_then(|(j, _)| substitute(&j).ok());
            match single_plate::plan(&single_question(scene, plate.as_ref())) {
                Ok(plan) => plan,
                Err(b) => return (Method::Table, b.reason),
            }
        }
        Model::TwoPlate => {
            // a scene whose joint cannot be built, or that asks `hankel` out of reach, is refused
            // by its checks before it is solved
            let Ok((joint, nut)) = joint_solved(scene) else {
                return (Method::Fem, "finite elements");
            };
            match two_plate::plan(&super::two_hankel::question(scene, &joint, nut)) {
                Ok(plan) => plan,
                Err(b) if scene.method == Method::Table => return (Method::Table, b.reason),
                Err(b) => return (Method::Hankel, b.reason),
            }
        }
    };
    (plan.method, plan.why)
}

/// The single-plate question of `scene` for the route layer, its plate `plate` (in the units
/// it is solved in) when it can be built.
fn single_question<'a>(
    scene: &Scene,
    plate: Option<&'a crate::joint::SinglePlate>,
) -> single_plate::Question<'a> {
    single_plate::Question {
        method: scene.method,
        field: scene.outputs.field.is_some() || scene.outputs.midplane.is_some(),
        rigid_nut: scene.load.nut_displacement.is_some(),
        thermal: scene.temperature.is_some(),
        b_over_d: scene
            .plates
            .first()
            .map_or(0.0, |p| scene.load.outer_radius / p.thickness),
        curve: false,
        plate,
        tolerance: scene.tolerance,
    }
}

/// The first scene key that keeps a single-plate scene from the tables
/// ([`single_plate::table_answer`]), with the reason; None when they answer.
pub(super) fn single_table_blocker(scene: &Scene) -> Option<(&'static str, &'static str)> {
    let plate = joint_solved(scene)
        .ok()
        .and_then(|(j, _)| substitute(&j).ok())?;
    let b = single_plate::table_answer(&single_question(scene, Some(&plate))).err()?;
    Some((super::two_hankel::scene_key(b.key), b.reason))
}

/// Answers `scene`. A scene built in code is checked here as [`Scene::parse`] checks a file
/// (its errors then say line 1: there is no file).
pub fn solve(scene: &Scene) -> Result<Solution, SceneError> {
    let t0 = Instant::now();
    scene.check("")?;
    let (joint, nut) = joint_solved(scene)?;
    let to = solved(scene);
    let mut plan = vec![Step {
        name: "joint in the solving units".into(),
        ran: true,
        note: format!("from {} to {}", scene.units.name(), to.units.name()),
        seconds: t0.elapsed().as_secs_f64(),
    }];
    let (mut method, mut why) = pick(scene);
    let (l, st) = (to.length, to.stress);
    let mut out = Solution {
        r_o: 0.0,
        r_o_error: 0.0,
        converged: false,
        units: scene.units,
        length_unit: scene.units.symbols().0,
        model: scene.model,
        method,
        version: env!("CARGO_PKG_VERSION"),
        inputs: scene.understood(),
        full_contact: None,
        nut_deflection: None,
        joint_conductance: None,
        conductance_unit: None,
        heat_passes: None,
        heat_flow: None,
        heat_flow_unit: None,
        rules: Default::default(),
        friction: None,
        joint: Default::default(),
        plan: Vec::new(),
        interface: None,
        field: None,
        midplane: None,
    };
    let mut t1 = Instant::now();
    let member = super::bolt_spec::joint_step(scene, &joint, nut, &mut out, &mut plan)?;
    t1 = if member.is_some() { Instant::now() } else { t1 };
    let mut heat_step = None;
    let other = match (scene.model, method) {
        (Model::TwoPlate, Method::Table) => {
            if !super::two_hankel::solve_table(scene, &joint, l, &mut out) {
                return Err(SceneError::Invalid {
                    key: "method".into(),
                    line: 1,
                    reason: "the tables do not answer this scene".into(),
                });
            }
            None
        }
        (Model::TwoPlate, Method::Hankel) => {
            let scale = (l, st);
            let ran = super::two_hankel::solve(scene, &joint, scale, &mut out);
            let (failed, resolved) = (ran.is_err(), *ran.as_ref().unwrap_or(&true));
            let declined = match ran {
                Err(SceneError::Receding(e))
                    if two_plate::fall_back(scene.method, failed, resolved) =>
                {
                    Some(e.to_string())
                }
                Ok(_) if two_plate::fall_back(scene.method, failed, resolved) => {
                    Some(two_plate::UNRESOLVED.into())
                }
                r => r.map(|_| None)?,
            };
            match declined {
                None => Some("finite elements"),
                Some(reason) => {
                    // `auto` hands the joint the route declines to the finite elements
                    plan.push(Step {
                        name: "hankel route".into(),
                        ran: true,
                        note: format!("declined: {reason}"),
                        seconds: t1.elapsed().as_secs_f64(),
                    });
                    (method, why) = (
                        Method::Fem,
                        "finite elements: the semi-analytic route declined the joint (above)",
                    );
                    (out.method, out.interface) = (Method::Fem, None);
                    t1 = Instant::now();
                    heat_step = super::two_fem::solve(scene, &joint, nut, &mut out, None)?;
                    None
                }
            }
        }
        (Model::TwoPlate, _) => {
            heat_step = super::two_fem::solve(scene, &joint, nut, &mut out, member)?;
            None
        }
        (Model::Slab, _) => {
            let plate = substitute(&joint)?;
            let slab = Slab::new(
                plate.half_thickness(),
                plate.material(),
                plate.load().clone(),
            )?;
            let params = SeparationParams {
                rel_tol: scene.tolerance,
                ..SeparationParams::default()
            };
            let s = slab.separation_radius(&params)?;
            (out.r_o, out.r_o_error, out.converged) = (s.r_o / l, s.r_o_error / l, s.converged);
            if scene.outputs.midplane.is_some() {
                let m = field::slab_midplane(&slab, s.r_o, scene.tolerance);
                out.midplane = Some(field::midplane_scaled(m, l, st));
            }
            None
        }
        (Model::SinglePlate, Method::Fem) => {
            let params = SingleParams {
                loading: nut.map_or(FaceCondition::Pressure, |_| {
                    FaceCondition::UniformDisplacement
                }),
                tolerance: scene.tolerance,
                levels: crate::fem::single::MAX_LEVELS,
                ..SingleParams::default()
            };
            let plate = substitute(&joint)?;
            let keep = scene.outputs.field.is_some() || scene.outputs.midplane.is_some();
            let (s, h) = match &scene.temperature {
                Some(t) => super::temperature::solve_single(&plate, &params, t, st, keep)?,
                None if keep => {
                    let (s, h) = fem_single::solve_with_field(&plate, &params)?;
                    (s, Some(h))
                }
                None => (fem_single::solve(&plate, &params)?, None),
            };
            out.full_contact = Some(s.full_contact);
            if let Some(h) = h {
                if scene.outputs.field.is_some() {
                    let grid = field::single_plate_grid(plate.material(), &h)?;
                    out.field = Some(field::scaled(grid, l, st));
                }
                if scene.outputs.midplane.is_some() {
                    let m = field::single_plate_midplane(&plate, &h)?;
                    out.midplane = Some(field::midplane_scaled(m, l, st));
                }
            }
            (out.r_o, out.r_o_error, out.converged) = (s.r_o / l, s.r_o_error / l, s.converged);
            Some("Hankel + hole correction")
        }
        (Model::SinglePlate, Method::Table) => {
            let plate = substitute(&joint)?;
            let q = single_question(scene, Some(&plate));
            let r = single_plate::table_answer(&q).map_err(|b| SceneError::Invalid {
                key: super::two_hankel::scene_key(b.key).into(),
                line: 1,
                reason: b.reason.into(),
            })?;
            (out.r_o, out.r_o_error, out.converged) = (r.value / l, r.error / l, r.converged);
            Some("FE and Hankel routes (the tables answer)")
        }
        (Model::SinglePlate, _) => {
            let (search, hole) = hankel_params(scene.tolerance);
            let (s, _) = single_plate_separation(&substitute(&joint)?, &search, &hole)?;
            (out.r_o, out.r_o_error, out.converged) = (s.r_o / l, s.r_o_error / l, s.converged);
            Some("finite elements (not needed for R_o alone)")
        }
    };
    plan.push(Step {
        name: format!("{:?} route", method).to_lowercase(),
        ran: true,
        note: why.into(),
        seconds: t1.elapsed().as_secs_f64() - heat_step.unwrap_or(0.0),
    });
    plan.push(match heat_step {
        Some(seconds) => Step {
            name: "joint conductance".into(),
            ran: true,
            note: "integral of h_c(p) dA over the contact zone of the same solution".into(),
            seconds,
        },
        None => Step {
            name: "joint conductance".into(),
            ran: false,
            note: "skipped: not asked".into(),
            seconds: 0.0,
        },
    });
    if let Some(skipped) = other {
        plan.push(Step {
            name: skipped.into(),
            ran: false,
            note: "skipped: one route answers the outputs asked".into(),
            seconds: 0.0,
        });
    }
    let o = &scene.outputs;
    for (name, asked, served) in [
        (
            "interface curve",
            o.wants_curve(),
            scene.model == Model::TwoPlate,
        ),
        (
            "field (finest mesh)",
            o.field.is_some(),
            scene.model != Model::Slab,
        ),
        (
            "midplane sigma_z",
            o.midplane.is_some(),
            scene.model != Model::TwoPlate,
        ),
    ] {
        if served {
            plan.push(Step {
                name: name.into(),
                ran: asked,
                note: if asked {
                    "from the same solution (time included in the route)".into()
                } else {
                    "skipped: not asked".into()
                },
                seconds: 0.0,
            });
        }
    }
    out.rules = rules_of(scene, &out);
    out.plan = plan;
    Ok(out)
}

/// The rules of thumb beside the answer `out` (the scene's units: B, the plates' thicknesses
/// and C as written).
fn rules_of(scene: &Scene, out: &Solution) -> crate::route::rules_beside::Rules {
    let d1 = scene.plates.first().map_or(0.0, |p| p.thickness);
    let d2 = scene.plates.last().map_or(d1, |p| p.thickness);
    let c = scene.joint.outer_radius.map_or(
        crate::joint::OuterRadius::Infinite,
        crate::joint::OuterRadius::Finite,
    );
    let r_o = crate::value::Value {
        value: out.r_o,
        error: out.r_o_error,
        converged: out.converged,
    };
    crate::route::rules_beside::beside((scene.load.outer_radius, d1, d2, c), 30.0, r_o)
}

/// The single-plate substitute of a symmetric joint.
fn substitute(joint: &Joint) -> Result<crate::joint::SinglePlate, SceneError> {
    joint
        .single_plate_substitute()
        .ok_or_else(|| match joint.asymmetry() {
            Some(crate::joint::Asymmetry::NutFace) => SceneError::Invalid {
                key: "load.nut_outer_radius".into(),
                line: 1,
                reason: "the single-plate and slab models press both faces alike (B2 = B)".into(),
            },
            _ => SceneError::Invalid {
                key: "plates".into(),
                line: 1,
                reason:
                    "two unequal plates: the single-plate and slab models need two equal plates"
                        .into(),
            },
        })
}
