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
//! Error estimate: the mesh is refined by halving every element `levels` times (nested meshes);
//! with R_l on level l, the observed order p = log₂((R_{L−3} − R_{L−2})/(R_{L−2} − R_{L−1})) and
//! the Richardson value R = R_{L−1} + (R_{L−1} − R_{L−2})/(2^p − 1) are returned; the error
//! estimate is |R − R_{L−1}| (the finest mesh's own error, an upper bound for the
//! extrapolated value's when the rate is stable). If the observed p is not in [1, 8], no
//! extrapolation is made and the estimate is |R_{L−1} − R_{L−2}|.
//!
//! An infinite plate is truncated at C = B + 30 D (the midplane stress decays like e^(−r/D)·…;
//! beyond a few D the rim is invisible to R_o at the 10⁻⁶ level).
//!
//! Units: any consistent set; R_o in the length unit of A, B, D. Sign: compression negative.
//!
//! ```
//! use boltzone::fem::single::{single_plate_r_o, Loading, SingleParams};
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.22, 1.0).unwrap();
//! let plate = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1,
//!                              Material::unit(0.3).unwrap(), load).unwrap();
//! let (r_o, info) = single_plate_r_o(&plate, &SingleParams::default()).unwrap();
//! assert!((r_o / 0.1 - 3.3).abs() < 0.2); // Table 1 (A/D = 1, B/A = 2.2): 3.3 ± its 0.15 grid
//! assert_eq!(info.levels.len(), 4);
//! let nut = SingleParams { loading: Loading::UniformDisplacement, ..SingleParams::default() };
//! assert!(single_plate_r_o(&plate, &nut).unwrap().0 > r_o); // a rigid nut reaches further
//! ```

use super::assemble::{assemble, Pattern};
use super::dofs::{Component, DofMap, Supports};
use super::element::ElementKind;
use super::loads::Loads;
use super::mesh::{Mesh, PlateSpec};
use super::ordering::nested_dissection;
use super::recover::{line_traction, reactions};
use super::solve::{Factorization, SolveParams};
use super::spacing::Spacing;
use super::FemError;
use crate::error::InputError;
use crate::joint::{OuterRadius, SinglePlate};
use std::time::Instant;

/// How the bolt head (and nut) load the faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Loading {
    /// The face pressure p(r) of the plate's [`crate::FaceLoad`] (Table 1).
    #[default]
    Pressure,
    /// A rigid, frictionless nut: a uniform axial displacement of the face over the load's
    /// annulus (report Fig. 21), radial motion free; R_o does not depend on its magnitude.
    UniformDisplacement,
}

/// Parameters of the single-plate R_o study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SingleParams {
    /// Face pressure or rigid-nut displacement (default pressure).
    pub loading: Loading,
    /// Element kind (default Q9).
    pub kind: ElementKind,
    /// Coarsest element size at the hole and load edges, as a fraction of D (default 0.5).
    pub coarse_size: f64,
    /// Growth ratio of element sizes away from A and B (default 1.15).
    pub growth: f64,
    /// Number of nested refinement levels, ≥ 3 for the Richardson estimate (default 4).
    pub levels: usize,
    /// Sparse solver parameters.
    pub solve: SolveParams,
}

impl Default for SingleParams {
    fn default() -> Self {
        Self {
            loading: Loading::Pressure,
            kind: ElementKind::Q9,
            coarse_size: 0.5,
            growth: 1.15,
            levels: 4,
            solve: SolveParams::default(),
        }
    }
}

/// What the R_o study did.
#[derive(Debug, Clone, PartialEq)]
pub struct SingleInfo {
    /// R_o on each level, coarse to fine.
    pub levels: Vec<f64>,
    /// Observed convergence order (None if it could not be measured).
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
pub struct Midplane {
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

/// The radial spacing used on the coarsest level for `plate` (knots at the load's knots).
pub fn coarse_radial_spacing(
    plate: &SinglePlate,
    params: &SingleParams,
) -> Result<Spacing, InputError> {
    let d = plate.half_thickness();
    let (a, b) = (plate.hole_radius(), plate.load().outer());
    let c = match plate.outer_radius() {
        OuterRadius::Infinite => b + 30.0 * d,
        OuterRadius::Finite(c) => c,
    };
    let h = params.coarse_size * d;
    let foci = [a, plate.load().inner(), b];
    Spacing::graded(a, c, plate.load().knots(), &foci, h, params.growth, 4.0 * d)
}

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
}

/// Solves the upper half plate on the mesh `radial` × `axial` (0 ≤ z ≤ D).
pub fn solve_half_plate(
    plate: &SinglePlate,
    loading: Loading,
    kind: ElementKind,
    radial: &Spacing,
    axial: &Spacing,
    solve: &SolveParams,
) -> Result<HalfPlate, FemError> {
    let mesh = Mesh::structured(
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
        Loading::Pressure => loads.add_face_pressure(&mesh, &mesh.top(0), 1.0, plate.load())?,
        Loading::UniformDisplacement => {
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
    let dofs = DofMap::new(&s);
    let k = assemble(
        &mesh,
        &[plate.material()],
        &dofs,
        &Pattern::new(&mesh, &dofs),
    )?;
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
    })
}

/// Solves the half plate on the mesh `radial` × `nz` uniform axial elements and recovers the
/// midplane σ_z from the roller reactions.
pub fn solve_midplane(
    plate: &SinglePlate,
    loading: Loading,
    kind: ElementKind,
    radial: &Spacing,
    nz: usize,
    solve: &SolveParams,
) -> Result<Midplane, FemError> {
    let z = Spacing::uniform(0.0, plate.half_thickness(), nz)?;
    let h = solve_half_plate(plate, loading, kind, radial, &z, solve)?;
    let mid = h.mesh.bottom(0);
    let reac = reactions(&h.mesh, &[plate.material()], &h.u, &h.loads)?;
    let rz: Vec<f64> = mid.iter().map(|&n| reac[n][1]).collect();
    let t = line_traction(&h.mesh, &mid, &rz)?;
    Ok(Midplane {
        r: mid.iter().map(|&n| h.mesh.nodes()[n][0]).collect(),
        sigma_z: t.iter().map(|t| -t).collect(),
        order: kind.order(),
        nodes: h.mesh.n_nodes(),
        dofs: h.dofs.n_equations(),
    })
}

impl Midplane {
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

/// The crossings of nested meshes, level l with every element of the coarse mesh split 2^l
/// times each way: an endless iterator, so callers choose how many levels and when to stop
/// ([`single_plate_r_o`] takes `params.levels` and extrapolates; the comparison module stops at
/// a tolerance).
pub struct CrossingLevels<'a> {
    plate: &'a SinglePlate,
    params: &'a SingleParams,
    coarse: Spacing,
    nz0: usize,
    level: u32,
}

/// Nested refinement levels of the single-plate model (see [`CrossingLevels`]).
pub fn crossing_levels<'a>(
    plate: &'a SinglePlate,
    params: &'a SingleParams,
) -> Result<CrossingLevels<'a>, FemError> {
    crate::error::positive("coarse element size", params.coarse_size)?;
    Ok(CrossingLevels {
        plate,
        params,
        coarse: coarse_radial_spacing(plate, params)?,
        nz0: (1.0 / params.coarse_size).ceil().max(1.0) as usize,
        level: 0,
    })
}

impl Iterator for CrossingLevels<'_> {
    type Item = Result<LevelCrossing, FemError>;

    fn next(&mut self) -> Option<Self::Item> {
        let k = 1usize << self.level;
        self.level += 1;
        let p = self.params;
        let solved = solve_midplane(
            self.plate,
            p.loading,
            p.kind,
            &self.coarse.refined(k),
            self.nz0 * k,
            &p.solve,
        );
        Some(solved.and_then(|m| {
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
        }))
    }
}

/// R_o of `plate` with a Richardson error estimate over nested refinements.
pub fn single_plate_r_o(
    plate: &SinglePlate,
    params: &SingleParams,
) -> Result<(f64, SingleInfo), FemError> {
    if params.levels < 2 || params.levels > 12 {
        return Err(InputError::Parameter {
            field: "refinement levels",
            value: params.levels as f64,
            reason: "must lie in 2..=12",
        }
        .into());
    }
    let t0 = Instant::now();
    let mut values = Vec::new();
    let (mut nodes, mut dofs) = (0, 0);
    for level in crossing_levels(plate, params)?.take(params.levels) {
        let level = level?;
        values.push(level.r_o);
        (nodes, dofs) = (level.nodes, level.dofs);
    }
    let (r_o, order, err) = richardson(&values);
    Ok((
        r_o,
        SingleInfo {
            levels: values,
            observed_order: order,
            error_estimate: err,
            nodes,
            dofs,
            seconds: t0.elapsed().as_secs_f64(),
        },
    ))
}

/// Richardson extrapolation of a sequence on meshes halved each time: (value, order, error).
pub fn richardson(v: &[f64]) -> (f64, Option<f64>, f64) {
    let n = v.len();
    let last = v[n - 1];
    if n < 3 {
        return (
            last,
            None,
            if n == 2 {
                (v[1] - v[0]).abs()
            } else {
                f64::INFINITY
            },
        );
    }
    let (d1, d2) = (v[n - 2] - v[n - 3], last - v[n - 2]);
    let p = (d1 / d2).abs().log2();
    if d1 * d2 > 0.0 && (1.0..=8.0).contains(&p) {
        let extra = last + d2 / (2f64.powf(p) - 1.0);
        (extra, Some(p), (extra - last).abs())
    } else {
        (last, p.is_finite().then_some(p), d2.abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mid(r: Vec<f64>, s: Vec<f64>, order: usize) -> Midplane {
        Midplane {
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
    fn richardson_recovers_a_known_limit() {
        // v_l = 1 + 0.3·2^(−3l): order 3, limit 1
        let v: Vec<f64> = (0..4).map(|l| 1.0 + 0.3 * 2f64.powi(-3 * l)).collect();
        let (x, p, e) = richardson(&v);
        assert!((x - 1.0).abs() < 1e-14 && (p.unwrap() - 3.0).abs() < 1e-12);
        assert!((e - 0.3 * 2f64.powi(-9)).abs() < 1e-14);
        // oscillating sequence: no extrapolation, the last difference as the estimate
        let (x, _, e) = richardson(&[1.0, 1.1, 1.05]);
        assert_eq!(x, 1.05);
        assert!((e - 0.05).abs() < 1e-15);
    }
}
