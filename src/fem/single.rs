//! The single-plate model by finite elements (Fernlund's substitution, report Chapter II.A and
//! Table 1's "single plate" column): a plate 2D thick with a hole of radius A (A = 0: none), outer
//! radius C, both faces pressed by p(r) over A..B. By symmetry only the upper half 0 ≤ z ≤ D is
//! meshed, with a roller on the midplane (w = 0, u free, τ_rz = 0), a free hole and a free rim.
//!
//! R_o is the smallest radius beyond the load (r ≥ B) where the midplane σ_z turns tensile.
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
use super::ordering::nested_dissection;
use super::recover::{line_traction, reactions};
use super::single_temperature::SingleTemperature;
use super::solve::{Factorization, SolveParams};
use super::spacing::{level_grading_below, Spacing, GRADING_FIXED_DOWN_TO};
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

/// The midplane of one solved single-plate mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct MidplaneNodes {
    /// Radii of the midplane nodes.
    pub r: Vec<f64>,
    /// σ_z at those nodes (compression negative).
    pub sigma_z: Vec<f64>,
    /// Edge order (1 or 2) for interpolation.
    pub order: usize,
    /// Number of nodes of the mesh.
    pub nodes: usize,
    /// Number of equations.
    pub dofs: usize,
}

/// The radial spacing of level 0 for `plate` (knots at the load's knots): the radial part of
/// [`level_spacings`] at level 0.
pub fn coarse_radial_spacing(
    plate: &SinglePlate,
    params: &SingleParams,
) -> Result<Spacing, InputError> {
    Ok(level_spacings(plate, params, 0, None)?.0)
}

/// The radial and axial spacings of refinement level `level` (module docs). Graded: element
/// size `coarse_size`·D/2^level at A, the load's knots, B and `r_focus` (the previous level's
/// R_o), growing by `growth` radially up to 4D and by `axial_growth` away from z = 0 and z = D
/// up to D/2. Uniform: level 0's spacings (without `r_focus`) with every element split into
/// 2^level. An infinite plate ends at C = B + 30D.
pub fn level_spacings(
    plate: &SinglePlate,
    params: &SingleParams,
    level: u32,
    r_focus: Option<f64>,
) -> Result<(Spacing, Spacing), InputError> {
    crate::error::positive("coarse element size", params.coarse_size)?;
    let refinement = params.refinement.for_element(params.kind);
    if refinement == Refinement::Uniform && level > 0 {
        let (r, z) = level_spacings(plate, params, 0, None)?;
        let k = 1usize << level.min(20);
        return Ok((r.refined(k), z.refined(k)));
    }
    let d = plate.half_thickness();
    let (a, b) = (plate.hole_radius(), plate.load().outer());
    let c = match plate.outer_radius() {
        OuterRadius::Infinite => b + FAR_RIM * d,
        OuterRadius::Finite(c) => c.min(b + FAR_RIM * d),
    };
    let h = params.coarse_size * d / 2f64.powi(level as i32);
    let mut foci = vec![a, plate.load().inner(), b];
    foci.extend(r_focus.filter(|&r| r > a && r < c));
    // the growth ratios, and the largest axial size, shrink on the finest levels
    // ([`level_grading`]) so that every part of the mesh is refined
    let fixed = if params.tolerance < FIXED_GRADING_TOLERANCE {
        FIXED_GRADING_TIGHT
    } else {
        GRADING_FIXED_DOWN_TO
    };
    let (growth, axial_growth, shrink) =
        level_grading_below(h, d, params.growth, params.axial_growth, fixed);
    let radial = Spacing::graded(a, c, plate.load().knots(), &foci, h, growth, 4.0 * d)?;
    let axial = match refinement {
        Refinement::Graded | Refinement::Auto => Spacing::graded(
            0.0,
            d,
            &[],
            &[0.0, d],
            h,
            axial_growth,
            (0.5 * d * shrink).max(h),
        )?,
        Refinement::Uniform => {
            Spacing::uniform(0.0, d, (1.0 / params.coarse_size).ceil() as usize)?
        }
    };
    Ok((radial, axial))
}

pub use crate::joint::FAR_RIM;

/// Most levels [`solve`] refines to meet a tolerance for its callers that do not choose
/// (`single --levels`' default, the tables, scenes and figures): the finest has 2⁻⁷ of the
/// first's element size at the foci. [`SingleParams::default`]'s 5 are the fixed study of
/// [`single_plate_r_o`].
pub const MAX_LEVELS: usize = 8;

/// The tightest `tolerance` whose levels keep the fixed grading down to h = D/64
/// ([`crate::fem::spacing::level_grading`]); tighter ones shrink it from h = D/8 on
/// ([`FIXED_GRADING_TIGHT`]). The fixed grading leaves a floor of 1.2e-6 to 2.4e-6 of R_o that
/// the level-to-level changes do not show: example 16 at `tolerance` 1e-5 found 15 of 355
/// converged runs over their estimate (up to 1.71×, most stopping at level 5, the last fixed
/// one); at 1e-4 none (at most 0.84 of it).
pub const FIXED_GRADING_TOLERANCE: f64 = 1e-4;

/// The shrink of the error estimate per level beyond which [`solve`] decides that a tolerance
/// is out of reach and stops, not converged: twice the fastest seen (38×, from level 3 to 4;
/// 2–15× elsewhere, on 15 geometries of example 16 over 8 levels with either grading), so that
/// no reachable tolerance is given up. `table1 --tol 1e-320` solved every level of the finer
/// tight-tolerance grading: 9.7 s and 266 MB, over the fuzz's 30 s under load.
pub const FASTEST_ESTIMATE_RATE: f64 = 76.0;

/// Element size, in D, below which a study tighter than [`FIXED_GRADING_TOLERANCE`] shrinks
/// its grading: from level 3 on (h = D/16 with the default `coarse_size`).
pub const FIXED_GRADING_TIGHT: f64 = 1.0 / 8.0;

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
    let dofs = DofMap::new(&s);
    let k = assemble(&mesh, &materials, &dofs, &Pattern::new(&mesh, &dofs))?;
    let mut rhs = dofs.gather(loads.forces());
    for (a, b) in rhs.iter_mut().zip(&k.prescribed_load) {
        *a += b;
    }
    let order = nested_dissection(&mesh, &dofs);
    let x = Factorization::with_ordering(&k.matrix, Some(&order), solve)?.solve(&rhs);
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

/// The midplane σ_z of a solved half plate, recovered from the roller reactions.
pub fn midplane_of(_plate: &SinglePlate, h: &HalfPlate) -> Result<MidplaneNodes, FemError> {
    let kind = h.mesh.kind();
    let mid = h.mesh.bottom(0);
    let reac = reactions(&h.mesh, &h.materials, &h.u, &h.loads)?;
    let rz: Vec<f64> = mid.iter().map(|&n| reac[n][1]).collect();
    let t = line_traction(&h.mesh, &mid, &rz)?;
    Ok(MidplaneNodes {
        r: mid.iter().map(|&n| h.mesh.nodes()[n][0]).collect(),
        sigma_z: t.iter().map(|t| -t).collect(),
        order: kind.order(),
        nodes: h.mesh.n_nodes(),
        dofs: h.dofs.n_equations(),
    })
}

impl MidplaneNodes {
    /// The first radius ≥ `from` where σ_z goes from ≤ 0 to > 0, interpolated within the element
    /// edge (linear or quadratic); None if σ_z never turns tensile.
    pub fn first_tensile_crossing(&self, from: f64) -> Option<f64> {
        let o = self.order;
        let start = self
            .r
            .partition_point(|&r| r < from - 1e-12 * (1.0 + from.abs()));
        let mut i = start - start % o; // the edge that contains `from`
        if self.sigma_z.get(i).is_some_and(|&s| s > 0.0) {
            return Some(self.r[i]); // already tensile where the search starts
        }
        while i + o < self.r.len() {
            let (s0, s1) = (self.sigma_z[i], self.sigma_z[i + o]);
            let mid = self.sigma_z[i + o / 2];
            if s1 > 0.0 || mid > 0.0 {
                return Some(if o == 1 {
                    self.r[i] + (self.r[i + 1] - self.r[i]) * (-s0) / (s1 - s0)
                } else {
                    quadratic_root(self.r[i], self.r[i + 2], s0, mid, s1)
                });
            }
            i += o;
        }
        None
    }
}

/// The smallest root in [x0, x2] of the quadratic through (x0, f0), (mid, fm), (x2, f2), f0 ≤ 0.
fn quadratic_root(x0: f64, x2: f64, f0: f64, fm: f64, f2: f64) -> f64 {
    // in s ∈ [0, 1]: f = f0 + b s + a s², with f(1/2) = fm, f(1) = f2
    let a = 2.0 * (f2 - 2.0 * fm + f0);
    let b = f2 - f0 - a;
    let s = if a.abs() < 1e-14 * (f0.abs() + fm.abs() + f2.abs()) {
        -f0 / b
    } else {
        let disc = (b * b - 4.0 * a * f0).max(0.0).sqrt();
        // numerically stable roots; pick the smallest one in [0, 1]
        let q = -0.5 * (b + b.signum() * disc);
        let mut roots = [q / a, f0 / q];
        roots.sort_by(f64::total_cmp);
        roots
            .into_iter()
            .find(|s| (-1e-12..=1.0 + 1e-12).contains(s))
            .unwrap_or(0.5)
    };
    x0 + s.clamp(0.0, 1.0) * (x2 - x0)
}

/// The discrete crossing R_o of one mesh level, and that mesh's size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelCrossing {
    /// First upward zero of the recovered midplane σ_z beyond B on this mesh.
    pub r_o: f64,
    /// Nodes of the mesh.
    pub nodes: usize,
    /// Equations of the mesh.
    pub dofs: usize,
}

/// The crossings of the refinement levels of the module docs (level l: element size
/// `coarse_size`·D/2^l at the foci, graded toward the previous level's R_o): an endless
/// iterator, so callers choose how many levels and when to stop ([`single_plate_r_o`] takes
/// `params.levels`; the comparison module stops at a tolerance).
pub struct CrossingLevels<'a> {
    plate: &'a SinglePlate,
    params: &'a SingleParams,
    previous: Option<f64>,
    level: u32,
    /// Keep each level's solved half plate (for a field or curve output).
    keep: bool,
    last: Option<HalfPlate>,
    temperature: Option<&'a SingleTemperature>,
}

/// Refinement levels of the single-plate model (see [`CrossingLevels`]).
pub fn crossing_levels<'a>(
    plate: &'a SinglePlate,
    params: &'a SingleParams,
) -> Result<CrossingLevels<'a>, FemError> {
    level_spacings(plate, params, 0, None)?; // checks the parameters once
    Ok(CrossingLevels {
        plate,
        params,
        previous: None,
        level: 0,
        keep: false,
        last: None,
        temperature: None,
    })
}

impl Iterator for CrossingLevels<'_> {
    type Item = Result<LevelCrossing, FemError>;

    fn next(&mut self) -> Option<Self::Item> {
        let p = self.params;
        let solved = level_spacings(self.plate, p, self.level, self.previous)
            .map_err(FemError::from)
            .and_then(|(radial, axial)| {
                solve_half_plate_with(self.plate, p, &radial, &axial, self.temperature)
            })
            .and_then(|h| {
                let m = midplane_of(self.plate, &h);
                if self.keep {
                    self.last = Some(h);
                }
                m
            });
        self.level += 1;
        let level = solved.and_then(|m| {
            let r_o =
                m.first_tensile_crossing(self.plate.load().outer())
                    .ok_or(FemError::Solver(
                        "the midplane stress never turns tensile inside the plate".into(),
                    ))?;
            Ok(LevelCrossing {
                r_o,
                nodes: m.nodes,
                dofs: m.dofs,
            })
        });
        self.previous = level.as_ref().ok().map(|l| l.r_o);
        Some(level)
    }
}

/// R_o of the single plate refined to a tolerance: the result of [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct SingleSolution {
    /// Separation radius R_o (the last level's crossing, not extrapolated).
    pub r_o: f64,
    /// Its estimated absolute error ([`level_estimate`]).
    pub r_o_error: f64,
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
    let (mut nodes, mut dofs) = (0, 0);
    let mut levels = crossing_levels(plate, params)?;
    levels.keep = keep;
    levels.temperature = temperature;
    for level in levels.by_ref().take(params.levels) {
        let level = level?;
        values.push(level.r_o);
        (nodes, dofs) = (level.nodes, level.dofs);
        let met = |(_, e): (f64, f64)| tolerance.is_some_and(|t| meets(level.r_o, e, t));
        // out of reach: even shrinking FASTEST_ESTIMATE_RATE× per level, the levels left
        // cannot bring the estimate to the tolerance; stop (not converged)
        let left = params.levels.saturating_sub(values.len()) as i32;
        let hopeless = |(r, e): (f64, f64)| {
            tolerance.is_some_and(|t| e > t * r.abs() * FASTEST_ESTIMATE_RATE.powi(left))
        };
        if level_estimate(&values).is_some_and(|v| met(v) || hopeless(v)) {
            break;
        }
    }
    let (r_o, r_o_error) = level_estimate(&values).ok_or(FemError::Solver(
        "fewer than three refinement levels were solved".into(),
    ))?;
    let solution = SingleSolution {
        r_o,
        r_o_error,
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

    fn mid(r: Vec<f64>, s: Vec<f64>, order: usize) -> MidplaneNodes {
        MidplaneNodes {
            r,
            sigma_z: s,
            order,
            nodes: 0,
            dofs: 0,
        }
    }

    #[test]
    fn crossing_is_interpolated_inside_the_edge() {
        // σ = (r − 0.7)(r + 1): quadratic interpolation is exact, linear gives the chord's root
        let r: Vec<f64> = (0..=10).map(|i| i as f64 * 0.1).collect();
        let s: Vec<f64> = r.iter().map(|r| (r - 0.7) * (r + 1.0)).collect();
        let q = mid(r.clone(), s.clone(), 2)
            .first_tensile_crossing(0.2)
            .unwrap();
        assert!((q - 0.7).abs() < 1e-14, "{q}");
        let l = mid(r, s, 1).first_tensile_crossing(0.2).unwrap();
        assert!((l - 0.7).abs() < 1e-12, "{l}"); // 0.7 is a node: linear is exact there too
                                                 // a crossing below `from` is ignored; never tensile: None
        let r: Vec<f64> = (0..=4).map(|i| i as f64).collect();
        let m = mid(r.clone(), vec![1.0, -1.0, -2.0, 1.0, 2.0], 1);
        assert!((m.first_tensile_crossing(1.0).unwrap() - (2.0 + 2.0 / 3.0)).abs() < 1e-14);
        assert_eq!(mid(r, vec![-1.0; 5], 1).first_tensile_crossing(0.0), None);
    }

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
