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
//! exact to O(ξ^(−4.5)). The edge coefficient of the total is X's φ(c); R_o is its root, by the
//! receding solver's scan and a step-stopping inverse interpolation (module `holed_search`).
//!
//! **Error control.** R_o's estimate adds (a) the change from a run with ⌈3n/4⌉ Nyström points,
//! (b) the change from a run with half the hole modes (the bilateral plate and Z), 2/3 of the
//! heights and, with [`HoledParams::vary_xi_l`], 2/3 of ξ_l, (c) the root tolerance; the
//! residual traction on the hole is measured on the fit's check heights. Each variant's R_o is
//! one Newton step from R_o (slope: a secant through two of the search's edge values), its error
//! ∝ the change squared (≤ 1e-6 D: negligible; as full searches to 2e-12 D on Table 1 row 1); a
//! change beyond 0.01 D gets the full search. [`HoledParams::for_tolerance`] picks the knobs for
//! a tolerance. Its tier for 1e-8 changes (b): N doubles from 32 until the bilateral residual
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
//! **Finite rim C** (module `rim_holed`: the infinite plate plus the rim's bending correction,
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
//! Measured 2026-11-24 on all twelve Table 1 rows with `boltzone two --method hankel --tol 1e-6`
//! ([`HoledParams::for_tolerance`]`(1e-6)`), this branch's binary and main's before it, run by
//! turns in one session (CPU of all threads by `perf stat`, load 2–4 on the 2 cores): 0.59–0.92 s
//! per geometry against 1.23–1.83 s before (2.0–2.3×), R_o moved by ≤ 1.5e-10 R_o (estimates
//! 3.8e-10 … 1.3e-6), 9–10 trial radii instead of 10–12. The FE at --tol 1e-6 beside it:
//! example 19. The issue's 10 ms (20× faster than the FE) is still far off. Where the time goes
//! now (row 1, one thread, temporary timers): per trial radius about 70 ms — J₀ rows of l's
//! transform 15, cos rows of the Nyström rule 14, cos rows of the hole rule 8, H_l weights 8,
//! per-radius rules and l's basis values 6, three crack iterations 20 — and once per geometry
//! the slab's midplane curve over [A, B + reach + tail] (0.12 s) and the corner fields' table
//! (0.07 s), about 30 % of the total. Both are now built up to B + 3D + tail only (the
//! whole reach's curve on first use, by a radius beyond B + 3D; the corner fields directly
//! there): a second run of all twelve rows by turns, at a higher load, gave 0.75–1.03 s against
//! 1.56–2.33 s before (2.0–2.5×), R_o within 1.6e-10 R_o of main's; forcing every radius onto
//! the far curve (a one-off build) moved R_o by ≤ 3.4e-12 R_o on rows 1 and 12.
//!
//! What was cut, in order: the Anderson-accelerated iteration (17 → 8 steps per radius on the
//! narrowest load), the corner table (12 ms per radius), two solves per geometry (the search's
//! last solve and the secant are reused), rayon over table rows and over the two variants; then
//! (this round) the H_l weights on the s-rule itself except within a quarter panel of c (60 →
//! 15 ms per radius), l's transform on the Nyström rule beyond ξ_l by the endpoint expansion,
//! J₀ by Horner's rule in Hankel's expansion instead of a term-by-term loop (45 → 15 ms), dot
//! products in four partial sums, the hole rule built per radius for that c with panels up to
//! 4/D beyond ξ_l (3240 → 1500 nodes on row 1: the scan's farthest radius no longer sets it),
//! the search refined by step-stopping inverse interpolation instead of Brent (9 → 7 radii),
//! each radius's iteration warm-started from the nearest radius's correction, and the
//! estimate's half-terms setup sharing the midplane curve and corner table (0.15 → 0.01 s).
//! Next: tables independent of c (fixed panels in t and s with a partial panel at c, a ξ-rule
//! for a cap on c), so that only the partial panels are rebuilt per radius; the midplane curve
//! built lazily up to the radii the search reaches; a contact basis whose transforms are
//! tabulated once.
//!
//! Re-measured after this round: A → 0 (`small_holes_approach_the_receding_solution`) gives
//! −8.255e-8, −1.973e-8, −4.965e-9 as before (the study in 2.5 s wall, 3.9 s CPU); the 10 × 10
//! grid study against the FE at 1e-4 (`tests/hankel/grid_study.rs`) the same ratios (median
//! 0.02, max 0.08) in 146 s instead of 218 s.
//!
//! Cost that follows the tolerance: [`HoledParams::for_tolerance`] has tiers from 1e-3, 1e-4,
//! 1e-5 (fewer nodes, heights, modes, a lower ξ_l, a shorter tail, looser root and iteration
//! tolerances), J₀ below 25 comes from a table ([`super::grid`]), and the scan starts at
//! B + 0.45D (module `holed_search`). All twelve Table 1 rows by `boltzone two --method
//! hankel --tol T`, this branch's binary and main's by turns in one session (CPU user + sys):
//! after the tiers and the table (load 4–7), T = 1e-3 0.14–0.22 s per row against 0.65–1.02 s
//! (4.3× in total), 1e-4 3.4×, 1e-5 1.9×, 1e-6 1.15× (R_o moved ≤ 6.3e-12 R_o, the same
//! estimates); again at load 2: 4.4×, 3.4×, 2.0×, 1.08×. With the scan's start too (load
//! 2.6–3.3; 7–8 radii instead of 9–10 at 1e-6, 5–7 at 1e-3): 1e-3 0.10–0.15 s per row against
//! main's 0.61–0.90 s (5.8×), 1e-4 0.14–0.26 s (4.0×), 1e-5 0.25–0.41 s (2.2×; with the
//! tier's final, finer knobs 0.38–0.58 s against 0.75–0.94 s, 1.8×, at load 1.7), 1e-6
//! 0.43–0.78 s against 0.61–1.02 s (1.25×; R_o moved ≤ 3.2e-10 R_o, estimates 3.8e-10 …
//! 1.3e-6 as before); every row converged at 1e-3 … 1e-5 (estimates ≤ 2.1e-4, 3.7e-5, 9.0e-7
//! R_o) and lies within its estimate of main's R_o. The issue's 10 ms is still 10× off at
//! 1e-3: per radius the tables of l's transform and the Nyström and hole rules, once per
//! geometry the bilateral plate, the midplane curve and the corner table (17 % of the CPU at
//! the knobs for 1e-3 on (0.5, 1.6), by profile).
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

use super::contact::RecedingError;
pub use super::holed_params::HoledParams;
pub use super::holed_record::{HoledContact, HoledInfo};
use crate::error::InputError;
use crate::joint::SinglePlate;

/// R_o of two equal plates with a hole on a frictionless interface: `plate` is the single plate
/// of the reflected picture (its half-thickness is one plate's thickness D). See the module docs;
/// a finite outer radius C adds the rim's terms (module `rim_holed`), C = ∞ is unchanged.
pub fn two_plate_hole(
    plate: &SinglePlate,
    params: &HoledParams,
) -> Result<HoledContact, RecedingError> {
    two_plate_hole_pressure(plate, params, &[]).map(|(out, _)| out)
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
        return super::rim_holed::finite_rim(plate, c, params, at);
    }
    super::holed_infinite::solve(plate, params, at)
}
