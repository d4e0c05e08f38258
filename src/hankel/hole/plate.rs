//! The single plate with a hole: extended-load slab + fitted Lamé and Papkovich–Fadle modes,
//! its fields at any (r, z), r ≥ A, and its midplane σ_z.
//!
//! **Extension of the load.** A load that starts at the hole edge with p(A) ≠ 0 gives the slab a
//! logarithmically singular σ_r at the corner (A, ±D), which no smooth correction can cancel
//! quickly. The fictitious slab (no hole) is therefore loaded by p(r) continued into the hole:
//! linearly with the first segment's slope on [max(0, A − D), A], then constantly down to r = 0.
//! The continuation is continuous at A, so the slab field is smooth at the corner; in r ≥ A it
//! differs from the unextended slab by the field of a load on r < A, itself a homogeneous
//! solution there (faces free for r > A). This is the "face-pressure extension" half of the
//! correction; the other half is the fitted modes of [`super::fit`].
//!
//! ```
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! use boltzone::hankel::hole::{HoleParams, HolePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0).unwrap();
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3).unwrap(), load).unwrap();
//! let holed = HolePlate::new(&plate, &HoleParams::default()).unwrap();
//! assert!(holed.info().residual_max <= 1e-6);
//! ```

use super::eigen::{lame_field, symmetric_roots, Mode, ModeField};
use super::fit::{fit, heights, Fit, HoleData};
use super::{HoleInfo, HoleLevel, HoleParams};
use crate::error::InputError;
use crate::hankel::field::{Slab, Stress};
use crate::hankel::quadrature::QuadParams;
use crate::joint::SinglePlate;
use crate::load::FaceLoad;
use std::time::Instant;

/// The load continued into the hole (see the module docs); `None` when A = 0.
pub fn extended_load(load: &FaceLoad, a: f64, d: f64) -> Result<Option<FaceLoad>, InputError> {
    if a <= 0.0 {
        return Ok(None);
    }
    let first = load.segments().next().expect("a load has a segment");
    let slope = (first.p1 - first.p0) / (first.r1 - first.r0);
    if load.inner() > a {
        // The load starts beyond the hole edge: the slab is smooth at the corner already.
        return Ok(Some(load.clone()));
    }
    let pa = first.p0;
    if slope == 0.0 && load.knots().len() == 2 {
        return FaceLoad::uniform(0.0, load.outer(), pa).map(Some);
    }
    let s0 = (a - d).max(0.0);
    let p0 = pa - slope * (a - s0);
    let (mut r, mut p) = (Vec::new(), Vec::new());
    if s0 > 0.0 {
        r.push(0.0);
        p.push(p0);
    }
    r.extend([s0, a]);
    p.extend([p0, pa]);
    for (k, v) in load.knots().iter().zip(load.values()).skip(1) {
        r.push(*k);
        p.push(*v);
    }
    FaceLoad::tabulated(&r, &p).map(Some)
}

/// The single plate with a hole, solved by the Hankel route with the hole correction.
#[derive(Debug, Clone)]
pub struct HolePlate {
    a: f64,
    slab: Slab,
    roots: Vec<num_complex::Complex64>,
    modes: Vec<Mode>,
    fit: Option<Fit>,
    /// Slab hole traction on the heights of 4N intervals (collocation + check points).
    grid: Vec<HoleData>,
    quad: QuadParams,
    nu: f64,
    g: f64,
    p_ref: f64,
    max_terms: usize,
    info: HoleInfo,
}

impl HolePlate {
    /// Solves the hole correction of `plate` (its outer radius is taken as infinite): N from
    /// `params.terms`, or doubled from `params.start_terms` until the residual target is met or
    /// `params.max_terms` is reached.
    pub fn new(plate: &SinglePlate, params: &HoleParams) -> Result<Self, InputError> {
        let mut holed =
            Self::with_terms(plate, params, params.terms.unwrap_or(params.start_terms))?;
        if params.terms.is_none() {
            while holed.info.residual_max > params.residual_target && holed.refine() {}
        }
        Ok(holed)
    }

    /// The correction with exactly `n` modes (no doubling).
    pub fn with_terms(
        plate: &SinglePlate,
        params: &HoleParams,
        n: usize,
    ) -> Result<Self, InputError> {
        let start = Instant::now();
        params.check()?;
        let (a, d) = (plate.hole_radius(), plate.half_thickness());
        let mat = plate.material();
        let p_ref = plate.load().mean_pressure().abs();
        let ext = extended_load(plate.load(), a, d)?;
        let slab = Slab::new(d, mat, ext.unwrap_or_else(|| plate.load().clone()))?;
        let mut holed = Self {
            a,
            slab,
            roots: Vec::new(),
            modes: Vec::new(),
            fit: None,
            grid: Vec::new(),
            quad: QuadParams {
                rel_tol: 1e-14,
                abs_tol: params.slab_tolerance * p_ref,
                ..QuadParams::default()
            },
            nu: mat.poisson_ratio(),
            g: mat.shear_modulus(),
            p_ref,
            max_terms: params.terms.unwrap_or(params.max_terms).max(n),
            info: HoleInfo::default(),
        };
        if a > 0.0 {
            holed.solve(n);
        }
        holed.info.seconds = start.elapsed().as_secs_f64();
        Ok(holed)
    }

    /// Doubles N, reusing every slab evaluation; false (and nothing done) when 2N would exceed
    /// the largest N allowed or there is no hole.
    pub fn refine(&mut self) -> bool {
        let n = 2 * self.info.terms;
        if self.a <= 0.0 || n > self.max_terms {
            return false;
        }
        let start = Instant::now();
        self.solve(n);
        self.info.seconds += start.elapsed().as_secs_f64();
        true
    }

    /// Fits N = `n` modes: samples the slab on the new heights, solves, measures the residual.
    fn solve(&mut self, n: usize) {
        let d = self.slab.half_thickness();
        let z = heights(d, 4 * n);
        let nested = !self.grid.is_empty() && self.grid.len() * 2 - 1 == z.len();
        let mut old = std::mem::take(&mut self.grid).into_iter();
        let mut grid = Vec::with_capacity(z.len());
        for (j, &zj) in z.iter().enumerate() {
            match (nested && j % 2 == 0).then(|| old.next()).flatten() {
                Some(p) => grid.push(p),
                None => {
                    let s = self.slab.stress(self.a, zj, &self.quad);
                    self.info.slab_evaluations += s.sigma_r.evaluations;
                    let err = s.sigma_r.error.hypot(s.tau_rz.error) / self.p_ref;
                    self.info.slab_error = self.info.slab_error.max(err);
                    grid.push(HoleData {
                        z: zj,
                        sigma_r: s.sigma_r.value,
                        tau_rz: s.tau_rz.value,
                    });
                }
            }
        }
        if self.roots.len() < n {
            self.roots = symmetric_roots(n);
        }
        let (a, nu, g) = (self.a, self.nu, self.g);
        self.modes = self.roots[..n]
            .iter()
            .map(|x| Mode::new(*x, a, d, nu, g))
            .collect();
        let colloc: Vec<HoleData> = grid.iter().step_by(2).copied().collect();
        let f = fit(&self.modes, &colloc);
        let (rmax, rrms) = f.residual(&self.modes, &grid);
        let level = HoleLevel {
            terms: n,
            collocation_points: colloc.len(),
            residual_max: rmax / self.p_ref,
            residual_rms: rrms / self.p_ref,
            condition: f.condition,
        };
        self.info.history.push(level);
        self.info.terms = n;
        self.info.collocation_points = level.collocation_points;
        self.info.check_points = grid.len();
        self.info.residual_max = level.residual_max;
        self.info.residual_rms = level.residual_rms;
        self.info.condition = level.condition;
        self.grid = grid;
        self.fit = Some(f);
    }

    /// The fit's sizes, residual and cost.
    pub fn info(&self) -> &HoleInfo {
        &self.info
    }

    /// The fictitious slab loaded by the extended load.
    pub fn slab(&self) -> &Slab {
        &self.slab
    }

    /// Hole radius A.
    pub fn hole_radius(&self) -> f64 {
        self.a
    }

    /// The fitted correction alone (Lamé + modes, without the slab) at (r, z), r ≥ A.
    pub fn correction(&self, r: f64, z: f64) -> ModeField<f64> {
        let Some(f) = &self.fit else {
            return ModeField::default();
        };
        let l = lame_field(self.a, self.g, r);
        let mut out = ModeField {
            sigma_r: f.lame * l.sigma_r,
            sigma_theta: f.lame * l.sigma_theta,
            sigma_z: 0.0,
            tau_rz: 0.0,
            u: f.lame * l.u,
            w: 0.0,
        };
        for (m, c) in self.modes.iter().zip(&f.modes) {
            let v = m.field(r, z);
            out.sigma_r += (c * v.sigma_r).re;
            out.sigma_theta += (c * v.sigma_theta).re;
            out.sigma_z += (c * v.sigma_z).re;
            out.tau_rz += (c * v.tau_rz).re;
            out.u += (c * v.u).re;
            out.w += (c * v.w).re;
        }
        out
    }

    /// The fitted correction's midplane σ_z(r, 0) (the Lamé field has none).
    pub fn correction_midplane(&self, r: f64) -> f64 {
        self.fit.as_ref().map_or(0.0, |f| {
            self.modes
                .iter()
                .zip(&f.modes)
                .map(|(m, c)| (c * m.midplane_sigma_z(r)).re)
                .sum()
        })
    }

    /// Stresses of the plate with the hole at (r, z), r ≥ A: slab (extended load) + correction.
    /// Error estimates are the slab quadrature's; the hole residual is in [`Self::info`].
    pub fn stress(&self, r: f64, z: f64, params: &QuadParams) -> Stress {
        let mut s = self.slab.stress(r, z, params);
        let c = self.correction(r, z);
        s.sigma_r.value += c.sigma_r;
        s.sigma_theta.value += c.sigma_theta;
        s.sigma_z.value += c.sigma_z;
        s.tau_rz.value += c.tau_rz;
        s
    }
}
