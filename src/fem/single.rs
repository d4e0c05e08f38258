//! The single-plate model by finite elements (Fernlund's substitution, report Chapter II.A and
//! Table 1's "single plate" column): a plate 2D thick with a hole of radius A (A = 0: none), outer
//! radius C, both faces pressed by p(r) over A..B. By symmetry only the upper half 0 ≤ z ≤ D is
//! meshed, with a roller on the midplane (w = 0, u free, τ_rz = 0), a free hole and a free rim.
//!
//! R_o is the smallest radius beyond the load (r ≥ B) where the midplane σ_z turns tensile; a
//! finite plate whose midplane stays compressive out to its rim is in full contact, R_o = C
//! ([`SingleSolution::full_contact`]; short thick plates, C − B below about D: the two-plate
//! model, which shares no code, agrees on which joints, `tests/fem/full_contact.rs`).
//! σ_z on the midplane is recovered from the roller reactions ([`super::line_traction`]:
//! σ_z = −t_z); the crossing is located inside the element edge where the nodal values change
//! sign, by linear (Q4, Cst4) or quadratic (Q9) interpolation of the nodal values.
//!
//! **Method.** Refinement levels ([`crossing_levels`]): level l is a mesh graded in r and z with element size
//! h_l = `coarse_size`·D/2^l at the foci — the hole edge A, the load's knots, the load edge B and,
//! from level 1 on, the previous level's R_o — growing away from them by the ratio `growth`
//! (radially, up to 4D) and `axial_growth` (from both faces, up to D/2); below h = D/64 (below
//! D/8 when `tolerance` < [`FIXED_GRADING_TOLERANCE`]) the ratios and the largest axial size
//! shrink ([`crate::fem::spacing::level_grading`]), so that the mesh away from the foci refines
//! too and its error shows in the level-to-level changes. Only the element size
//! at the foci halves from level to level, so the number of unknowns grows 1.5–2.8× (mean 2×) per
//! level instead of the 4× of halving every element; the meshes are not nested
//! ([`Refinement::Graded`], the default for Q9; [`Refinement::Uniform`], nested halving of
//! every element, is the default for the linear elements, whose error away from the foci the
//! graded levels do not reduce). At 68 points over the design map's range (A/D ∈ [0.2, 5],
//! B/A ∈ [1.1, 5], C = 15.4 A) graded level 5 (h = D/64 at the foci) and nested uniform level 4
//! agreed within 3.3e-5 relative, the size of the uniform level's own last change: the far
//! field left coarse does not bias R_o at that level.
//!
//! An infinite plate, or one wider than B + 30 D, is meshed to C = B + 30 D. The rim's
//! influence on the midplane σ_z is exactly an end effect: the Lamé state σ_r = −σ_θ ∝ 1/r²,
//! σ_z = 0 that a free rim at another radius adds has no σ_z, and the self-equilibrated rest
//! decays like the slowest Papkovich–Fadle mode of a plate 2D thick, e^(−2.1·(C − r)/D)
//! (sin 2λ + 2λ = 0, λ₁ ≈ 2.106 + 1.125i), i.e. by e^(−50) or more over the ≥ 24 D between
//! R_o and the cut: far below f64 resolution of R_o, so the cut adds nothing to the error.
//!
//! Units: any consistent set; R_o in the length unit of A, B, D. Sign: compression negative.
//!
//! # Accuracy
//!
//! Error estimate ([`level_estimate`]): the level-to-level changes of R_o are irregular (the
//! crossing moves through the elements; at many points the changes alternate in sign, and at some
//! the value stalls for two levels before moving on), so the last value is not extrapolated and its
//! error is estimated as the largest of the last three changes shrunk at rate 2 per level,
//! max(|d₃|, |d₂|/4, |d₁|/16). Evaluated on the levels of 156 map points (a 12 × 12 grid and
//! Table 1) against level 8 (h = D/512 at the foci), at tolerances from 2e-3 to 1e-4: no actual error
//! above its estimate (at most 0.51 of it); the two-change form max(|d₃|, |d₂|/4) exceeded its
//! estimate at 3–8 of the points, by up to 2.1 times. Example 13 repeats the check point by point;
//! `tests/fem/single.rs` checks a Table 1 row against the report within its mesh spacing and the
//! midplane traction against the applied force; `tests/fem/hole_agreement.rs` checks R_o against
//! the Hankel route with the hole.
//!
//! # Cost
//!
//! `cargo bench --bench fem` (`single_plate_r_o`: Table 1's first geometry to 0.05 %); example 13
//! (per map point).
//!
//! ```
//! use boltzone::fem::single::{single_plate_r_o, FaceCondition, SingleParams};
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.22, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1,
//!                              Material::unit(0.3)?, load)?;
//! let (r_o, info) = single_plate_r_o(&plate, &SingleParams::default())?;
//! assert!((r_o / 0.1 - 3.3).abs() < 0.2); // Table 1 (A/D = 1, B/A = 2.2): 3.3 ± its 0.15 grid
//! assert_eq!(info.levels.len(), 5);
//! assert!(info.error_estimate < 1e-3 * r_o);
//! let nut = SingleParams { loading: FaceCondition::UniformDisplacement, ..SingleParams::default() };
//! assert!(single_plate_r_o(&plate, &nut)?.0 > r_o); // a rigid nut reaches further
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::assemble::{assemble, Pattern};
use super::dofs::{Component, DofMap, Supports};
use super::element::ElementKind;
use super::error::FemError;
use super::loads::Loads;
use super::mesh::{Mesh, PlateSpec};
pub use super::midplane_crossing::{midplane_of, MidplaneNodes};
use super::ordering::node_dissection;
pub use super::single_levels::{
    coarse_radial_spacing, crossing_levels, level_spacings, CrossingLevels, LevelCrossing,
    FASTEST_ESTIMATE_RATE, FIXED_GRADING_TIGHT, FIXED_GRADING_TOLERANCE, MAX_LEVELS,
};
use super::single_temperature::SingleTemperature;
use super::solve::{Factorization, SolveParams};
use super::spacing::Spacing;
use super::thermal::Thermal;
use crate::error::InputError;
use crate::joint::{OuterRadius, SinglePlate};
use crate::material::Material;
pub use crate::numerics::convergence::level_estimate;
use crate::value::meets;
use std::time::Instant;

/// How the bolt head (and nut) load the faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FaceCondition {
    /// The face pressure p(r) of the plate's [`crate::FaceLoad`] (Table 1).
    #[default]
    Pressure,
    /// A rigid, frictionless nut: a uniform axial displacement of the face over the load's
    /// annulus (report Fig. 21), radial motion free; R_o does not depend on its magnitude.
    UniformDisplacement,
}

/// How the meshes of successive refinement levels are made (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Refinement {
    /// Graded for Q9, uniform for the linear elements (the default).
    #[default]
    Auto,
    /// Element size halved at the foci and at the previous level's R_o, grading kept (not
    /// nested; cheap). Validated for Q9, whose error away from the foci is negligible on such
    /// meshes; for Cst4 at Table 1's A/D = 0.5, B/A = 2.2 the graded levels settled 0.25 %
    /// away from the converged R_o.
    Graded,
    /// Every element of level 0 split into 2^l × 2^l (nested meshes, 4× the unknowns per
    /// level): for the linear elements (Q4, B-bar, Cst4), whose error away from the foci the
    /// graded levels do not reduce.
    Uniform,
}

impl Refinement {
    /// The refinement used for element `kind` (resolves [`Refinement::Auto`]).
    pub fn for_element(self, kind: ElementKind) -> Self {
        match (self, kind) {
            (Self::Auto, ElementKind::Q9) => Self::Graded,
            (Self::Auto, _) => Self::Uniform,
            (r, _) => r,
        }
    }
}

/// Parameters of the single-plate R_o study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SingleParams {
    /// Face pressure or rigid-nut displacement (default pressure).
    pub loading: FaceCondition,
    /// Element kind (default Q9).
    pub kind: ElementKind,
    /// Graded or uniform refinement levels (default: graded for Q9, uniform otherwise).
    pub refinement: Refinement,
    /// Element size at the foci (A, the load's knots, B, the previous R_o) on level 0, as a
    /// fraction of D (default 0.5); halved on each further level.
    pub coarse_size: f64,
    /// Radial growth ratio of element sizes away from the foci (default 1.25).
    pub growth: f64,
    /// Axial growth ratio of element sizes away from the midplane and the loaded face
    /// (default 1.5).
    pub axial_growth: f64,
    /// Number of refinement levels of [`single_plate_r_o`], ≥ 3 for the error estimate
    /// (default 5: on four levels the estimate of [`level_estimate`] still carries a
    /// sixteenth of the first, coarsest change).
    pub levels: usize,
    /// Sparse solver parameters.
    pub solve: SolveParams,
    /// Wanted relative error of R_o for [`solve`] (default 5e-4 = 0.05 %), which refines until
    /// the estimate meets it, on at least three and at most `levels` levels.
    pub tolerance: f64,
}

impl Default for SingleParams {
    fn default() -> Self {
        Self {
            loading: FaceCondition::Pressure,
            kind: ElementKind::Q9,
            refinement: Refinement::Auto,
            coarse_size: 0.5,
            growth: 1.25,
            axial_growth: 1.5,
            levels: 5,
            solve: SolveParams::default(),
            tolerance: 5e-4,
        }
    }
}

/// What the R_o study did.
#[derive(Debug, Clone, PartialEq)]
pub struct SingleInfo {
    /// R_o on each level, coarse to fine.
    pub levels: Vec<f64>,
    /// Observed order log₂|d₁/d₂| of the last two changes (None with fewer than three levels
    /// or a vanishing change); informative only, the estimate does not use it.
    pub observed_order: Option<f64>,
    /// Estimated error of the returned R_o (see the module docs).
    pub error_estimate: f64,
    /// Nodes of the finest mesh.
    pub nodes: usize,
    /// Equations of the finest mesh.
    pub dofs: usize,
    /// Wall-clock seconds for all levels.
    pub seconds: f64,
}

pub use crate::joint::FAR_RIM;

/// A solved half plate: mesh, supports, loads and nodal displacements (global frame).
#[derive(Debug, Clone)]
pub struct HalfPlate {
    /// The mesh (one plate, 0 ≤ z ≤ D).
    pub mesh: Mesh,
    /// The equation map (midplane rollers, axis, rigid-nut displacements).
    pub dofs: DofMap,
    /// Applied nodal forces.
    pub loads: Loads,
    /// Nodal displacements (u, w).
    pub u: Vec<[f64; 2]>,
    /// Element materials: the plate's one material, or one per element at its temperature.
    pub materials: Vec<Material>,
    /// The temperature field and its tables (None: isothermal; [`super::single_thermal`]).
    pub thermal: Option<Thermal>,
}

/// Solves the upper half plate on the mesh `radial` × `axial` (0 ≤ z ≤ D).
pub fn solve_half_plate(
    plate: &SinglePlate,
    loading: FaceCondition,
    kind: ElementKind,
    radial: &Spacing,
    axial: &Spacing,
    solve: &SolveParams,
) -> Result<HalfPlate, FemError> {
    let params = SingleParams {
        loading,
        kind,
        solve: *solve,
        ..SingleParams::default()
    };
    solve_half_plate_with(plate, &params, radial, axial, None)
}

/// As [`solve_half_plate`] with the loading, element and solver of `params`, and the thermal
/// strains of `temperature` when given ([`super::single_thermal`]).
pub fn solve_half_plate_with(
    plate: &SinglePlate,
    params: &SingleParams,
    radial: &Spacing,
    axial: &Spacing,
    temperature: Option<&SingleTemperature>,
) -> Result<HalfPlate, FemError> {
    let (loading, kind, solve) = (params.loading, params.kind, &params.solve);
    let mut mesh = Mesh::structured(
        kind,
        radial,
        &[PlateSpec {
            z: axial.clone(),
            material: 0,
        }],
    )?;
    let mut s = Supports::new(mesh.n_nodes());
    for n in mesh.bottom(0) {
        s.roller_z(n);
    }
    if plate.hole_radius() == 0.0 {
        for n in mesh.inner(0) {
            s.roller_r(n);
        }
    }
    let mut loads = Loads::new(mesh.n_nodes());
    match loading {
        FaceCondition::Pressure => {
            loads.add_face_pressure(&mesh, &mesh.top(0), 1.0, plate.load())?
        }
        FaceCondition::UniformDisplacement => {
            let (a, b) = (plate.load().inner(), plate.load().outer());
            let tol = 1e-12 * b;
            for n in mesh.top(0) {
                let r = mesh.nodes()[n][0];
                if r >= a - tol && r <= b + tol {
                    // δ = D/1000 of a unit-modulus plate: stresses of order 1e-3
                    s.prescribe(n, Component::Z, -1e-3 * plate.half_thickness());
                }
            }
        }
    }
    let (materials, thermal) = match temperature {
        Some(t) => {
            if loading == FaceCondition::UniformDisplacement {
                return Err(InputError::Parameter {
                    field: "face loading with temperatures",
                    value: t.reference,
                    reason:
                        "a rigid-nut displacement has no stress scale: load the faces by a pressure",
                }
                .into());
            }
            let (m, th) = t.apply(&mut mesh, plate.half_thickness(), &mut loads)?;
            (m, Some(th))
        }
        None => (vec![plate.material()], None),
    };
    // equations in nested-dissection order: the factorization needs no permutation
    let dofs = DofMap::in_node_order(&s, &node_dissection(&mesh))?;
    let k = assemble(&mesh, &materials, &dofs, &Pattern::new(&mesh, &dofs))?;
    let mut rhs = dofs.gather(loads.forces());
    for (a, b) in rhs.iter_mut().zip(&k.prescribed_load) {
        *a += b;
    }
    let x = Factorization::natural(&k.matrix, solve)?.solve(&rhs);
    let u = dofs.expand(&x);
    Ok(HalfPlate {
        mesh,
        dofs,
        loads,
        u,
        materials,
        thermal,
    })
}

/// Solves the half plate on the mesh `radial` × `nz` uniform axial elements and recovers the
/// midplane σ_z from the roller reactions.
pub fn solve_midplane(
    plate: &SinglePlate,
    loading: FaceCondition,
    kind: ElementKind,
    radial: &Spacing,
    nz: usize,
    solve: &SolveParams,
) -> Result<MidplaneNodes, FemError> {
    let z = Spacing::uniform(0.0, plate.half_thickness(), nz)?;
    solve_midplane_on(plate, loading, kind, radial, &z, solve)
}

/// As [`solve_midplane`] on the mesh `radial` × `axial` (0 ≤ z ≤ D).
pub fn solve_midplane_on(
    plate: &SinglePlate,
    loading: FaceCondition,
    kind: ElementKind,
    radial: &Spacing,
    axial: &Spacing,
    solve: &SolveParams,
) -> Result<MidplaneNodes, FemError> {
    let h = solve_half_plate(plate, loading, kind, radial, axial, solve)?;
    midplane_of(plate, &h)
}

/// R_o of the single plate refined to a tolerance: the result of [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct SingleSolution {
    /// Separation radius R_o (the last level's crossing, not extrapolated).
    pub r_o: f64,
    /// Its estimated absolute error ([`level_estimate`]).
    pub r_o_error: f64,
    /// Whether the midplane stayed compressive out to a finite rim on the finest level: full
    /// contact, R_o = C (its error the level estimate while the last two levels agree on it,
    /// else the span C − B).
    pub full_contact: bool,
    /// Whether `r_o_error` ≤ `tolerance`·R_o.
    pub converged: bool,
    /// The study's record (levels, sizes, time).
    pub info: SingleInfo,
}

/// R_o of `plate` refined level by level (module docs) until the error estimate of
/// [`level_estimate`] meets `params.tolerance` relative to R_o, on at least three and at most
/// `params.levels` levels (3..=12); when the last level misses it, `converged` is false.
pub fn solve(plate: &SinglePlate, params: &SingleParams) -> Result<SingleSolution, FemError> {
    check_tolerance(params.tolerance)?;
    Ok(study(plate, params, Some(params.tolerance), false, None)?.0)
}

pub(crate) fn check_tolerance(tolerance: f64) -> Result<(), FemError> {
    if !(tolerance > 0.0 && tolerance < 1.0) {
        return Err(InputError::Parameter {
            field: "single-plate tolerance",
            value: tolerance,
            reason: "must lie in (0, 1)",
        }
        .into());
    }
    Ok(())
}

/// The levels of `params` (all of them, or until the estimate meets `tolerance`), with the
/// thermal strains of `temperature` when given.
pub(crate) fn study(
    plate: &SinglePlate,
    params: &SingleParams,
    tolerance: Option<f64>,
    keep: bool,
    temperature: Option<&SingleTemperature>,
) -> Result<(SingleSolution, Option<HalfPlate>), FemError> {
    check_levels(params.levels)?;
    let t0 = Instant::now();
    let mut values = Vec::new();
    let mut margins = Vec::new();
    let (mut nodes, mut dofs) = (0, 0);
    let mut levels = crossing_levels(plate, params)?;
    levels.keep = keep;
    levels.temperature = temperature;
    // the span B..C in which a full contact not yet settled may still end (none without a rim)
    let span = match plate.outer_radius() {
        OuterRadius::Finite(c) => c - plate.load().outer(),
        OuterRadius::Infinite => f64::INFINITY,
    };
    // (r_o, error) and whether a full contact is still unsettled (no tolerance then out of reach)
    let level_estimate = |values: &[f64], margins: &[Option<f64>]| {
        level_estimate(values).map(|e| full_contact_estimate(e, margins, span))
    };
    for level in levels.by_ref().take(params.levels) {
        let level = level?;
        values.push(level.r_o);
        margins.push(level.full_contact_margin);
        (nodes, dofs) = (level.nodes, level.dofs);
        let met = |(_, e): (f64, f64)| tolerance.is_some_and(|t| meets(level.r_o, e, t));
        // out of reach: even shrinking FASTEST_ESTIMATE_RATE× per level, the levels left
        // cannot bring the estimate to the tolerance; stop (not converged)
        let left = params.levels.saturating_sub(values.len()) as i32;
        let hopeless = |(r, e): (f64, f64)| {
            tolerance.is_some_and(|t| e > t * r.abs() * FASTEST_ESTIMATE_RATE.powi(left))
        };
        if level_estimate(&values, &margins)
            .is_some_and(|(r, e, unsettled)| met((r, e)) || (!unsettled && hopeless((r, e))))
        {
            break;
        }
    }
    let (r_o, r_o_error, _) = level_estimate(&values, &margins).ok_or(FemError::Solver(
        "fewer than three refinement levels were solved".into(),
    ))?;
    let solution = SingleSolution {
        r_o,
        r_o_error,
        full_contact: margins.last().is_some_and(Option::is_some),
        converged: meets(r_o, r_o_error, tolerance.unwrap_or(params.tolerance)),
        info: SingleInfo {
            observed_order: observed_order(&values),
            levels: values,
            error_estimate: r_o_error,
            nodes,
            dofs,
            seconds: t0.elapsed().as_secs_f64(),
        },
    };
    Ok((solution, levels.last.take()))
}

/// The level estimate `(r_o, error)` where a level found full contact (R_o = C, its midplane
/// compressive out to the rim by `margins`), and whether that is still unsettled. It stands
/// when no level was in full contact, when the last three were (and the last margin exceeds
/// four times each of their two changes: the sign of σ_z near the rim settled), or when the
/// last three all found a crossing; otherwise R_o may yet lie anywhere in B..C, and the error
/// is that width, `span`. On (A, B, D, C) = (0.1, 0.2, 0.5, 0.58) the margins were 5.1e-4,
/// 7.1e-4, 6.1e-4 P on levels 1–3 (a rule of half the last margin would have settled there),
/// then 2.5e-4, 4.0e-5 P: the two-plate
/// model, which shares no code, opens 1.2e-3 inside that rim; at C = 0.57 they were 5.29e-3,
/// 5.24e-3, 5.08e-3 P. (Those later levels were graded at A and B only; graded at the rim too,
/// as [`crossing_levels`] now does after a level in full contact, level 4 finds the crossing
/// and at --tol 1e-4 R_o converges to 0.579326 ± 3.1e-5, within the bar of a run to 1e-5,
/// 0.5792983 ± 3.6e-6.) `tests/fem/full_contact.rs`.
fn full_contact_estimate(
    (r_o, error): (f64, f64),
    margins: &[Option<f64>],
    span: f64,
) -> (f64, f64, bool) {
    let settled = match margins {
        [.., None, None, None] => true,
        [.., Some(m0), Some(m1), Some(m2)] => {
            *m2 > 0.0 && 4.0 * (m2 - m1).abs().max((m1 - m0).abs()) < *m2
        }
        // fewer than three levels, or a change between full contact and a crossing among
        // the last three
        _ => margins.iter().all(Option::is_none),
    };
    match settled {
        true => (r_o, error, false),
        false => (r_o, error.max(span), true),
    }
}

fn check_levels(levels: usize) -> Result<(), FemError> {
    if !(3..=12).contains(&levels) {
        return Err(InputError::Parameter {
            field: "refinement levels",
            value: levels as f64,
            reason: "must lie in 3..=12",
        }
        .into());
    }
    Ok(())
}

/// log₂|d₁/d₂| of the last two changes (None with fewer than three values or a vanishing change).
fn observed_order(values: &[f64]) -> Option<f64> {
    let n = values.len();
    if n < 3 {
        return None;
    }
    let ratio = ((values[n - 2] - values[n - 3]) / (values[n - 1] - values[n - 2])).abs();
    (ratio.is_finite() && ratio > 0.0).then(|| ratio.log2())
}

/// As [`solve`], keeping the finest level's solved half plate (mesh, supports, loads and
/// displacements) for a field or curve output: nothing is solved twice, and nothing is kept
/// when [`solve`] is called instead.
pub fn solve_with_field(
    plate: &SinglePlate,
    params: &SingleParams,
) -> Result<(SingleSolution, HalfPlate), FemError> {
    check_tolerance(params.tolerance)?;
    let (s, h) = study(plate, params, Some(params.tolerance), true, None)?;
    let h = h.ok_or(FemError::Solver("no refinement level was solved".into()))?;
    Ok((s, h))
}

/// R_o of `plate` on `params.levels` refinement levels, with the error estimate of
/// [`level_estimate`] (no extrapolation).
pub fn single_plate_r_o(
    plate: &SinglePlate,
    params: &SingleParams,
) -> Result<(f64, SingleInfo), FemError> {
    let (s, _) = study(plate, params, None, false, None)?;
    Ok((s.r_o, s.info))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn auto_refinement_is_graded_for_q9_only() {
        assert_eq!(
            Refinement::Auto.for_element(ElementKind::Q9),
            Refinement::Graded
        );
        for k in [ElementKind::Q4, ElementKind::Q4Bbar, ElementKind::Cst4] {
            assert_eq!(Refinement::Auto.for_element(k), Refinement::Uniform);
            assert_eq!(Refinement::Graded.for_element(k), Refinement::Graded);
        }
    }
}
