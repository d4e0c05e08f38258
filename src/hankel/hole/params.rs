//! The knobs of the hole correction ([`HoleParams`], with the choice of [`SlabSampling`]) and
//! what it reports ([`HoleInfo`], one [`HoleLevel`] per doubling of N); the method they steer is
//! in the [folder's docs](super).
//!
//! # Accuracy
//!
//! Plain data; the defaults' effect on R_o is measured by example 14 and
//! `tests/hankel/hole_correction.rs`.
//!
//! # Cost
//!
//! None: the solver's cost is in `cargo bench --bench hole`.
//!
//! ```
//! use boltzone::hankel::hole::{HoleParams, SlabSampling};
//! let p = HoleParams::default();
//! assert_eq!((p.start_terms, p.corner_terms), (4, 3));
//! assert_eq!(p.slab_sampling, SlabSampling::Profile);
//! ```

use crate::error::{positive, InputError};

/// Knobs of the hole correction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoleParams {
    /// Target of the largest residual traction on the hole, relative to P (default 1e-6):
    /// [`HolePlate::new`](super::HolePlate::new) doubles N until it is met;
    /// [`single_plate_separation`](super::single_plate_separation) reports the residual but stops
    /// on R_o's estimate ([`Self::r_o_tolerance`]).
    pub residual_target: f64,
    /// A fixed number of Papkovich–Fadle modes N; `None` (default) doubles N from
    /// `start_terms` until the target is met or `max_terms` is reached.
    pub terms: Option<usize>,
    /// First N of the doubling (default 4).
    pub start_terms: usize,
    /// Largest N of the doubling (default 64).
    pub max_terms: usize,
    /// Absolute tolerance of the slab's hole tractions, relative to P (default 1e-8: a hundredth
    /// of the residual target; the enriched fit reaches the floor this sets, ~3e-9 P, by N = 8
    /// on the wide loads; it moves
    /// R_o by at most tolerance·P/slope, 1e-8 to 6e-8 A on Table 1). With the default
    /// [`SlabSampling::Profile`] it is the target of the interpolant's error estimate
    /// (truncation + Lebesgue constant × the samples' quadrature error); the quadrature
    /// confirms little below ~1e-10 next to the face, so tighter targets stop there and say so
    /// in [`HoleInfo::slab_error`].
    pub slab_tolerance: f64,
    /// [`single_plate_separation`](super::single_plate_separation) stops doubling N when R_o's
    /// whole error estimate (the hole's share, the quadrature's and the slab data's, see the module
    /// docs) is below this fraction of R_o (default 1e-6).
    pub r_o_tolerance: f64,
    /// How the slab's traction on the hole is obtained (default [`SlabSampling::Profile`]).
    pub slab_sampling: SlabSampling,
    /// Leading exponents of the corner (A, ±D)'s singular expansion whose fields enrich the fit
    /// ([`corner::enrichment_exponents`](super::corner::enrichment_exponents): λ₁, λ₁ + 1, λ₁ + 2,
    /// λ₂, …; four real columns each, and the collocation heights double to 4N + 1 to keep the
    /// system overdetermined); 0 fits modes only. Default 3: the fewest reaching 1e-6 P at N ≤ 32
    /// on all of Table 1 (measured in example 05; 2 needs N = 64 on the narrowest load, 4 saves one
    /// doubling on two rows but costs more per level and conditions worse). At most 6.
    pub corner_terms: usize,
}

/// [`HoleParams::for_tolerance`]: the slab's hole tractions to this fraction of R_o's
/// relative tolerance.
pub const SLAB_SHARE: f64 = 2e-3;

/// How the slab's traction on the hole (and rim) is obtained at the fit's heights.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SlabSampling {
    /// Sampled once at a few Chebyshev heights and interpolated ([`profile`](super::profile)): the
    /// default; 4–13× fewer ξ-nodes than the direct route on Table 1, to the same `slab_tolerance`.
    #[default]
    Profile,
    /// Every fitted and checked height integrated on its own ([`traction`](super::traction)); the
    /// reference route of the tests.
    Direct,
}

impl Default for HoleParams {
    fn default() -> Self {
        Self {
            residual_target: 1e-6,
            terms: None,
            start_terms: 4,
            max_terms: 64,
            slab_tolerance: 1e-8,
            r_o_tolerance: 1e-6,
            slab_sampling: SlabSampling::Profile,
            corner_terms: 3,
        }
    }
}

impl HoleParams {
    /// The defaults for R_o to the relative tolerance `tol` (what `single --method hankel` and
    /// the scenes use): `r_o_tolerance` = tol, and the slab's hole tractions to
    /// [`SLAB_SHARE`]·tol (within 1e-8..1e-5). The slab data's error enters R_o's estimate as
    /// slab_tolerance·P/slope (see the [folder's docs](super)); with the slopes of Table 1 and
    /// beyond (≥ 0.01 P/A at R_o ≥ 2A) that share is at most a tenth of the tolerance, while
    /// a looser profile needs 30–60 % fewer ξ-nodes at tolerances 1e-4 and above (example 17).
    pub fn for_tolerance(tol: f64) -> Self {
        Self {
            r_o_tolerance: tol,
            slab_tolerance: (SLAB_SHARE * tol).clamp(1e-8, 1e-5),
            ..Self::default()
        }
    }

    pub(super) fn check(&self) -> Result<(), InputError> {
        positive("hole residual target", self.residual_target)?;
        positive("hole slab tolerance", self.slab_tolerance)?;
        positive("hole R_o tolerance", self.r_o_tolerance)?;
        let bad = |field, v: usize| InputError::Parameter {
            field,
            value: v as f64,
            reason: "must lie in 1..=512",
        };
        if let Some(n) = self.terms {
            if n == 0 || n > 512 {
                return Err(bad("hole terms", n));
            }
        }
        if self.start_terms == 0 || self.start_terms > 512 {
            return Err(bad("hole start_terms", self.start_terms));
        }
        if self.max_terms > 512 {
            return Err(bad("hole max_terms", self.max_terms));
        }
        if self.corner_terms > 6 {
            return Err(InputError::Parameter {
                field: "hole corner_terms",
                value: self.corner_terms as f64,
                reason: "must lie in 0..=6",
            });
        }
        Ok(())
    }
}

/// One step of the doubling of N.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct HoleLevel {
    /// Papkovich–Fadle modes N.
    pub terms: usize,
    /// Collocation heights on 0 ≤ z ≤ D.
    pub collocation_points: usize,
    /// Largest residual traction on the hole, relative to P.
    pub residual_max: f64,
    /// RMS residual traction (Chebyshev measure in z), relative to P.
    pub residual_rms: f64,
    /// Largest residual traction on the rim r = C, relative to P (0 for an infinite plate).
    pub rim_residual_max: f64,
    /// Condition number of the column-scaled collocation matrix.
    pub condition: f64,
}

/// What the hole correction did and how well.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct HoleInfo {
    /// Papkovich–Fadle modes N of the accepted fit (0 when there is no hole).
    pub terms: usize,
    /// Collocation heights of the accepted fit.
    pub collocation_points: usize,
    /// Heights the residual was measured on (collocation + check points).
    pub check_points: usize,
    /// Largest residual traction |(σ_r, τ_rz)| on the hole, relative to P.
    pub residual_max: f64,
    /// RMS residual traction, relative to P.
    pub residual_rms: f64,
    /// Largest residual traction on the rim r = C, relative to P (0 for an infinite plate).
    pub rim_residual_max: f64,
    /// Condition number of the column-scaled collocation matrix.
    pub condition: f64,
    /// A finite rim left unfitted because it is too far from R_o to matter: the bound on its
    /// effect on R_o ([`super::rim`], a length, included in R_o's estimate); 0 when the rim
    /// was fitted or the plate is infinite.
    pub rim_bound: f64,
    /// Error estimate of the slab's hole tractions, relative to P: the traction profile's
    /// (interpolation + samples), or with [`SlabSampling::Direct`] the largest quadrature
    /// estimate.
    pub slab_error: f64,
    /// ξ-nodes spent on the slab's hole tractions (each serves up to
    /// [`traction::BATCH`](super::traction::BATCH) heights).
    pub slab_evaluations: usize,
    /// Corner exponents enriched (4 real columns each; see [`HoleParams::corner_terms`]).
    pub corner_terms: usize,
    /// Every N tried, in order.
    pub history: Vec<HoleLevel>,
    /// Wall-clock seconds of the correction.
    pub seconds: f64,
}
