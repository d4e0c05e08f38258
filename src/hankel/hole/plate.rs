//! The single plate with a hole: extended-load slab + fitted Lamé and Papkovich–Fadle modes and
//! corner enrichment ([`super::corner`]), its fields at any (r, z), r ≥ A, and its midplane σ_z.
//!
//! **Extension of the load.** A load that starts at the hole edge with p(A) ≠ 0 gives the slab a
//! logarithmically singular σ_r at the corner (A, ±D), which no smooth correction can cancel
//! quickly. The fictitious slab (no hole) is therefore loaded by p(r) continued into the hole:
//! linearly with the first segment's slope on [max(0, A − D), A], then constantly down to r = 0.
//! The continuation is continuous at A, so the slab field is smooth at the corner; in r ≥ A it
//! differs from the unextended slab by the field of a load on r < A, itself a homogeneous
//! solution there (faces free for r > A). This is the "face-pressure extension" half of the
//! correction; the other half is the fitted modes and corner fields of [`super::fit`].
//!
//! # Accuracy
//!
//! The extended load continues the load into the hole; the midplane carries the applied force; a
//! rim is freed too and a far rim changes nothing (`tests/hankel/hole_correction.rs`).
//!
//! # Cost
//!
//! `cargo bench --bench hole`.
//!
//! ```
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! use boltzone::hankel::hole::{HoleParams, HolePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load)?;
//! let holed = HolePlate::new(&plate, &HoleParams { terms: Some(16), ..Default::default() })?;
//! let info = holed.info();
//! assert!(info.residual_max < 1e-4 && info.history.len() == 1);
//! // the hole is (nearly) free: σ_r(A, z) = slab + correction
//! let s = holed.stress(0.1, 0.05, &Default::default());
//! assert!(s.sigma_r.value.abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::corner::CornerLoads;
use super::eigen::{symmetric_roots, Mode};
use super::fit::{fit, heights, Boundary, Fit, HoleData};
use super::profile::TractionProfile;
use super::traction::hole_tractions;
use super::{HoleInfo, HoleLevel, HoleParams, SlabSampling};
use crate::error::InputError;
use crate::hankel::field::Slab;
use crate::joint::{OuterRadius, SinglePlate};
use crate::load::FaceLoad;
use crate::numerics::quadrature::QuadParams;
use num_complex::Complex64;
use std::collections::HashMap;
use std::time::Instant;

mod fields;

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
    /// Rim radius C (None: infinite plate).
    rim: Option<f64>,
    /// Slab traction on the hole (and the rim) at the heights of 4N intervals (collocation +
    /// check points).
    grid: Vec<HoleData>,
    rim_grid: Vec<HoleData>,
    /// How the slab traction is sampled, and the interpolants of [`SlabSampling::Profile`]
    /// (hole, rim), built on first use.
    sampling: SlabSampling,
    profiles: Vec<(f64, TractionProfile)>,
    /// Target of the slab traction's error (absolute).
    slab_tolerance: f64,
    quad: QuadParams,
    nu: f64,
    g: f64,
    p_ref: f64,
    max_terms: usize,
    info: HoleInfo,
    /// Corner exponents enriched ([`super::corner`]; 0: none).
    corner_terms: usize,
    corner: Option<CornerLoads>,
    /// The enrichment's traction columns on the hole (and the rim) by height (bits of z).
    corner_cache: HashMap<u64, Vec<f64>>,
    corner_rim_cache: HashMap<u64, Vec<f64>>,
    /// Fitted (pressure, shear) amplitudes per exponent.
    corner_amplitudes: Vec<[Complex64; 2]>,
    /// Radii up to which the enrichment's midplane σ_z uses its shared node set.
    corner_r_max: f64,
}

impl HolePlate {
    /// Solves the hole correction of `plate` (and frees its rim r = C if the outer radius is
    /// finite): N from `params.terms`, or doubled from `params.start_terms` until the residual
    /// target is met or `params.max_terms` is reached.
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
        // P (a zero load has nothing to correct: measure its residuals absolutely)
        let p_ref = Some(plate.load().mean_pressure().abs())
            .filter(|p| *p > 0.0)
            .unwrap_or(1.0);
        let ext = extended_load(plate.load(), a, d)?;
        let slab = Slab::new(d, mat, ext.unwrap_or_else(|| plate.load().clone()))?;
        let mut holed = Self {
            a,
            slab,
            roots: Vec::new(),
            modes: Vec::new(),
            fit: None,
            rim: match plate.outer_radius() {
                OuterRadius::Finite(c) if a > 0.0 => Some(c),
                _ => None,
            },
            grid: Vec::new(),
            rim_grid: Vec::new(),
            sampling: params.slab_sampling,
            profiles: Vec::new(),
            slab_tolerance: params.slab_tolerance * p_ref,
            quad: QuadParams {
                rel_tol: 1e-10,
                abs_tol: params.slab_tolerance * p_ref,
                window: 13,
                ..QuadParams::default()
            },
            nu: mat.poisson_ratio(),
            g: mat.shear_modulus(),
            p_ref,
            max_terms: params.terms.unwrap_or(params.max_terms).max(n),
            info: HoleInfo::default(),
            corner_terms: params.corner_terms,
            corner: None,
            corner_cache: HashMap::new(),
            corner_rim_cache: HashMap::new(),
            corner_amplitudes: Vec::new(),
            corner_r_max: 0.0,
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

    /// Slab traction at radius `r` on the heights `z` of 4N intervals. With
    /// [`SlabSampling::Profile`] (default) the values come from the Chebyshev interpolant of the
    /// cylinder r, sampled once on first use ([`TractionProfile`]); with
    /// [`SlabSampling::Direct`] every height is integrated, reusing `old` (the grid of 2N
    /// intervals) when nested.
    fn sample(&mut self, r: f64, old: Vec<HoleData>, z: &[f64]) -> Vec<HoleData> {
        if self.sampling == SlabSampling::Profile {
            let i = match self.profiles.iter().position(|(rp, _)| *rp == r) {
                Some(i) => i,
                None => {
                    let p = TractionProfile::new(&self.slab, r, self.slab_tolerance, &self.quad);
                    self.info.slab_evaluations += p.evaluations();
                    self.info.slab_error = self.info.slab_error.max(p.error() / self.p_ref);
                    self.profiles.push((r, p));
                    self.profiles.len() - 1
                }
            };
            let p = &self.profiles[i].1;
            return z
                .iter()
                .map(|&z| {
                    let (sigma_r, tau_rz) = p.eval(z);
                    HoleData { z, sigma_r, tau_rz }
                })
                .collect();
        }
        let nested = !old.is_empty() && old.len() * 2 - 1 == z.len();
        // heights not sampled yet: all, or the odd-numbered ones of a nested refinement
        let fresh: Vec<f64> = z
            .iter()
            .enumerate()
            .filter(|(j, _)| !nested || j % 2 == 1)
            .map(|(_, &zj)| zj)
            .collect();
        let (values, evaluations) = hole_tractions(&self.slab, r, &fresh, &self.quad);
        self.info.slab_evaluations += evaluations;
        for v in &values {
            self.info.slab_error = self.info.slab_error.max(v.error / self.p_ref);
        }
        let mut old = old.into_iter();
        let mut new = fresh.iter().zip(&values);
        (0..z.len())
            .map(|j| {
                if nested && j % 2 == 0 {
                    old.next().expect("nested grid")
                } else {
                    let (&z, v) = new.next().expect("one value per fresh height");
                    HoleData {
                        z,
                        sigma_r: v.sigma_r,
                        tau_rz: v.tau_rz,
                    }
                }
            })
            .collect()
    }

    /// Fits N = `n` modes: samples the slab on the new heights, solves, measures the residual.
    fn solve(&mut self, n: usize) {
        let d = self.slab.half_thickness();
        // 2N + 1 collocation heights (between them the check heights) for modes only; with the
        // corner enrichment 4N + 1, so that its 4 columns per exponent keep the system ~2× overdetermined
        let per_mode = if self.corner_terms > 0 { 8 } else { 4 };
        let z = heights(d, per_mode * n);
        let old = std::mem::take(&mut self.grid);
        self.grid = self.sample(self.a, old, &z);
        if let Some(c) = self.rim {
            let old = std::mem::take(&mut self.rim_grid);
            self.rim_grid = self.sample(c, old, &z);
        }
        if self.roots.len() < n {
            self.roots = symmetric_roots(n);
        }
        let (a, nu, g) = (self.a, self.nu, self.g);
        self.modes = self.roots[..n]
            .iter()
            .map(|x| Mode::new(*x, a, d, nu, g))
            .collect();
        if let Some(c) = self.rim {
            let growing = self.roots[..n]
                .iter()
                .map(|x| Mode::growing(*x, c, d, nu, g));
            self.modes.extend(growing);
        }
        if self.corner.is_none() && self.corner_terms > 0 {
            self.corner = Some(CornerLoads::new(a, d, nu, g, self.corner_terms));
        }
        let columns = 4 * self.corner.as_ref().map_or(0, |c| c.count());
        let hole_extra = self.corner_columns(a, &z, false);
        let rim_extra = self
            .rim
            .map_or_else(Vec::new, |c| self.corner_columns(c, &z, true));
        // collocation heights: every other one of the grid
        let every_other = |v: &[f64]| -> Vec<f64> {
            v.chunks(2 * columns.max(1))
                .step_by(2)
                .flatten()
                .copied()
                .collect()
        };
        let (hole_colloc_extra, rim_colloc_extra) =
            (every_other(&hole_extra), every_other(&rim_extra));
        let colloc: Vec<HoleData> = self.grid.iter().step_by(2).copied().collect();
        let rim_colloc: Vec<HoleData> = self.rim_grid.iter().step_by(2).copied().collect();
        let mut bounds = vec![Boundary {
            r: a,
            data: &colloc,
            extra: &hole_colloc_extra,
        }];
        if let Some(c) = self.rim {
            bounds.push(Boundary {
                r: c,
                data: &rim_colloc,
                extra: &rim_colloc_extra,
            });
        }
        let f = fit(&self.modes, a, self.rim.is_some(), columns, &bounds);
        let (rmax, rrms) = f.residual(
            &self.modes,
            &Boundary {
                r: a,
                data: &self.grid,
                extra: &hole_extra,
            },
        );
        let rim_residual = self.rim.map_or(0.0, |c| {
            f.residual(
                &self.modes,
                &Boundary {
                    r: c,
                    data: &self.rim_grid,
                    extra: &rim_extra,
                },
            )
            .0 / self.p_ref
        });
        self.corner_amplitudes = f
            .extra
            .chunks(4)
            .map(|x| [Complex64::new(x[0], -x[1]), Complex64::new(x[2], -x[3])])
            .collect();
        // the R_o scan reaches B + 12D by default, the equilibrium test B + 20D; beyond r_max
        // the enrichment's midplane σ_z is the (slower) direct integral
        self.corner_r_max = self.slab.transform().outer().max(a) + 20.0 * d;
        let level = HoleLevel {
            terms: n,
            collocation_points: colloc.len(),
            residual_max: rmax / self.p_ref,
            residual_rms: rrms / self.p_ref,
            rim_residual_max: rim_residual,
            condition: f.condition,
        };
        self.info.corner_terms = self.corner_terms;
        self.info.history.push(level);
        self.info.terms = n;
        self.info.collocation_points = level.collocation_points;
        self.info.check_points = self.grid.len();
        self.info.residual_max = level.residual_max;
        self.info.residual_rms = level.residual_rms;
        self.info.rim_residual_max = rim_residual;
        self.info.condition = level.condition;
        self.fit = Some(f);
    }

    /// The enrichment's traction columns on the cylinder r at the heights `z` (see
    /// [`Boundary::extra`]), computing only heights not cached yet.
    fn corner_columns(&mut self, r: f64, z: &[f64], rim: bool) -> Vec<f64> {
        let Some(corner) = &self.corner else {
            return Vec::new();
        };
        let cache = if rim {
            &mut self.corner_rim_cache
        } else {
            &mut self.corner_cache
        };
        let fresh: Vec<f64> = z
            .iter()
            .copied()
            .filter(|h| !cache.contains_key(&h.to_bits()))
            .collect();
        if !fresh.is_empty() {
            for (h, t) in fresh.iter().zip(corner.tractions(r, &fresh)) {
                let (mut sr, mut tau) = (Vec::new(), Vec::new());
                for c in &t {
                    sr.extend([c[0].re, c[0].im, c[1].re, c[1].im]);
                    tau.extend([c[2].re, c[2].im, c[3].re, c[3].im]);
                }
                sr.extend(tau);
                cache.insert(h.to_bits(), sr);
            }
        }
        z.iter()
            .flat_map(|h| cache[&h.to_bits()].iter().copied())
            .collect()
    }
}

/// Σ x_i y_i over the common length.
pub(super) fn dot(x: &[f64], y: &[f64]) -> f64 {
    x.iter().zip(y).map(|(a, b)| a * b).sum()
}
