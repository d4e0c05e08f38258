//! The two-plate model WITH the hole, semi-analytically: two equal plates D thick, hole radius A,
//! frictionless interface, pressed by p(r) on A ≤ r ≤ B — the report's own problem (Ch. II.B,
//! Table 1's two-plate column) — and its separation radius R_o.
//!
//! **Problem.** By symmetry one plate A ≤ r, 0 ≤ z ≤ D on a frictionless rigid plane: top face
//! σ_z = −p, τ_rz = 0; hole free; bottom τ_rz = 0, w = 0 on A ≤ r ≤ R_o (contact) and σ_z = 0
//! beyond; R_o where the contact pressure ends like √(R_o − r). Reflected in the plane, it is the
//! single plate 2D thick of [`crate::hankel::hole`] with its midplane cut for r > R_o. It lives
//! here, beside the receding solver it extends, because its unknown and its root condition are
//! that solver's (the Abel function φ of a contact disk and its edge value φ(c)).
//!
//! **Method** (superposition; compression negative, w upward, lengths in the units of D).
//! For a trial contact radius c the solution is the sum of
//! 1. the *bilateral* holed plate: the single plate with the hole, midplane held everywhere
//!    ([`crate::hankel::hole::HolePlate`]: slab + Papkovich–Fadle modes + corner enrichment), midplane stress s₀(r);
//! 2. the *crack field* X of a layer without hole on the plane, in contact on r ≤ c and pressed
//!    on its bottom r > c by l(r) = s₀(r) + σ_z^Z(r, 0): the receding layer's Fredholm equation
//!    (module `system`) with a bottom load instead of a top one (Abel function
//!    φ = ψ + H_l, H_l(t) = −(2/π)∫_c^∞ l(s) s ds/√(s² − t²) the half-space part, whose √(c − t)
//!    behaviour is taken out so that ψ is smooth and Nyström converges geometrically);
//! 3. a *hole correction* Z of X: Lamé + symmetric Papkovich–Fadle modes of the 2D slab + the
//!    corner enrichment at (A, D) ([`crate::hankel::hole::fit`]), which keep w = τ_rz = 0 on the
//!    plane and so leave the contact condition alone, fitted to cancel X's traction on r = A
//!    (computed with [`super::layer_field`] at Chebyshev heights and interpolated: X is analytic
//!    in z across the plane, where its ξ-integrals converge slowly).
//!
//! The total is free on r > c exactly because of l's definition; Z's own σ_z there feeds back into
//! l, so 2–3 are iterated (a contraction: X's traction on the hole and Z's stress beyond c both
//! decay over c − A), Anderson-accelerated (module `anderson`: 17 → 8 steps on the narrowest
//! load). X's traction on the hole needs l's transform to ξ ≫ ξ_l; beyond ξ_l it is the
//! endpoint expansion by parts, −l(c)cJ₁(ξc)/ξ − l′(c)cJ₀(ξc)/ξ² + (l′ + c l″)(c)J₁(ξc)/ξ³,
//! exact to O(ξ^(−4.5)). The edge coefficient of the total is X's φ(c); R_o is its root, by
//! Newton's method from a predictor with secant slopes, stopping when the step or the last
//! secant step's own error is within the root tolerance (module `search`; the receding
//! solver's scan and inverse interpolation when Newton fails).
//!
//! **Error control.** R_o's estimate adds (a) the change from a run with ⌈3n/4⌉ Nyström points,
//! (b) the change from a run with half the hole modes (the bilateral plate and Z), 2/3 of the
//! heights and, with [`HoledParams::vary_xi_l`], 2/3 of ξ_l, (c) the root tolerance; the
//! residual traction on the hole is measured on the fit's check heights. Each variant's R_o is
//! one Newton step from R_o (slope: a secant through two of the search's edge values), its error
//! ∝ the change squared (≤ 1e-6 D: negligible; as full searches to 2e-12 D on Table 1 row 1); a
//! change beyond 0.01 D gets the full search. When R_o was extrapolated from the search's last
//! radius x, the variants are solved at x and their change is the difference of edge values
//! there, −(f_v(x) − f(x))/f′ (module `search`). [`HoledParams::for_tolerance`] picks the knobs for
//! a tolerance; its tier for 1e-6 doubles N from 16 until the bilateral residual is 2e-6 P
//! (the change from N/2 at N = 16 overstated a 5e-8 error 30× on (0.5, 1.3), which it left
//! not converged at 1e-6) and coarsens the modes, the heights and ξ_l each alone, as the
//! tier for 1e-8. Its tier for 1e-8 changes (b): N doubles from 32 until the bilateral residual
//! is 5e-7 P, where the modes converge regularly and the change from N/2 overstates the error
//! 10–10³×; the variants take 3/4 of the modes ([`HoledParams::coarse_modes`]), 2/3 of the
//! heights and 2/3 of ξ_l each alone ([`HoledParams::split_variants`]), their changes added.
//!
//! # Accuracy
//!
//! `tests/hankel/two_plate_hole.rs`. The layer kernels: face conditions and the
//! bilateral limit (the slab's own kernels, to 1e-9). R_o against the FE two-plate model, which
//! shares no code, on all twelve Table 1 geometries (C = ∞, ν = 0.3; study
//! `table1_against_the_fe`, 25 minutes): this route's estimates are 4e-11 to 1.3e-6 R_o on eleven
//! rows and 7e-5 R_o on (A/D, B/A) = (0.75, 1.6), where the coarse variant's 12 Chebyshev heights
//! are too few (the crack field's traction there is 0.035 P); the FE at --tol 1e-4 lies within
//! its estimate on all twelve (|FE − this|/estimate 0.23–0.65); at --tol 1e-5 and 1e-6 it lies
//! HIGH by up to 2.0e-5 R_o and outside its estimate (1.3–2.5×) on four rows: (0.75, 1.3),
//! (0.5, 2.2), (0.5, 1.6), (0.5, 1.3). On the last (study `table1_rows_record`, ROWS=11) this
//! route's R_o/A = 2.4256934 moves by at most 3.1e-7 when ξ_l goes 40 → 70/D, the tail 14 → 20D,
//! the heights 18 → 26, or N adapts until the bilateral residual is 5e-9 P (from 1.1e-5 P at
//! N = 16), while the FE's 2.425743 (estimate ±8e-6 relative) is also where its finite-C runs,
//! meshed whole, converge like C⁻² (2.42356, 2.42520, 2.42561, 2.42571, 2.42574 at C = 2.65…42.4
//! in): the FE's excess is not its cut of the infinite plate.
//! `agrees_with_the_fe_on_table1_first_row` checks one row with coarse settings. A → 0 (study `small_holes_approach_the_receding_solution`, B = 3D):
//! R_o minus the no-hole receding solver's under the disk load is −8.3e-8, −2.0e-8, −5.0e-9 (in, D = 0.1 in)
//! at A = 0.2D, 0.1D, 0.05D — the predicted A² (observed rates 2.07, 1.99). The interface
//! pressure ([`two_plate_hole_pressure`]) balances the load within the hole's residual shear
//! (`tests/hankel/two_plate_hole_pressure.rs`: −7.8e-9, −1.3e-10 at ξ_l = 40, 70/D, measured
//! with the two-term expansion; −5.8e-11 at 70/D with three). With the changes below, A → 0
//! re-measured: −8.26e-8, −1.97e-8, −4.97e-9 (rates 2.06, 1.99). On (1, 2.2) R_o/A = 2.623523384608 (two-term expansion) moved
//! ≤ 1.1e-8 under each knob doubled; the FE at 1e-6 stalls 4.7e-6 below, about its own outer-cut
//! estimate (example 19).
//!
//! The third term of l's endpoint expansion moved the defaults' R_o on Table 1 by −1.2e-7 …
//! +3.7e-8 R_o (largest on (0.5, 1.3), where R_o/A is now 2.4256930944): the two-term error in
//! ξ_l fell like ξ_l⁻³ (1.5e-6, 5e-7, 1.3e-7 R_o at 20, 28, 40/D), the three-term error falls at
//! rate ≈ 6 (1.6e-8, 1.3e-9 at 27, 40/D against 70/D; `tests/hankel/two_plate_hole_fast.rs`,
//! `the_endpoint_expansion_converges_fast_in_its_cutoff`), and the defaults now agree with
//! ξ_l = 70/D within 1.3e-9 R_o on all twelve rows. The knobs of
//! [`HoledParams::for_tolerance`]`(1e-6)` lie within 1.1e-8 R_o of that finer run on all twelve,
//! their estimates 3.8e-10 … 1.3e-6 R_o (over 1e-6, honestly not converged, on (0.5, 1.3) only);
//! Anderson moves R_o by ≤ 3.7e-13 R_o (same file).
//!
//! **Finite rim C** (module `rim`: the infinite plate plus the rim's bending correction,
//! which the FE meshed to C measured as ∝ C⁻², `tests/hankel/two_plate_rim.rs`): on Table 1's
//! first row R_o(C) − R_o(∞) = −2.6503e-4, −6.744e-5, −1.694e-5 in at C = 1.54, 3.08, 6.16 in
//! (rates 1.97, 1.99; the FE at --tol 1e-4: −2.653e-4, −6.758e-5, −1.671e-5), and at
//! C = 1.54 in on all twelve rows the FE meshed to C lies within its estimate (example 19's
//! second table; `tests/hankel/two_plate_rim_holed.rs`).
//!
//! **To 1e-8** ([`HoledParams::for_tolerance`]`(1e-8)`, its choice measured there): on
//! (0.5, 1.3), the row the 1e-6 knobs left at 1.3e-6, R_o moves by 1.65e-6, 5.1e-8, 1.6e-10
//! R_o from 8, 16, 32 hole modes to 64 and by ≤ 1.3e-9 under every other knob: the 1e-6
//! estimate was the N/2 variant's pessimism over a 5e-8 error. At the tier all twelve rows
//! estimate 7.2e-12 … 4.8e-9 R_o at C = ∞ (example 19), and its estimate holds against a run
//! finer in every knob on (0.5, 1.3) (error 1.2e-10, estimate 4.8e-9 R_o) and over random
//! geometries (`tests/hankel/two_plate_hole_tier8.rs`: 30 of 30 within, error at most 0.54 of the
//! estimate, estimates ≤ 6.4e-9 R_o, every one converged at 1e-8).
//!
//! # Cost
//!
//! Per Table 1 row at `--tol 1e-6` (C = ∞, [`HoledParams::for_tolerance`]): 0.15–0.32 s of CPU,
//! 7–9 crack solves, every row converged (estimates 3.8e-10 … 3.6e-7 R_o); at 1e-3 about a
//! third of that; with the rim C = 1.54 in several times more (module `rim`). The
//! bilateral holed plate alone (the single plate with its hole) is about 9 ms of it; the
//! measurements behind these figures, and their history, are in `CHANGELOG.md`.
//!
//! **Where the time goes** (row (1, 1.3) at 1e-6, one thread, `perf record`): 6 search radii
//! and 2 of the estimate's variants, of which the fewer-nodes variant (at R_o, where the search
//! ended) now takes the search's tables. Per radius the tables of module `crack_tables`
//! (22 % of the CPU): the J₀ rows of l's transform at the Nyström rule's nodes up to ξ_l
//! (12 %), the Nyström rule's cosine tables on the t-rule and H_l's weights; then a few Anderson-accelerated crack iterations (32 over the 8 radii);
//! per geometry the setup
//! (16 %: the bilateral plate of each variant 5 %, the slab's midplane curve, the corner
//! table) and the hole tables' panels (9 %, module `hole_tables`).
//!
//! **Next** (structural; not done): the Nyström ξ-rule fixed per table epoch (its ω from the
//! epoch's largest c, as the hole rule's) with the J₀ rows of l's transform and its cosine
//! tables on fixed panels, only the partial panel at c rebuilt (the s-rule's first panel must
//! stay at least a quarter panel wide, H_l's weights need the branch point at c that far
//! from the next panel, and no wider than a panel, J₀'s resolution: a partial panel under a
//! quarter merges with the next into two halves; `PanelInterp` then needs unequal panels);
//! the variants' radius tables in parts (the heights and modes variants change neither the
//! Nyström rule nor the J₀ rows of l's transform, only the hole's part and the modes'
//! midplane rows), and the heights and ξ_l variants' hole tables; fewer radii, which needs a
//! start within a few 1e-3 D of R_o (module `search`'s Cost: neither B + 0.45D nor the
//! no-hole receding solution is one).
//!
//! ```no_run
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load)?;
//! let out = two_plate_hole(&plate, &HoledParams::default())?;
//! assert!(out.r_o > 0.31 && out.info.r_o_error < 1e-5 * out.r_o);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod anderson;
mod crack;
mod crack_tables;
mod endpoint;
mod hole_tables;
mod infinite;
mod params;
mod record;
pub mod rim;
mod search;
mod setup;
mod setup_tables;

pub use self::params::{HoledParams, AUTO_BELOW, MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
pub use self::record::{HoledContact, HoledInfo};
use super::contact::RecedingError;
use crate::error::InputError;
use crate::joint::SinglePlate;

/// R_o of two equal plates with a hole on a frictionless interface: `plate` is the single plate
/// of the reflected picture (its half-thickness is one plate's thickness D). See the module docs;
/// a finite outer radius C adds the rim's terms (module `rim`), C = ∞ is unchanged.
pub fn two_plate_hole(
    plate: &SinglePlate,
    params: &HoledParams,
) -> Result<HoledContact, RecedingError> {
    two_plate_hole_pressure(plate, params, &[]).map(|(out, _)| out)
}

/// R_o (and the pressure at `at`, as [`two_plate_hole_pressure`]) to the relative tolerance
/// `tol`: the knobs of [`HoledParams::for_tolerance`]`(tol)`, and when their run does not meet
/// `tol` ([`HoledContact::meets`]: by its own estimate, the hole resolved), or fails
/// numerically (no sign change of the edge coefficient within the scan, a singular system),
/// each tighter tier in turn up to the tier for 1e-6
/// ([`HoledParams::tiers_from`]); the first run that meets `tol`, else the last run (its
/// estimate says what was reached) or its error. Bad input is returned at once; not handed on
/// either: a run whose rim residue alone
/// ([`RimRecord::decay_bound`](self::rim::RimRecord::decay_bound), which no knob moves)
/// is over `tol`, and a run whose hole modes stopped short of their target
/// ([`HoledInfo::hole_resolved`]) when the next tier allows no more of them (the 10⁴ CLI fuzz
/// found `two --method hankel --a 0.1 --b 0.102 --d 0.5 --c 3 --tol 1e-4`, a narrow load on a
/// small hole, taking 29 s of CPU through every tier to 1e-6, each unresolved). What
/// `two --method hankel`, a scene's `method = "hankel"` and the map take.
///
/// Why: each tier was chosen on Table 1 and held over random geometries near it
/// (`tests/hankel/two_plate_hole_tiers.rs`); over the whole reach
/// (`tests/hankel/two_plate_hole_reach_survey.rs`) small holes (A/D < 0.3) left the loose
/// tiers short: with 6 fixed modes the tier for 1e-3 found no contact radius on 5 of 30
/// random geometries and on (A/D, B/A, ν) = (0.067, 1.58, −0.29) left 6.1 P on the hole,
/// R_o off by 6.6e-3 against an estimate of 2.4e-3 R_o. The loose tiers now double their
/// modes to a residual target (module `params`), and a tier whose run still falls short
/// hands over to the next.
///
/// ```no_run
/// use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
/// use boltzone::hankel::receding::holed::two_plate_hole_to;
/// let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
/// let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load)?;
/// let (out, _) = two_plate_hole_to(&plate, 1e-6, &[])?;
/// assert!(out.info.r_o_error <= 1e-6 * out.r_o);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn two_plate_hole_to(
    plate: &SinglePlate,
    tol: f64,
    at: &[f64],
) -> Result<(HoledContact, Vec<(f64, f64)>), RecedingError> {
    let tiers = HoledParams::tiers_from(tol);
    let mut run = two_plate_hole_pressure(plate, &tiers[0], at);
    for pair in tiers.windows(2) {
        let (this, next) = (&pair[0], &pair[1]);
        // done when met, on bad input, when the rim's residue alone (no knob moves it) is over
        // the tolerance, or when the hole's modes stopped short of their target and the next
        // tier cannot take more of them
        let more_modes = next.hole.terms.is_none() && next.hole.max_terms > this.hole.max_terms;
        let done = match &run {
            Ok((out, _)) => {
                let rim = out.info.rim.as_ref().map_or(0.0, |r| r.decay_bound);
                out.meets(tol) || rim > tol * out.r_o || (!out.info.hole_resolved && !more_modes)
            }
            Err(e) => matches!(e, RecedingError::Input(_)),
        };
        if done {
            break;
        }
        run = two_plate_hole_pressure(plate, next, at);
    }
    run
}

/// [`two_plate_hole`] and the interface pressure q(r) ≥ 0 (compression positive, the units of
/// the load) at r = A + x(R_o − A) for each fraction x in `at` (0 ≤ x ≤ 1): pairs (r, q).
pub fn two_plate_hole_pressure(
    plate: &SinglePlate,
    params: &HoledParams,
    at: &[f64],
) -> Result<(HoledContact, Vec<(f64, f64)>), RecedingError> {
    if let Some(&x) = at.iter().find(|x| !(0.0..=1.0).contains(*x)) {
        return Err(InputError::Parameter {
            field: "pressure fraction of [A, R_o]",
            value: x,
            reason: "between 0 and 1",
        }
        .into());
    }
    if let crate::joint::OuterRadius::Finite(c) = plate.outer_radius() {
        return self::rim::finite_rim(plate, c, params, at);
    }
    self::infinite::solve(plate, params, at)
}
