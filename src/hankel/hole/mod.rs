//! The single plate with a hole by Hankel transforms: the infinite slab's solution corrected so
//! that the hole r = A (and a finite rim r = C) is free of traction, and the plate's separation
//! radius R_o, the first upward zero of the midplane σ_z beyond B (report eq. 2.6, Fernlund's
//! single-plate substitute).
//!
//! **Problem.** The plate r ≥ A, −D ≤ z ≤ D, pressed by p(r) on both faces, with a traction-free
//! hole: σ_r(A, z) = τ_rz(A, z) = 0. The infinite slab ([`crate::hankel::Slab`]) satisfies the
//! face conditions but leaves σ_r and τ_rz on r = A; Fernlund superposed their negatives (report
//! Fig. 3(d)–(e)). Here the correction is a field that is homogeneous in r ≥ A (faces free,
//! symmetric in z, decaying as r → ∞) whose traction on r = A cancels the slab's. Sign
//! convention: compression negative; lengths in any unit; residual tractions relative to the
//! mean pressure P.
//!
//! **Method.** The correction combines the Lamé field u = c/r (σ_r = −σ_θ ∝ 1/r², no σ_z) and
//! the symmetric Papkovich–Fadle eigenfunctions of the layer, K₀/K₁(λ_k r) times trigonometric
//! functions of λ_k z with sin 2λ_kD + 2λ_kD = 0 (Fadle 1941; Little & Childs, *Q. Appl. Math.*
//! 25 (1967) 261; Gregory, *J. Elasticity* 10 (1980) 57): [`eigen`]. They are closed forms (one
//! complex K₀, K₁ pair per mode and point, [`crate::numerics::bessel_k`]), so the fit and the
//! midplane sum cost microseconds — the reason they were chosen over ring loads of the slab's
//! Green's function (a Hankel integral per collocation point, and an ill-conditioned basis). The
//! fictitious slab is loaded by p continued smoothly into the hole ([`plate::extended_load`]), so
//! its traction on r = A is smooth. The true solution has a Williams singularity at the 90°
//! corner (A, ±D), stresses ~ ρ^(λ−1) with sin(λπ/2) = −λ, λ₁ = 2.7396 + 1.1190i (Williams,
//! *J. Appl. Mech.* 19 (1952) 526), which smooth modes resolve only down to a height ~D/N; the
//! fit is therefore enriched by the corner's singular fields ([`corner`], [`corner_quad`]):
//! exact homogeneous solutions of r ≥ A — the slab loaded inside the hole by pressures and
//! shears ∝ (1 − r²/A²)^(λ−1) — whose span contains the Williams field of each exponent.
//! [`HoleParams::corner_terms`] takes the leading exponents in order of real part, λ₁, λ₁ + 1,
//! λ₁ + 2 (the axisymmetric companions of the first), λ₂, …; four real columns each. The
//! amplitudes come from least-squares collocation on r = A ([`fit`]; the slab's tractions at all
//! heights interpolated by [`profile`] from a few Chebyshev heights integrated by
//! [`traction`]). N, the number of modes, doubles until R_o's whole error estimate is below
//! [`HoleParams::r_o_tolerance`]·R_o ([`single_plate_separation`], in `separation.rs`).
//!
//! With `OuterRadius::Finite(C)` the same treatment frees r = C: N modes growing outward
//! (I₀, I₁(λ_k r), [`crate::numerics::bessel_i`]) and the uniform in-plane state σ_r = σ_θ join
//! the unknowns, and the fit collocates on both cylinders. A rim changes the midplane σ_z only
//! through the modes, ≈ e^(−2.1(C − R_o)/D): nothing for the report's C = 1.54 in, 3 % of R_o
//! for a rim 1.3D beyond the load. The rim's corner is not enriched. R_o alone does not fit a rim
//! that cannot move it by a tenth of the tolerance asked ([`rim`]: Table 1's C = 1.54 in at the
//! scene tolerances), and adds the bound of its effect to the estimate.
//!
//! **Error estimate.** R_o's estimate adds the slab quadrature's share, the slab data's
//! ([`HoleInfo::slab_error`] divided by the slope: the fit cannot see an error in its own data)
//! and the hole's: at the first N the bound max residual·P/slope (|δσ_z| ≤ max residual
//! traction: the error field is the response to that traction, whose self-equilibrated part
//! decays away from the hole and whose net radial force is carried by the Lamé field, which has
//! no σ_z); after a doubling, the last change of R_o, which bounds the current error whenever the
//! doubling at least halves it — checked on what is measured (the last change at most half the
//! one before, or after a single doubling the residual met its target; a residual merely halved
//! far above it, on a narrow load, let R_o's error stand at 11 times the change:
//! `tests/hankel/hole_reach_survey.rs`), else the larger of the last two changes.
//!
//! # Accuracy
//!
//! Modes alone: the residual falls like N^(−1.74) (the corner exponent;
//! `tests/hankel/hole_correction.rs`, `residual_falls_at_the_corner_singularity_rate`). With the
//! default 3 corner terms: like N^(−4) or faster (λ₂ = 4.8083 + 1.4639i bounds it at N^(−3.8)),
//! down to the slab data's quadrature floor, ~3e-9 P; every Table 1 geometry reaches 1e-6 P at N ≤
//! 32 (example 05). R_o's actual error (against N = 256) falls 2.8× or more per doubling and is
//! 2.1e-6 R_o or less already at N = 4; at the default tolerance six of Table 1's rows stop at N =
//! 8 and six at N = 16, with estimates of 1.3e-8–8.8e-7 R_o and actual errors of 9e-14–3.2e-8
//! R_o (example 14; ten and two before one change was trusted alone only with the
//! residual met: that cost 1.3–1.4× on the four rows it moved to N = 16). Beyond Table 1, over
//! random geometries across the reach and random narrow loads (B/A 1.001–1.1;
//! `tests/hankel/hole_reach_survey.rs`, in CI): every error within its estimate plus the
//! reference's, at most 0.17 of it. Against the finite-element single plate the difference is
//! within the two estimates, < 0.005 % on Table 1, including a rim 1.3D beyond the load
//! (`tests/fem/hole_agreement.rs`).
//!
//! # Cost
//!
//! (R_o to 1e-6, default parameters; `cargo bench --bench hole` and example 14, one thread):
//! 4.0–5.7 ms for the six Table 1 rows that stop at N = 8, 6.6–8.3 ms for the six at N = 16, 74 ms
//! for all twelve (example 14, idle machine; before: ten rows at N = 8 in 4.6–6.5 ms,
//! two at 16 in 8.7 ms, 72 ms). About 30 % goes to the slab's traction on the hole at M/2 + 1
//! Chebyshev–Lobatto heights (M = 24–72, [`profile`]; 4–12 thousand ξ-nodes, 1.1–3.0 ms), 25–35 % to the corner fields'
//! tractions, the rest to the fit (Householder QR), the residual and the root search on
//! interpolants sized for the bracket. The direct route ([`SlabSampling::Direct`]: every fitted and
//! checked height integrated) costs 9.3–18 ms. At the scene tolerances, R_o alone with
//! [`HoleParams::for_tolerance`]: 3.1 ms at 5e-4 and 3.6 ms at 1e-4 on Table 1 row 1 (its rim
//! left unfitted, [`rim`]), 3.8–5.7 ms on A/D 1, B/A 2 (example 17).
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
//! assert!(sep.r_o_error < 1e-6 * sep.r_o);
//! assert!((sep.r_o / 0.1 - 4.03183).abs() < 1e-5);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod corner;
mod corner_midplane;
pub mod corner_quad;
pub mod eigen;
pub mod fit;
pub mod midplane_sum;
mod params;
pub mod plate;
pub mod profile;
pub mod rim;
mod separation;
pub mod traction;

// Former homes, kept so that old paths work.
pub use crate::numerics::{bessel_i, bessel_k, bessel_nu, chebyshev};
pub use params::{HoleInfo, HoleLevel, HoleParams, SlabSampling, SLAB_SHARE};
pub use plate::HolePlate;
pub use profile::TractionProfile;
pub use separation::single_plate_separation;
