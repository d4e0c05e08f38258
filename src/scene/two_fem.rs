//! The two-plate model of a scene by the finite elements ([`crate::contact::two_plate`]): R_o,
//! the nut's deflection and, where asked, the interface curve, the field and the joint's
//! conductance, in the scene's units; with `[temperature]` the thermal strains (module
//! [`super::temperature`], or from the heat solution, module [`super::from_heat`]). Module
//! [`super::run`] calls it for `method = "fem"`, for `auto` where the semi-analytic route does
//! not apply, and where that route declines the joint.
//!
//! # Accuracy
//!
//! That of [`crate::contact::two_plate`]; the scene against the library call:
//! `tests/scene/examples.rs`.
//!
//! # Cost
//!
//! One two-plate solve (`cargo bench --bench contact`), one more for a field.
//!
//! ```
//! let text = "model = \"two-plate\"\nmethod = \"fem\"\ntolerance = 1e-2\n[hole]\nradius = 0.1\n\
//!             [load]\nouter_radius = 0.31\npressure = 1.0\n[[plates]]\nthickness = 0.1\n";
//! let s = boltzone::solve(&boltzone::scene::Scene::parse(text)?)?;
//! assert_eq!(s.method, boltzone::scene::Method::Fem);
//! assert!(s.r_o > 0.31 && s.converged);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::field;
use super::file::Scene;
use super::si::{material_in, solved};
use super::solution::{FrictionSummary, InterfaceCurve, Solution};
use crate::contact::thermal;
use crate::contact::two_plate::{self, TwoPlateParams};
use crate::joint::Joint;
use std::time::Instant;

/// Solves `joint` (in the units the scene is solved in, [`super::si::solved`]; `nut` the nut's
/// displacement, if the scene gives one) by the finite elements and fills `out` in the
/// scene's units; returns the seconds of the conductance step
/// when it ran. The contact solution of a member-compliance study under the scene's pressure
/// (`member`) answers R_o where no field or temperature asks for another solve.
pub fn solve(
    scene: &Scene,
    joint: &Joint,
    nut: Option<f64>,
    out: &mut Solution,
    member: Option<crate::contact::compliance::MemberCompliance>,
) -> Result<Option<f64>, SceneError> {
    let to = solved(scene);
    let (l, st) = (to.length, to.stress);
    let mut heat_step = None;
    let params = two_plate_params(scene, joint, nut);
    let s = match (&scene.temperature, &scene.outputs.field) {
        (Some(t), _) if t.from_heat => {
            super::from_heat::solve(scene, joint, &params, t, out)?.solution
        }
        (Some(t), Some(_)) => {
            super::temperature::two_plate_field(joint, &params, t, (l, st), &mut out.field)?
        }
        (Some(t), None) => {
            let jt = t.joint_temperature(joint, st)?;
            thermal::solve_with_temperature(joint, &params, &jt)?
        }
        (None, Some(_)) => {
            let (s, f) = two_plate::solve_field(joint, &params)?;
            let (grid, _) = field::two_plate_grid(&s, &f)?;
            out.field = Some(field::scaled(grid, l, st));
            s
        }
        (None, None) => match member {
            Some(m) if nut.is_none() => m.contact,
            _ => two_plate::solve(joint, &params)?,
        },
    };
    (out.r_o, out.r_o_error, out.converged) = (s.r_o / l, s.r_o_error / l, s.converged);
    out.full_contact = Some(s.full_contact);
    out.nut_deflection = Some(s.nut_deflection / l);
    if let Some(f) = &s.friction {
        out.friction = Some(FrictionSummary {
            mu: f.mu,
            stick_zones: scaled_zones(f.zones(&s.radius, false), l),
            slip_zones: scaled_zones(f.zones(&s.radius, true), l),
            max_slip: f.max_slip(&s.pressure) / l,
        });
    }
    if scene.outputs.wants_curve() {
        let (slip, state) = s.friction.as_ref().map_or((vec![], vec![]), |f| {
            (
                f.slip.iter().map(|x| x / l).collect(),
                f.state.iter().map(|x| x.code()).collect(),
            )
        });
        out.interface = Some(InterfaceCurve {
            radius: s.radius.iter().map(|r| r / l).collect(),
            pressure: s.pressure.iter().map(|p| p / st).collect(),
            gap: s.gap.iter().map(|g| g / l).collect(),
            shear: s.shear.iter().map(|t| t / st).collect(),
            slip,
            state,
        });
    }
    if scene.outputs.conductance {
        let t = Instant::now();
        let last = scene.plates.len().saturating_sub(1);
        let m = [
            material_in(scene, 0, to.units)?,
            material_in(scene, last, to.units)?,
        ];
        out.joint_conductance = Some(super::heat::conductance(
            scene.heat.as_ref(),
            scene.units,
            &s,
            to.units,
            m,
        )?);
        out.conductance_unit = Some(scene.units.heat_symbols().1);
        heat_step = Some(t.elapsed().as_secs_f64());
    }
    Ok(heat_step)
}

/// Zones [r₁, r₂] in the solving units divided by the length unit `l`.
fn scaled_zones(z: Vec<[f64; 2]>, l: f64) -> Vec<[f64; 2]> {
    z.into_iter().map(|[a, b]| [a / l, b / l]).collect()
}

/// The two-plate parameters of `scene` (its joint `joint` and nut displacement `nut` in the
/// units it is solved in): the route layer's ([`crate::route::two_plate::Question::fem_params`]).
pub fn two_plate_params(scene: &Scene, joint: &Joint, nut: Option<f64>) -> TwoPlateParams {
    super::two_hankel::question(scene, joint, nut).fem_params()
}
