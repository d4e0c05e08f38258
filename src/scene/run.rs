//! Answers one scene: builds the library objects in SI units, runs the one route that serves the
//! outputs asked, and converts the results back to the scene's units.
//!
//! # Accuracy
//!
//! The route's own; `tests/scene/examples.rs` finds R_o bit for bit equal to the library call on
//! every example scene.
//!
//! # Cost
//!
//! The route's (`boltzone solve --explain` prints it per step).
//!
//! ```
//! let text = "model = \"single-plate\"\n[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\n\
//!             force = 100.0\n[[plates]]\nthickness = 0.1\n";
//! let s = boltzone::solve(&boltzone::scene::Scene::parse(text)?)?;
//! assert_eq!(s.method, boltzone::scene::Method::Hankel); // auto: R_o alone needs no FE
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::field;
use super::file::{Method, Model, Scene};
use crate::fem::single::{self as fem_single, FaceCondition, SingleParams};
use crate::hankel::hole::{single_plate_separation, HoleParams};
use crate::hankel::{SeparationParams, Slab};
use crate::joint::Joint;
use std::time::Instant;

pub use super::si::joint_si;
pub use super::solution::{InterfaceCurve, Solution, Step};
pub use super::two_fem::two_plate_params;

/// The Hankel search and hole parameters the single-plate route uses at `tolerance` (as
/// `boltzone single --method hankel`).
pub fn hankel_params(tolerance: f64) -> (SeparationParams, HoleParams) {
    let search = SeparationParams {
        rel_tol: SeparationParams::default().rel_tol.max(1e-3 * tolerance),
        ..SeparationParams::default()
    };
    (search, HoleParams::for_tolerance(tolerance))
}

/// What `method` resolves to for `scene`, and why.
pub fn pick(scene: &Scene) -> (Method, &'static str) {
    match (scene.model, scene.method) {
        (Model::TwoPlate, Method::Hankel) => (
            Method::Hankel,
            "semi-analytic two plates (asked; with a hole, or the receding contact without one): R_o and the interface pressure",
        ),
        (Model::TwoPlate, Method::Auto) if super::two_hankel::auto_takes(scene) => (
            Method::Hankel,
            "semi-analytic two plates (with a hole, or the receding contact without one): below a tolerance of 3e-5 the FE cannot claim it",
        ),
        (Model::TwoPlate, _) => (
            Method::Fem,
            "finite elements: the two-plate model's route; the interface curve comes from the same levels",
        ),
        (Model::Slab, _) => (Method::Hankel, "Hankel transforms: the slab's exact route"),
        (Model::SinglePlate, Method::Fem) => (Method::Fem, "finite elements (asked)"),
        (Model::SinglePlate, Method::Hankel) => (Method::Hankel, "Hankel + hole correction (asked)"),
        (Model::SinglePlate, Method::Auto) if scene.temperature.is_some() => (
            Method::Fem,
            "finite elements: the thermal strains of [temperature] are in the FE model only",
        ),
        (Model::SinglePlate, Method::Auto)
            if scene.outputs.field.is_some() || scene.outputs.midplane.is_some() =>
        {
            (
                Method::Fem,
                "finite elements: the field or midplane asked comes from the FE levels (Hankel gives R_o alone)",
            )
        }
        (Model::SinglePlate, Method::Auto) if scene.load.nut_displacement.is_some() => (
            Method::Fem,
            "finite elements: the Hankel route loads the faces by a pressure only",
        ),
        (Model::SinglePlate, Method::Auto) => (
            Method::Hankel,
            "Hankel + hole correction: R_o alone is a root search of milliseconds, no FE solve",
        ),
    }
}

/// Answers `scene`. A scene built in code is checked here as [`Scene::parse`] checks a file
/// (its errors then say line 1: there is no file).
pub fn solve(scene: &Scene) -> Result<Solution, SceneError> {
    let t0 = Instant::now();
    scene.check("")?;
    let (joint, nut) = joint_si(scene)?;
    let mut plan = vec![Step {
        name: "joint in SI units".into(),
        ran: true,
        note: format!("from {}", scene.units.name()),
        seconds: t0.elapsed().as_secs_f64(),
    }];
    let (mut method, mut why) = pick(scene);
    let l = scene.units.length();
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
        plan: Vec::new(),
        interface: None,
        field: None,
        midplane: None,
    };
    let mut t1 = Instant::now();
    let mut heat_step = None;
    let other = match (scene.model, method) {
        (Model::TwoPlate, Method::Hankel) => {
            let scale = (l, scene.units.stress());
            let declined = match super::two_hankel::solve(scene, &joint, scale, &mut out) {
                Err(SceneError::Receding(e)) if scene.method == Method::Auto => Some(e.to_string()),
                Ok(false) if scene.method == Method::Auto => {
                    Some(super::two_hankel::UNRESOLVED.into())
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
                    heat_step = super::two_fem::solve(scene, &joint, nut, &mut out)?;
                    None
                }
            }
        }
        (Model::TwoPlate, _) => {
            heat_step = super::two_fem::solve(scene, &joint, nut, &mut out)?;
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
                out.midplane = Some(field::midplane_scaled(m, l, scene.units.stress()));
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
                Some(t) => super::temperature::solve_single(
                    &plate,
                    &params,
                    t,
                    scene.units.stress(),
                    keep,
                )?,
                None if keep => {
                    let (s, h) = fem_single::solve_with_field(&plate, &params)?;
                    (s, Some(h))
                }
                None => (fem_single::solve(&plate, &params)?, None),
            };
            out.full_contact = Some(s.full_contact);
            if let Some(h) = h {
                let st = scene.units.stress();
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
            o.interface_pressure.is_some(),
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
    out.plan = plan;
    Ok(out)
}

/// The single-plate substitute of a symmetric joint.
fn substitute(joint: &Joint) -> Result<crate::joint::SinglePlate, SceneError> {
    joint.single_plate_substitute().ok_or(SceneError::Invalid {
        key: "plates".into(),
        line: 1,
        reason: "two unequal plates: the single-plate and slab models need two equal plates".into(),
    })
}
