//! The knobs of the holed two-plate route ([`super`]): [`HoledParams`], its defaults
//! and [`HoledParams::for_tolerance`], the knobs for a relative tolerance on R_o.
//!
//! # Accuracy
//!
//! What each knob buys is measured in [`super`]'s docs; the knobs for 1e-6 against a run
//! finer in every knob: `tests/hankel/two_plate_hole_fast.rs`
//! (`knobs_for_1e6_are_within_their_estimate_of_a_finer_run`); every tier against a run at
//! 1e-9 on random geometries: `tests/hankel/two_plate_hole_tiers.rs`.
//!
//! # Cost
//!
//! None of its own; the route's cost with each set of knobs: example 19.
//!
//! ```
//! use boltzone::hankel::receding::holed::HoledParams;
//! let p = HoledParams::for_tolerance(1e-6);
//! assert!(p.vary_xi_l && p.nodes < HoledParams::default().nodes);
//! ```

use crate::hankel::hole::HoleParams;

/// Widest load B/D (load's outer radius over one plate's thickness) that the route takes: its
/// cost grows like (B/D)² (measured on A = D, release: 1.8 s and 0.2 GB at B/D = 8, 4.7 s and
/// 0.6 GB at 16, 18 s and 2.0 GB at 32; the 10⁴ fuzz of `tests/cli/fuzz.rs` had runs over 30 s
/// from B/D = 42). Wider loads are refused by the entry point as bad input naming the ratio
/// (`tests/hankel/two_plate_hole_reach.rs`); `two --method auto` and a scene's `method = "auto"`
/// take the finite elements there.
pub const MAX_B_OVER_D: f64 = 16.0;

/// Smallest hole A/D (hole radius over one plate's thickness) that the route takes. The A → 0
/// study (`small_holes_approach_the_receding_solution`) ran down to A = 0.05D at the A² rate;
/// the 10⁴ CLI fuzz found holes of A/D = 0.001–0.005 with residual tractions of 1e1–1e4 P on
/// the hole (the estimate, from the variant runs, did not see them) and, with a rim, runs over
/// 30 s. Smaller holes are refused as bad input naming the ratio; `auto` takes the finite
/// elements there. Between 0.3 and the limit (`tests/hankel/small_hole_residual.rs`, ignored
/// study: A/D 0.3, 0.2, 0.15, 0.1, 0.06, 0.04, B/D 1, 3, 8, ν = 0.3, C = ∞, against a run finer
/// in every knob) the hole's residual traction grows smoothly toward 0.04 (B/D = 1, knobs for
/// 1e-6: 1.6e-8, 2.5e-8, 4.2e-8, 1.4e-7, 7.3e-7, 2.5e-6 P; for 1e-8 at most 3.2e-8 P) and every
/// error is within its estimate (at most 0.47 of it); at the limit the CI check
/// `at_the_smallest_hole_the_estimate_covers_a_finer_run`. With a rim the estimate missed the
/// Chebyshev heights at every A/D, not a small-hole effect, until it gained their variant
/// (module `rim`).
pub const MIN_A_OVER_D: f64 = 0.04;

/// Widest load B/D that the route takes with a finite rim C (module `rim`), whose cost is
/// 2–5× the infinite plate's: measured (release, A = D, C = 30D, with a CI build beside it)
/// 2.2, 3.9, 6.6 s of CPU at B/D = 4, 6, 8 and --tol 1e-4, 4.1, 6.6, 10.5 s at 1e-6; 17 s at
/// B/D = 11 and 35 s at 16 (over the fuzz's 30 s). Wider loads with a rim are refused as bad
/// input naming the ratio; `auto` takes the finite elements there.
pub const MAX_B_OVER_D_RIM: f64 = 8.0;

/// `auto` (`two --method auto`, a scene's `method = "auto"`, `map --method auto`) takes this
/// route for two plates only below this tolerance: above it the FE is several times faster and
/// its estimate held on Table 1 and on a 10 × 10 grid at 1e-4 (`tests/hankel/grid_study.rs`);
/// every FE estimate carries 2e-5 of R_o (the slow component its levels cannot show,
/// `contact::two_plate`), so below 3e-5 it would need its level estimate under 1e-5 and at 2e-5
/// it cannot claim the tolerance at all.
pub const AUTO_BELOW: f64 = 3e-5;

/// Knobs of [`two_plate_hole`](super::two_plate_hole).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoledParams {
    /// The hole correction: modes N (`terms`, default 16 here) and corner terms, for both the
    /// bilateral plate and the crack field's correction.
    pub hole: HoleParams,
    /// Nyström points on [0, c] (default 24) for loads out to B = 3.5D, proportionally more
    /// for wider ones.
    pub nodes: usize,
    /// Chebyshev heights on [−D, D] at which the crack field's hole traction is integrated
    /// (default 18; even).
    pub heights: usize,
    /// Root tolerance on R_o relative to D (default 1e-10).
    pub rel_tol: f64,
    /// The crack iteration stops when φ(c) changes by less than this fraction of p̄(0)/c
    /// (default 1e-12).
    pub iteration_tol: f64,
    /// Iterations allowed per contact radius (default 60).
    pub max_iterations: usize,
    /// Scan step as a fraction of D (default 0.25).
    pub step: f64,
    /// The scan gives up at B + `reach`·D (default 8).
    pub reach: f64,
    /// Whether to estimate the error by the two extra runs (⌈3n/4⌉ points; N/2 modes).
    pub estimate: bool,
    /// ξ·D beyond which l's transform is its two-term endpoint expansion (default 40).
    pub xi_l: f64,
    /// Length beyond c over which l is integrated, in D (default 14: l ~ e^(−2.1(r − c)/D)).
    pub tail: f64,
    /// Whether the coarse variant of the estimate also lowers ξ_l to 2/3 (default false), so
    /// that the estimate covers the cutoff of l's transform, whose error falls only like ξ_l⁻³.
    pub vary_xi_l: bool,
    /// The hole ξ-rule ends where e^(−ξ z_min) = e^(−`hole_decay`) at the lowest Chebyshev height
    /// z_min (default 13: 2e-6). 10 saves 15 % of the time and moves R_o by ≤ 2e-8 R_o on Table 1
    /// rows 1, 4, 12, but the estimate then fell short of the error on (0.75, 1.3) (7.8e-9 against
    /// 9.9e-9): not used by [`HoledParams::for_tolerance`].
    pub hole_decay: f64,
    /// Depth of the Anderson acceleration of the crack iteration (default 3; 0: the plain
    /// iteration), module `anderson`.
    pub anderson: usize,
    /// The fraction of the hole modes N that the estimate's coarse variant keeps (default 0.5;
    /// 0.75 in [`HoledParams::for_tolerance`]'s tier for 1e-8, where the modes' convergence is
    /// regular and the change from N/2 is 10–300 times the error: module docs there).
    pub coarse_modes: f64,
    /// Whether the estimate coarsens the modes, the heights and ξ_l in separate variants and
    /// adds their changes (default false: one variant, cheaper; true in the tiers for 1e-8,
    /// where their changes, each ~1e-10 R_o, were seen to cancel, and 1e-6, where ξ_l's
    /// 1.1e-8 R_o was).
    pub split_variants: bool,
}

impl Default for HoledParams {
    fn default() -> Self {
        Self {
            hole: HoleParams {
                terms: Some(16),
                ..HoleParams::default()
            },
            nodes: 24,
            heights: 18,
            rel_tol: 1e-10,
            iteration_tol: 1e-12,
            max_iterations: 60,
            step: 0.25,
            reach: 8.0,
            estimate: true,
            xi_l: 40.0,
            tail: 14.0,
            vary_xi_l: false,
            hole_decay: 13.0,
            anderson: 3,
            coarse_modes: 0.5,
            split_variants: false,
        }
    }
}

impl HoledParams {
    /// Knobs for R_o to a relative tolerance `tol`, the estimate covering every knob but the
    /// tail and the hole rule's end, the coarse variant also at 2/3 of ξ_l. From 1e-8 (up to
    /// 1e-6; tighter tolerances take these knobs too, the route's reach), hole modes doubled
    /// from 32 until the bilateral plate's residual is 5e-7 P (at most 128), 28 heights,
    /// ξ_l = 55/D, `hole_decay` 18 and the coarse variants apart, the modes' at 3/4 (below). From 1e-6 (up to
    /// 1e-5), 16 Nyström points, hole modes doubled from 16 until the bilateral residual is
    /// 2e-6 P (at most 128, 64 before the whole-reach survey below; the half-modes variant
    /// kept), ξ_l = 28/D, a tail of 12D (l ~ e^(−2.1(r−c)/D): 10D moved R_o by 1.5e-9 R_o on
    /// Table 1 row 1, 12D by ~2e-11), root and iteration tolerances 1e-9 (of D; of p̄(0)/c). Looser, one tier per decade, each
    /// chosen by its run on Table 1's twelve rows. Measured on those rows (ν = 0.3) by
    /// `boltzone two --method hankel`, by turns with main's binary (load 2.6–3.3): the largest
    /// estimate and |R_o − main's R_o at the knobs for 1e-6| relative to R_o, CPU per row:
    ///
    /// | from | nodes | heights | modes | ξ_l·D | tail/D | root, iteration | `hole_decay` | estimate | difference | CPU |
    /// |------|-------|---------|-------|-------|--------|-----------------|--------------|----------|------------|-----|
    /// | 1e-5 | 10 | 18 | 16, doubled to 2e-6 P | 22 | 10 | 1e-7 | 10 | 9.0e-7 | 5.5e-8 | 0.38–0.58 s |
    /// | 1e-4 | 8 | 12 | 8, doubled to 1e-4 P | 12 | 7 | 1e-5 | 8 | 3.7e-5 | 6.2e-6 | 0.14–0.26 s |
    /// | 1e-3 | 6 | 10 | 6, doubled to 1e-3 P | 10 | 6 | 1e-4 | 8 | 2.1e-4 | 4.0e-5 | 0.10–0.15 s |
    ///
    /// (1e-6 with 16 modes always: 1.3e-6, 3.2e-10, 0.43–0.78 s; main 0.61–1.02 s. The 1e-5 row by its own run at
    /// load 1.7, main 0.75–0.94 s: its first choice, 12 modes, 16 heights, ξ_l = 18/D, tail 9D,
    /// came within 0.91 of its estimate on (0.75, 1.3).) The estimate's honesty over random
    /// geometries:
    /// `tests/hankel/two_plate_hole_tiers.rs`.
    ///
    /// **The loose tiers' modes over the whole reach**: with 6 and 8 modes always,
    /// the survey over everything the route takes at C = ∞
    /// (`tests/hankel/two_plate_hole_reach_survey.rs`: A/D 0.04–15, B/A 1.02–20, ν −0.95 to
    /// 0.499, 30 random geometries) found the tier for 1e-3 short on small holes (A/D 0.05–0.19):
    /// no contact radius at all on 5 (the edge coefficient of one sign up to B + 8D), and on
    /// (0.067, 1.58, −0.29) 6.1 P left on the hole and R_o off by 6.6e-3 against an estimate of
    /// 2.4e-3 R_o; the tier for 1e-4 not converged there, estimates up to 0.82 R_o. Each knob
    /// alone on five of them: only the modes mattered (doubled to 2e-4 P: errors ≤ 4.2e-5 R_o,
    /// within 0.22 of the estimates). So these tiers double their modes too, to 1e-3 P and 1e-4
    /// P; on Table 1 the residual at 6 and 8 modes is already below (R_o and estimates
    /// unchanged). The survey then: every run within its bar (at most 0.29 of it), converged on
    /// 28, 30, 30, 30 of 30 at 1e-3 … 1e-6. Narrow loads (B/A 1.001–1.1, the same file's second
    /// survey): every run within its bar, but at most 0.94 and 0.96 of it at 1e-5 and 1e-6,
    /// where the modes stopped at 64 far short of 2e-6 P (1.6e-3 P). So the tiers for 1e-5 and
    /// 1e-6 double to 128 (as the tier for 1e-8), which resolves the small holes with wider
    /// loads (on the whole-reach survey 3 runs stopped at 64 with 3.2e-6 … 5e-5 P, at most
    /// 0.28 of their estimates; at 128 they meet 2e-6 P), and a run whose modes still stop short
    /// claims no tolerance ([`HoledInfo::hole_resolved`](super::HoledInfo::hole_resolved)):
    /// narrow loads then at most 0.50 of the bar, converged on 19, 13, 16, 9 of 30.
    /// [`two_plate_hole_to`](super::two_plate_hole_to) hands a run short of its
    /// tolerance to the next tier. On Table 1 and the tiers' survey nothing changed (40 of 40
    /// resolved and converged at every tier; Table 1's R_o and estimates bit for bit).
    ///
    /// **The tier for 1e-5's modes**: with 16 modes always its survey left
    /// (A/D, B/A, ν) = (0.341, 1.175, 0.388) not converged, error 1.6e-6 against an estimate
    /// of 1.6e-5 R_o (the half-modes variant, 8 modes, on a plate 3A thick), as the tier for
    /// 1e-6 had been; it now doubles the modes from 16 to the same 2e-6 P: there error 3.5e-8,
    /// estimate 3.9e-7 R_o, and the survey's 40 geometries all converge at 1e-5, error at most
    /// 0.39 of the estimate (as before), largest estimate 1.0e-6 R_o (1.6e-5 before). On
    /// Table 1 only (0.5, 1.3) takes more modes (32): R_o moved 5.1e-8 R_o, its estimate
    /// 9.0e-7 → 6.1e-7; the twelve rows' CPU by turns (two rounds, idle machine) 1.18–1.84 s
    /// against 1.33–1.43 s in total, within the rounds' spread.
    ///
    /// Re-measured on an idle machine with this session's rounds merged (tables, variants at the
    /// search's last radius, tables round 2), by turns with the session's first binary (module
    /// [`super`]'s Cost): CPU per row 0.14–0.28 s at 1e-6 (the twelve rows 3.14–3.43 →
    /// 2.19–2.37 s per round, 1.44×), 0.08–0.21 s at 1e-5, 0.03–0.05 s at 1e-3 (0.54 → 0.43 s);
    /// the table's CPU column above is the older binaries'.
    ///
    /// **The tier for 1e-6's modes and variants.** With 16 modes always, (0.5, 1.3) estimated
    /// 1.3e-6 R_o (not converged) over an error of 5.1e-8: the half-modes variant (8 modes,
    /// where the modes converge irregularly: below) set it; the 3/4 variant (12 modes) would
    /// change R_o by 4.3e-8, under that error, so it was not taken. Its bilateral residual at 16
    /// modes is 1.1e-5 P, the other eleven rows' at most 1.3e-6 P: doubling until 2e-6 P gives
    /// (0.5, 1.3) 32 modes (3.0e-7 P), estimate 7.9e-8 R_o, within 7.7e-9 R_o of the tier for
    /// 1e-8 (`tests/hankel/two_plate_hole_newton.rs`). With one coarse variant the tiers'
    /// survey then found on (A/D, B/A, ν) = (0.341, 1.175, 0.388) an error of 1.07e-8 R_o
    /// against an estimate of 3.3e-9 (the half-modes estimate had hidden it); each knob alone
    /// (`tier6_knobs_one_at_a_time`, same file) moved R_o − reference from −1.07e-8 to
    /// +8.4e-10 with ξ_l = 55/D, −7.9e-9 with 28 heights, and left it at −1.07e-8 … −1.15e-8
    /// with the modes to 5e-8 P, `hole_decay` 18, a tail of 14D or 24 points: ξ_l's error, its
    /// change cancelled in the one variant by the modes' and heights' (as on the tier for
    /// 1e-8, below). So the tier coarsens each alone ([`HoledParams::split_variants`]).
    /// The tiers' survey after both changes (`tests/hankel/two_plate_hole_tiers.rs`, 40
    /// random geometries, 199 s at load ~8): the tier for 1e-6 converged on 40 of 40 (36
    /// before, the others' estimates up to 1.5e-5 R_o), its error at most 0.21 of its
    /// estimate, the largest estimate 6.4e-7 R_o; the tiers for 1e-3, 1e-4, 1e-5 unchanged
    /// (at most 0.37, 0.37, 0.39 of their estimates). The rim survey
    /// (`tests/hankel/two_plate_rim_survey.rs`, 16 random rims, 316 s at load ~8): every run
    /// within its bar, the largest error/(estimate + reference's) 0.16 at 1e-3 and 0.75 at
    /// 1e-6 (before: 0.14, 0.72; both on A/D 1.77, B/A 1.91, C − B = 6.8D).
    ///
    /// The tier for 1e-8 (24 Nyström points, tail 14D, root 1e-11, iteration 1e-11), chosen by measurement on Table 1's five rows whose 1e-6 estimates were
    /// over 1e-8 ((1, 1.3), (0.75, 1.6), (0.75, 1.3), (0.5, 1.6), (0.5, 1.3)), each knob alone
    /// against a run with 64 modes, 36 heights, ξ_l = 80/D, tail 20D, 32 points: what limits
    /// them is the hole modes N (the bilateral plate's and the correction's). On (0.5, 1.3),
    /// the other knobs the defaults, R_o minus its value at N = 64 is −1.65e-6, +9.4e-8,
    /// +5.1e-8, −3.2e-9, +1.6e-10, −2e-12 of R_o at N = 8, 12, 16, 24, 32, 48 (bilateral residual
    /// 9e-5 … 2.5e-8 P): irregular below N = 24, then falling fast; 18 → 26 or 36 heights,
    /// 18 → 48 points and a tail of 20D each moved it by ≤ 4.3e-10 R_o, ξ_l 40 → 70/D by 1.3e-9.
    /// So the N/2 variant of the 1e-6 knobs (16 → 8 modes: 1.6e-6 R_o) overstated the error
    /// (5.1e-8) 30×, and on (1, 1.3) (16 modes, error 1.4e-10) about 10³×. With 32 modes the
    /// five rows lie within 2.1e-10 R_o of the finer run, and the 3/4 variant (24 modes, 18
    /// heights, ξ_l = 36.7/D) moves R_o by 8.5e-10 … 4.7e-9 R_o, 9–24× the error; all twelve
    /// rows estimate 4.4e-12 … 4.7e-9 R_o (1.0–2.4 s wall per row at load 7). With 32 modes
    /// always, the survey of `tests/hankel/two_plate_hole_tier8.rs` found on its third random
    /// geometry, (A/D, B/A, ν) = (0.347, 1.29, 0.238), a plate 2.9A thick, an error of 3.5e-9
    /// R_o against an estimate of 4.0e-10: there 32 modes leave 2.5e-6 P on the hole (on
    /// Table 1 at most 3.0e-7 P, on (0.5, 1.3)) and R_o moved +3.9e-9, −1.6e-10 R_o from 32 to 48
    /// to 64 modes, while the 3/4 variant (24 modes) moved it by 1.8e-10. Hence N doubles until the
    /// bilateral residual is 5e-7 P: 64 modes there (4.9e-8 P), error 8e-11 against an
    /// estimate of 4.1e-10 R_o; Table 1 keeps 32 on every row. The survey's next eleven
    /// geometries held (error/estimate ≤ 0.82) but that 0.82, on (0.82, 1.48, 0.32), was ξ_l's
    /// error (+1.1e-10 R_o from 55 to 80/D) half cancelled in the one coarse variant by the
    /// modes' and heights' changes: the tier coarsens each alone
    /// ([`HoledParams::split_variants`]: two more solves) and takes the hole rule to e^(−18)
    /// (13 left 1e-11 … 1.4e-10 R_o that no variant sees). The survey over 30 random
    /// geometries (same file, 992 s at load ~10): every error within its estimate (at most
    /// 0.54 of it, on (0.347, 1.29, 0.238)), estimates ≤ 6.4e-9 R_o, all 30 converged. Its
    /// cost at the route's reach (`two --method hankel --tol 1e-8`, A = D, load ~10): B/D = 16
    /// 19.5 s of CPU (37 s wall), with a rim at B/D = 8, C = 30D 28 s, against the 4.7 s and
    /// 10.5 s quoted at [`MAX_B_OVER_D`] and [`MAX_B_OVER_D_RIM`] (lower tiers, lower load):
    /// near the CLI fuzz's 30 s.
    pub fn for_tolerance(tol: f64) -> Self {
        Self::tiers_from(tol)[0]
    }

    /// The knobs of [`HoledParams::for_tolerance`]`(tol)` followed by each tighter tier's up to
    /// the tier for 1e-6: what [`two_plate_hole_to`](super::two_plate_hole_to) tries in
    /// turn until the estimate meets `tol`. The tier for 1e-8 only when asked for (`tol` below
    /// 1e-6): its cost at the reach (19.5 s of CPU at B/D = 16, 28 s with a rim at B/D = 8,
    /// below) after the looser tiers' would pass the 30 s a run may take
    /// (`tests/cli/fuzz.rs`).
    ///
    /// ```
    /// use boltzone::hankel::receding::holed::HoledParams;
    /// let tiers = HoledParams::tiers_from(1e-4);
    /// assert_eq!(tiers[0], HoledParams::for_tolerance(1e-4));
    /// assert_eq!(tiers.len(), 3); // 1e-4, 1e-5, 1e-6
    /// assert_eq!(HoledParams::tiers_from(1e-6).len(), 1);
    /// assert_eq!(HoledParams::tiers_from(1e-9), [HoledParams::for_tolerance(1e-8)]);
    /// ```
    pub fn tiers_from(tol: f64) -> Vec<Self> {
        let base = Self {
            vary_xi_l: true,
            ..Self::default()
        };
        // N doubled from 32 until the bilateral plate's residual is 5e-7 P: the variant at 3/4
        // of N is honest only where the modes converge regularly (the docs above)
        let doubled = |start, max, target| HoleParams {
            terms: None,
            start_terms: start,
            max_terms: max,
            residual_target: target,
            ..base.hole
        };
        let adaptive = doubled(32, 128, 5e-7);
        let tier = |from, nodes, heights, hole, xi_l, tail, root: f64, hole_decay, coarse| Tier {
            from,
            params: Self {
                hole,
                nodes,
                heights,
                rel_tol: root,
                iteration_tol: root,
                xi_l,
                tail,
                hole_decay,
                coarse_modes: coarse,
                // the tiers for 1e-6 and 1e-8
                split_variants: from <= 1e-6,
                ..base
            },
        };
        // (from, nodes, heights, modes, ξ_l·D, tail/D, root and iteration tolerance,
        // hole_decay, the coarse variant's share of the modes), loosest first
        let tiers = [
            tier(1e-3, 6, 10, doubled(6, 64, 1e-3), 10.0, 6.0, 1e-4, 8.0, 0.5),
            tier(1e-4, 8, 12, doubled(8, 64, 1e-4), 12.0, 7.0, 1e-5, 8.0, 0.5),
            tier(
                1e-5,
                10,
                18,
                doubled(16, 128, 2e-6),
                22.0,
                10.0,
                1e-7,
                10.0,
                0.5,
            ),
            tier(
                1e-6,
                16,
                18,
                doubled(16, 128, 2e-6),
                28.0,
                12.0,
                1e-9,
                13.0,
                0.5,
            ),
            tier(1e-8, 24, 28, adaptive, 55.0, 14.0, 1e-11, 18.0, 0.75),
        ];
        // tighter than the tightest tier: its knobs (the route's reach; the estimate says
        // what was reached)
        let first = tiers
            .iter()
            .position(|t| tol >= t.from)
            .unwrap_or(tiers.len() - 1);
        // the tightest tier handed over to: the one for 1e-6
        let last = tiers
            .iter()
            .rposition(|t| t.from >= ESCALATE_TO)
            .map_or(first, |k| k.max(first));
        tiers[first..=last].iter().map(|t| t.params).collect()
    }
}

/// The tightest tier [`HoledParams::tiers_from`] hands a run over to when it was not asked for.
const ESCALATE_TO: f64 = 1e-6;

/// One tier of [`HoledParams::for_tolerance`]: its knobs, for tolerances from `from` up.
struct Tier {
    from: f64,
    params: HoledParams,
}
