//! The single plate with a hole by Hankel transforms: the infinite slab's solution corrected so
//! that the hole r = A (and a finite rim r = C) is free of traction, and the plate's separation
//! radius R_o.
//!
//! **Problem.** The plate r ≥ A, −D ≤ z ≤ D, pressed by p(r) on both faces, with a traction-free
//! hole: σ_r(A, z) = τ_rz(A, z) = 0. The infinite slab ([`crate::hankel::Slab`]) satisfies the
//! face conditions but leaves σ_r and τ_rz on r = A; Fernlund superposed their negatives (report
//! Fig. 3(d)–(e)). Here the correction is a field that is homogeneous in r ≥ A (faces free,
//! symmetric in z, decaying as r → ∞) whose traction on r = A cancels the slab's.
//!
//! **Representation (and why).** Every such field is a combination of the Lamé field
//! u = c/r (σ_r = −σ_θ ∝ 1/r², σ_z = τ_rz = 0) and the symmetric Papkovich–Fadle eigenfunctions
//! of the layer, K₀/K₁(λ_k r) times trigonometric functions of λ_k z with sin 2λ_kD + 2λ_kD = 0
//! (Fadle 1941; Little & Childs, *Q. Appl. Math.* 25 (1967) 261; Gregory, *J. Elasticity* 10
//! (1980) 57): [`eigen`]. They are closed forms — one complex K₀, K₁ pair ([`bessel_k`]) per mode
//! and point, no quadrature — so the fit and the midplane sum cost microseconds, which is why
//! they were chosen over ring loads of the slab's Green's function (each a Hankel integral per
//! collocation point, and a notoriously ill-conditioned basis). The data to cancel would be
//! logarithmically singular at the corner (A, ±D) when the load starts at the hole edge; the
//! second half of the correction removes that: the fictitious slab is loaded by p continued
//! smoothly into the hole ([`plate::extended_load`]), so its traction on r = A is smooth. The
//! amplitudes come from least-squares collocation on r = A ([`fit`]; the slab's tractions at all
//! heights interpolated by [`profile`] from a few Chebyshev heights integrated by
//! [`traction`]), together with those of the corner enrichment ([`corner`]); the convergence
//! parameter is the number of modes N (doubled until the target is met), and the error measure
//! is the residual traction on the hole, measured on twice as many heights as were fitted.
//!
//! **Convergence.** With modes alone the residual falls algebraically, like N^(−1.74): the
//! true solution has a Williams singularity at the 90° corner where the free hole meets the
//! loaded face, stresses ~ ρ^(λ−1) with sin(λπ/2) = −λ, λ₁ = 2.7396 + 1.1190i (Williams,
//! *J. Appl. Mech.* 19 (1952) 526), which smooth modes resolve only down to a height ~D/N
//! (measured, example 05: max residual 6.0e-6 P at N = 64 for A/D = 1, B/A = 3.1; 9.5e-4 P at
//! N = 64 for A/D = 0.5, B/A = 1.3). The fit is therefore enriched by the corner's singular
//! fields ([`corner`]): exact homogeneous solutions of r ≥ A — the slab loaded inside the hole by
//! pressures and shears ∝ (1 − r²/A²)^(λ−1) — whose span contains the Williams field of each
//! exponent λ. [`HoleParams::corner_terms`] takes the leading exponents of the corner expansion
//! in order of real part, λ₁, λ₁ + 1, λ₁ + 2 (the last two the axisymmetric companions of the
//! first, which λ₁ alone leaves at N^(−2.7)), λ₂, …; four real columns each. With the default 3
//! the residual falls like N^(−4) or faster (the next unresolved exponent, λ₂ = 4.8083 +
//! 1.4639i, bounds it at N^(−3.8)): 4.7e-7 P at N = 4 for A/D = 1, B/A = 3.1 (down to the
//! slab data's quadrature floor, ~3e-9 P, at N = 8), and for A/D = 0.5, B/A = 1.3 2.8e-3, 9.0e-5,
//! 1.1e-5, 3.0e-7, 1.3e-8 P at N = 4 … 64 (fitted rate N^(−4.4); the last near that floor). Every Table 1 geometry reaches 1e-6 P at N ≤ 32
//! (N = 4–8 for the wide loads; the narrow ones need N = 16–32 to resolve the load edge B,
//! 0.03–0.06 in from the hole). R_o, a few D away, converges faster still: its changes under
//! doubling N fall below 1e-8 R_o (wide) and 1e-6 R_o (narrow) by N = 16, and it agrees with the
//! finite-element single plate to < 0.005 % on Table 1. The rim r = C of a finite plate has a
//! corner too, which is not enriched: its residual keeps the N^(−1.74) rate.
//!
//! **Outputs.** [`HolePlate`] (fields at any (r, z), r ≥ A) and [`single_plate_separation`]:
//! R_o, the first upward zero of the midplane σ_z beyond B, with an error estimate that adds the
//! hole's share to the slab quadrature's and to the slab data's error (the traction profile's
//! estimate, [`HoleInfo::slab_error`], divided by the slope: the fit cannot see an error in its
//! own data, so it is added in full). The hole's share: at the first N the bound
//! max residual·P/slope (|δσ_z| ≤ max residual traction: the error field is the response to
//! that traction, whose self-equilibrated part decays away from the hole and whose net radial
//! force is carried by the Lamé field, which has no σ_z); after a doubling, the last change of
//! R_o, which bounds the current error whenever the doubling at least halves it — checked on
//! what is measured (the last change at most half the one before, or after a single doubling the
//! residual met or halved), else the larger of the last two changes. Measured on Table 1 (fixed
//! N against N = 256): R_o's error falls 2.8× or more per doubling from N = 4 to 32 (mostly
//! 10–300×), and is 2.1e-6 R_o or less already at N = 4. N doubles until that whole estimate is below
//! [`HoleParams::r_o_tolerance`]·R_o (the residual target alone is not enough: at N = 4 its bound
//! is 1.08e-6 R_o for A/D = 1, B/A = 3.1); ten of Table 1's rows stop at N = 8, the two narrowest
//! (B/A = 1.3, A/D ≤ 0.75) at N = 16, with estimates of 1.3e-8–8.8e-7 R_o and actual errors of
//! 9e-14–9e-8 R_o (example 14).
//!
//! **Cost** (R_o to 1e-6, default parameters, A = 0.1, ν = 0.3; example 14, minimum of 21 runs,
//! one thread, load ≈ 1 on the 2-core machine; medians 2–4 % higher): 4.6–6.5 ms for the ten
//! rows that stop at N = 8, 8.7 ms for the two at N = 16 (72 ms for all twelve; before the
//! R_o-based stopping rule and the work below, 7.2–26 ms and 171 ms). The slab's traction on the
//! hole is computed once, at M/2 + 1 Chebyshev–Lobatto heights (M = 24–72 on Table 1, predicted
//! from the load edge's distance to the hole, [`profile`]), 4–12 thousand ξ-nodes, 1.1–3.0 ms
//! (criterion; Wynn's ε updated in O(window) per panel,
//! [`crate::numerics::quadrature::WynnWindow`]): ~30 % of a run. Each N then costs the corner
//! fields' tractions at the new heights (12-point panels, decayed contributions skipped, one
//! backward recurrence and one E_p table per family of exponents λ₁ + j: ~25–35 % of a run),
//! the fit (Householder QR) and residual, and a root search on the modes' closed forms: the
//! slab's midplane σ_z and the corner fields' are interpolated on the root's bracket once, on a
//! node set sized for it (~15 %). The direct route ([`SlabSampling::Direct`]: every fitted and
//! checked height integrated) costs 9.3–18 ms on the same geometries.
//!
//! **Finite rim.** With `OuterRadius::Finite(C)` the same treatment frees r = C: N modes growing
//! outward (I₀, I₁(λ_k r), [`bessel_i`]) and the uniform in-plane state σ_r = σ_θ join the
//! unknowns, and the fit collocates on both cylinders. A rim changes the midplane σ_z only
//! through the modes, ≈ e^(−2.1(C − R_o)/D) (the Lamé and uniform states have no σ_z): nothing
//! for the report's C = 1.54 in, 3 % of R_o for a rim 1.3D beyond the load (checked against the
//! finite-element plate in `tests/fem/hole_agreement.rs`).
//!
//! Sign convention: compression negative; residuals relative to the mean pressure P.
//!
//! ```
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! use boltzone::hankel::hole::{single_plate_separation, HoleParams};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load)?;
//! let (sep, hole) = single_plate_separation(&plate, &Default::default(), &HoleParams::default())?;
//! // the enrichment meets the 1e-6 P residual target at N = 4, but there the hole's share of
//! // R_o's error (max residual·P/slope) is 1.08e-6 R_o: one doubling more, after which the
//! // change of R_o bounds it and R_o's whole estimate is below 1e-6 R_o
//! assert!(hole.residual_max < 1e-6 && hole.terms == 8 && hole.corner_terms == 3);
//! assert!(sep.error < 1e-6 * sep.r_o);
//! assert!((sep.r_o / 0.1 - 4.03183).abs() < 1e-5);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod corner;
pub mod corner_quad;
pub mod eigen;
pub mod fit;
pub mod plate;
pub mod profile;
mod separation;
pub mod traction;

// Former homes, kept so that old paths work.
pub use crate::numerics::{bessel_i, bessel_k, bessel_nu, chebyshev};
pub use plate::HolePlate;
pub use profile::TractionProfile;
pub use separation::single_plate_separation;

use crate::error::{positive, InputError};

/// Knobs of the hole correction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoleParams {
    /// Target of the largest residual traction on the hole, relative to P (default 1e-6):
    /// [`HolePlate::new`] doubles N until it is met; [`single_plate_separation`] reports the
    /// residual but stops on R_o's estimate ([`Self::r_o_tolerance`]).
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
    /// [`single_plate_separation`] stops doubling N when R_o's whole error estimate (the
    /// hole's share, the quadrature's and the slab data's, see the module docs) is below this
    /// fraction of R_o (default 1e-6).
    pub r_o_tolerance: f64,
    /// How the slab's traction on the hole is obtained (default [`SlabSampling::Profile`]).
    pub slab_sampling: SlabSampling,
    /// Leading exponents of the corner (A, ±D)'s singular expansion whose fields enrich the fit
    /// ([`corner::enrichment_exponents`]: λ₁, λ₁ + 1, λ₁ + 2, λ₂, …; four real columns each, and
    /// the collocation heights double to 4N + 1 to keep the system overdetermined); 0 fits
    /// modes only. Default 3: the fewest reaching 1e-6 P at N ≤ 32 on all of Table 1 (measured
    /// in example 05; 2 needs N = 64 on the narrowest load, 4 saves one doubling on two rows but
    /// costs more per level and conditions worse). At most 6.
    pub corner_terms: usize,
}

/// How the slab's traction on the hole (and rim) is obtained at the fit's heights.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SlabSampling {
    /// Sampled once at a few Chebyshev heights and interpolated ([`profile`]): the default;
    /// 4–13× fewer ξ-nodes than the direct route on Table 1, to the same `slab_tolerance`.
    #[default]
    Profile,
    /// Every fitted and checked height integrated on its own ([`traction`]); the reference
    /// route of the tests.
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
    fn check(&self) -> Result<(), InputError> {
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
    /// Error estimate of the slab's hole tractions, relative to P: the traction profile's
    /// (interpolation + samples), or with [`SlabSampling::Direct`] the largest quadrature
    /// estimate.
    pub slab_error: f64,
    /// ξ-nodes spent on the slab's hole tractions (each serves up to
    /// [`traction::BATCH`] heights).
    pub slab_evaluations: usize,
    /// Corner exponents enriched (4 real columns each; see [`HoleParams::corner_terms`]).
    pub corner_terms: usize,
    /// Every N tried, in order.
    pub history: Vec<HoleLevel>,
    /// Wall-clock seconds of the correction.
    pub seconds: f64,
}
