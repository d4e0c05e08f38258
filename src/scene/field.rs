//! A scene's field outputs: `[outputs] field = "x.vtu"` (the finest mesh's displacements and
//! stresses, two-plate or single plate by finite elements) and `[outputs] midplane = "x.csv"`
//! (the midplane normal stress σ_z(r), compression negative: single plate by finite elements,
//! slab by Hankel transforms), in the scene's units; also the grids `boltzone two --field` and
//! `boltzone single --field` write (one construction for the commands and the scenes).
//!
//! Method: the two-plate field is the finest level [`crate::contact::two_plate::solve_field`] keeps
//! (the levels that give R_o, nothing solved twice); the single plate's is the finest level of
//! [`crate::fem::single::solve_with_field`], its upper half and the mirror image; the slab's
//! midplane is [`crate::hankel::Slab::sigma_z`] at z = 0 on 0 ≤ r ≤ 3 R_o, each value with its
//! quadrature error estimate. With `[temperature]` the grids carry σ = D (ε − ε_th) and the
//! nodal `temperature` ([`single_plate_grid`], [`two_plate_grid_with`]). [`Grid`] values are
//! converted by the scene's unit factors ([`scaled`]): lengths and displacements by the length
//! unit, stresses by the stress unit, temperatures kept.
//!
//! # Accuracy
//!
//! That of the levels (R_o's error estimate is the field's resolution near the separation);
//! `tests/scene/field.rs` checks that both midplanes change sign at the R_o of the separate root
//! search (slab: within 1e-3 R_o, the interpolation over its 121 points; FE: within twice R_o's
//! error estimate), that a field asked of a scene leaves R_o bit for bit as without it, and that
//! the VTU's largest radius is C in the scene's length unit to 1e-12.
//!
//! # Cost
//!
//! The field's levels (the FE route instead of the Hankel root search for a single plate:
//! `examples/17_scene_plan.rs` prints the times).
//!
//! ```
//! let mut g = boltzone::io::vtu::Grid::default();
//! g.points.push([0.0254, 0.0]);
//! g.add_scalar("sigma_z", vec![-6894.757293168361]);
//! let g = boltzone::scene::field::scaled(g, 0.0254, 6894.757293168361);
//! assert!((g.points[0][0] - 1.0).abs() < 1e-15 && (g.scalars[0].1[0] + 1.0).abs() < 1e-15);
//! ```

use super::error::SceneError;
use crate::contact::field::TwoPlateField;
use crate::contact::thermal::JointTemperature;
use crate::contact::two_plate::{TwoPlateParams, TwoPlateSolution};
use crate::fem::single::HalfPlate;
use crate::fem::thermal::Thermal;
use crate::fem::FemError;
use crate::hankel::Slab;
use crate::io::vtu::Grid;
use crate::joint::{Joint, SinglePlate};
use crate::material::Material;
use crate::numerics::quadrature::QuadParams;

/// The midplane normal stress σ_z(r) (scene units; compression negative).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MidplaneStress {
    /// Radii.
    pub radius: Vec<f64>,
    /// σ_z at those radii.
    pub sigma_z: Vec<f64>,
    /// Estimated absolute error of each σ_z (the slab's quadrature; None for the FE nodes).
    pub error: Option<Vec<f64>>,
}

/// `grid` with lengths (points, displacements, `gap`) divided by `length` and stresses
/// (`sigma_*`, `tau_rz`, `von_mises`, `contact_pressure`) by `stress`; `contact_status` and
/// `temperature` kept.
pub fn scaled(mut grid: Grid, length: f64, stress: f64) -> Grid {
    let l = |p: &mut [f64; 2]| p.iter_mut().for_each(|x| *x /= length);
    grid.points.iter_mut().for_each(l);
    grid.displacement.iter_mut().for_each(l);
    for (name, v) in &mut grid.scalars {
        let f = match name.as_str() {
            "gap" => length,
            "contact_status" | "temperature" => 1.0,
            _ => stress,
        };
        v.iter_mut().for_each(|x| *x /= f);
    }
    grid
}

/// The two-plate field as a grid: plate 0 the lower plate, plate 1 the upper (a symmetric
/// joint: the computed upper plate and its mirror image); interface nodes of both carry the
/// contact pressure, the gap and the status (1 closed, 0 open), every other node 0. Returns
/// the grid and a sentence on its plate layout.
pub fn two_plate_grid(
    s: &TwoPlateSolution,
    field: &TwoPlateField,
) -> Result<(Grid, &'static str), FemError> {
    two_plate_grid_with(s, field, None)
}

/// [`two_plate_grid`] of a joint with temperatures `thermal`
/// ([`crate::contact::thermal::solve_field_with_temperature`]): stresses σ = D (ε − ε_th) and
/// the nodal `temperature` (in the degrees it was given in).
pub fn two_plate_grid_with(
    s: &TwoPlateSolution,
    field: &TwoPlateField,
    thermal: Option<&Thermal>,
) -> Result<(Grid, &'static str), FemError> {
    let model = &field.model;
    let mesh = &model.mesh;
    let mut grid = match thermal {
        Some(th) => {
            let st = th.nodal_stresses(mesh, &model.materials, &field.u)?;
            let mut g = Grid::with_stresses(mesh, &st, &field.u, 0);
            g.add_scalar("temperature", th.temperature().to_vec());
            g
        }
        None => Grid::plate(mesh, &model.materials, &field.u, 0)?,
    };
    let n = mesh.n_nodes();
    let (mut p, mut g, mut st) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut faces = vec![mesh.bottom(model.upper)];
    faces.extend(model.lower.map(|l| mesh.top(l)));
    for face in &faces {
        for (i, &node) in face.iter().enumerate() {
            p[node] = s.pressure[i];
            g[node] = s.gap[i];
            st[node] = if field.closed[i] { 1.0 } else { 0.0 };
        }
    }
    grid.add_scalar("contact_pressure", p);
    grid.add_scalar("gap", g);
    grid.add_scalar("contact_status", st);
    let layout = if model.lower.is_none() {
        grid.plate.iter_mut().for_each(|id| *id = 1);
        let lower = grid.mirrored(-1);
        grid.append(&lower);
        "plate 1 = upper plate (computed on a rigid frictionless plane), plate 0 = its mirror image"
    } else {
        "plate 1 = upper plate, plate 0 = lower plate"
    };
    Ok((grid, layout))
}

/// The single plate's field: the solved upper half (plate 0) and its mirror image (plate 1).
/// With temperatures ([`HalfPlate::thermal`]) the stresses are σ = D (ε − ε_th) and the grid
/// carries the nodal `temperature` (in the degrees it was given in).
pub fn single_plate_grid(material: Material, h: &HalfPlate) -> Result<Grid, FemError> {
    let mut grid = match &h.thermal {
        Some(th) => {
            let s = th.nodal_stresses(&h.mesh, &h.materials, &h.u)?;
            let mut g = Grid::with_stresses(&h.mesh, &s, &h.u, 0);
            g.add_scalar("temperature", th.temperature().to_vec());
            g
        }
        None => Grid::plate(&h.mesh, &[material], &h.u, 0)?,
    };
    let lower = grid.mirrored(1);
    grid.append(&lower);
    Ok(grid)
}

/// The midplane of the FE single plate (finest level), in the plate's units.
pub fn single_plate_midplane(
    plate: &SinglePlate,
    h: &HalfPlate,
) -> Result<MidplaneStress, FemError> {
    let m = crate::fem::single::midplane_of(plate, h)?;
    Ok(MidplaneStress {
        radius: m.r,
        sigma_z: m.sigma_z,
        error: None,
    })
}

/// Points of the slab's midplane curve.
pub const SLAB_POINTS: usize = 121;

/// The slab's midplane σ_z on 0 ≤ r ≤ 3 R_o ([`SLAB_POINTS`] radii), in the slab's units.
pub fn slab_midplane(slab: &Slab, r_o: f64, rel_tol: f64) -> MidplaneStress {
    let params = QuadParams {
        rel_tol: rel_tol.min(1e-8),
        ..QuadParams::default()
    };
    let mut m = MidplaneStress {
        error: Some(Vec::with_capacity(SLAB_POINTS)),
        ..MidplaneStress::default()
    };
    for i in 0..SLAB_POINTS {
        let r = 3.0 * r_o * i as f64 / (SLAB_POINTS - 1) as f64;
        let e = slab.sigma_z(r, 0.0, &params);
        m.radius.push(r);
        m.sigma_z.push(e.value);
        if let Some(v) = m.error.as_mut() {
            v.push(e.error);
        }
    }
    m
}

/// `m` with radii divided by `length` and stresses by `stress`.
pub fn midplane_scaled(mut m: MidplaneStress, length: f64, stress: f64) -> MidplaneStress {
    m.radius.iter_mut().for_each(|r| *r /= length);
    m.sigma_z.iter_mut().for_each(|s| *s /= stress);
    if let Some(e) = m.error.as_mut() {
        e.iter_mut().for_each(|s| *s /= stress);
    }
    m
}

/// The two-plate joint with the temperatures `jt` (SI units) and its finest level's field
/// (thermal stresses, nodal temperature) written to `field` in the scene's units
/// `(length, stress)`.
pub fn two_plate_thermal_grid(
    joint: &Joint,
    params: &TwoPlateParams,
    jt: &JointTemperature,
    (length, stress): (f64, f64),
    field: &mut Option<Grid>,
) -> Result<TwoPlateSolution, SceneError> {
    let (s, f, th) = crate::contact::thermal::solve_field_with_temperature(joint, params, jt)?;
    let (grid, _) = two_plate_grid_with(&s, &f, Some(&th))?;
    *field = Some(scaled(grid, length, stress));
    Ok(s)
}
