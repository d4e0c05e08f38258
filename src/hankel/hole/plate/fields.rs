//! Reading a solved [`HolePlate`]: its parts (slab, fit sizes, rim), the fitted correction's
//! field at (r, z) (Lamé + Papkovich–Fadle modes + corner enrichment), its midplane σ_z and the
//! plate's stresses (slab + correction). Split from [`super`] (the solve) by size.
//!
//! # Accuracy
//!
//! The correction's fields are the fit's; the residual on the hole is in [`HolePlate::info`]
//! (`tests/hankel/hole.rs`).
//!
//! # Cost
//!
//! One field evaluation is a sum over the N modes and the enrichment (example 14).
//!
//! ```
//! use boltzone::hankel::hole::{HoleParams, HolePlate};
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load)?;
//! let holed = HolePlate::new(&plate, &HoleParams::default())?;
//! // the hole r = A is free: the plate's σ_r there is the residual only
//! let s = holed.stress(0.1, 0.05, &Default::default());
//! assert!(s.sigma_r.value.abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::super::corner::{CornerMidplaneRule, FieldComponent};
use super::super::eigen::{lame_field, uniform_field, Mode, ModeField};
use super::super::midplane_sum::MidplaneSum;
use super::super::HoleInfo;
use super::{dot, HolePlate};
use crate::hankel::field::{Slab, StressEstimate};
use crate::numerics::quadrature::QuadParams;
use num_complex::Complex64;

impl HolePlate {
    /// The rim radius C whose traction the correction cancels (None: infinite plate).
    pub fn rim(&self) -> Option<f64> {
        self.rim
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

    /// The fitted correction alone (Lamé + modes + corner enrichment, without the slab) at
    /// (r, z), r ≥ A.
    pub fn correction(&self, r: f64, z: f64) -> ModeField<f64> {
        let Some(f) = &self.fit else {
            return ModeField::default();
        };
        let l = lame_field(self.a, self.g, r);
        let s = uniform_field(self.nu, self.g, r, z);
        let mut out = ModeField {
            sigma_r: f.lame * l.sigma_r + f.uniform * s.sigma_r,
            sigma_theta: f.lame * l.sigma_theta + f.uniform * s.sigma_theta,
            sigma_z: 0.0,
            tau_rz: 0.0,
            u: f.lame * l.u + f.uniform * s.u,
            w: f.uniform * s.w,
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
        if let Some(corner) = &self.corner {
            use FieldComponent::*;
            let comps = [SigmaR, SigmaTheta, SigmaZ, TauRz, U, W];
            let f = &corner.fields(r, &[z], &comps)[0];
            let v: Vec<f64> = (0..comps.len())
                .map(|ci| {
                    f.iter()
                        .zip(&self.corner_amplitudes)
                        .map(|(fk, c)| (c[0] * fk[ci][0] + c[1] * fk[ci][1]).re)
                        .sum()
                })
                .collect();
            out.sigma_r += v[0];
            out.sigma_theta += v[1];
            out.sigma_z += v[2];
            out.tau_rz += v[3];
            out.u += v[4];
            out.w += v[5];
        }
        out
    }

    /// The fitted correction's midplane σ_z(r, 0) (modes and corner enrichment; the Lamé field
    /// has none).
    pub fn correction_midplane(&self, r: f64) -> f64 {
        self.modes_midplane(r) + dot(self.corner_weights(), &self.corner_midplane_basis(r))
    }

    /// The modes' part of [`Self::correction_midplane`] (modes whose share is bounded below
    /// 1e-18 P there are skipped: [`Mode::midplane_bound`](super::super::eigen::Mode::midplane_bound)).
    pub fn modes_midplane(&self, r: f64) -> f64 {
        self.modes_midplane_with(r, |k| self.modes[k].midplane_sigma_z(r))
    }

    /// [`Self::modes_midplane`] with mode k's midplane σ_z at r from `value(k)`: a caller
    /// that has tabulated the same modes ([`Self::modes`]) at r saves their evaluation.
    pub fn modes_midplane_with(&self, r: f64, value: impl Fn(usize) -> Complex64) -> f64 {
        let negligible = 1e-18 * self.p_ref;
        self.fit.as_ref().map_or(0.0, |f| {
            self.modes
                .iter()
                .zip(&f.modes)
                .enumerate()
                .filter(|(_, (m, c))| c.norm() * m.midplane_bound(r) > negligible)
                .map(|(k, (_, c))| (c * value(k)).re)
                .sum()
        })
    }

    /// The Papkovich–Fadle modes of the correction (decaying, then growing with a rim).
    pub fn modes(&self) -> &[Mode] {
        &self.modes
    }

    /// The corner enrichment's midplane σ_z(r, 0) field by field, 4 real values per exponent
    /// ([`CornerLoads::midplane_basis`](super::super::corner::CornerLoads::midplane_basis); empty without enrichment): they do not depend on N,
    /// so a caller scanning r at every N may keep them. The enrichment's σ_z is their dot
    /// product with [`Self::corner_weights`].
    pub fn corner_midplane_basis(&self, r: f64) -> Vec<f64> {
        self.corner
            .as_ref()
            .map_or_else(Vec::new, |c| c.midplane_basis(r, self.corner_r_max))
    }

    /// A node set for [`Self::corner_midplane_basis`]-values at radii up to `r_max`
    /// ([`CornerLoads::midplane_rule`](super::super::corner::CornerLoads::midplane_rule): fewer nodes for a smaller `r_max`); None without
    /// enrichment.
    pub fn corner_midplane_rule(&self, r_max: f64) -> Option<CornerMidplaneRule> {
        self.corner.as_ref().map(|c| c.midplane_rule(r_max))
    }

    /// The slab's midplane σ_z and the enrichment's midplane basis on one node set for radii
    /// up to `r_max` ([`MidplaneSum`]); None without enrichment.
    pub fn midplane_sum(&self, r_max: f64) -> Option<MidplaneSum> {
        self.corner
            .as_ref()
            .map(|c| MidplaneSum::new(&self.slab, c, r_max))
    }

    /// The fitted real amplitudes of the enrichment's fields (4 per exponent; empty without
    /// enrichment or fit).
    pub fn corner_weights(&self) -> &[f64] {
        self.fit.as_ref().map_or(&[], |f| &f.extra)
    }

    /// Stresses of the plate with the hole at (r, z), r ≥ A: slab (extended load) + correction.
    /// Error estimates are the slab quadrature's; the hole residual is in [`Self::info`].
    pub fn stress(&self, r: f64, z: f64, params: &QuadParams) -> StressEstimate {
        let mut s = self.slab.stress(r, z, params);
        let c = self.correction(r, z);
        s.sigma_r.value += c.sigma_r;
        s.sigma_theta.value += c.sigma_theta;
        s.sigma_z.value += c.sigma_z;
        s.tau_rz.value += c.tau_rz;
        s
    }
}
