//! The tiers of `HoledParams::for_tolerance` (1e-3, 1e-4, 1e-5, 1e-6) held to their estimates:
//! each run's R_o against a run of the same route at 1e-9 (the knobs of the tier for 1e-8,
//! `two_plate_hole_tier8.rs`; before that tier, the default knobs with ξ_l varied; its own
//! estimate added to the bound), over random geometries (the survey, ignored:
//! A/D 0.3–3, B/A 1.1–4, ν 0–0.45, all within the route's reach B/D ≤ 16) and on two of them in
//! CI. The error must never exceed the estimate, so that a run claiming `converged`
//! (estimate ≤ tol·R_o) is within its tolerance.

use boltzone::hankel::receding::holed::{two_plate_hole, HoledContact, HoledParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

const A: f64 = 0.1;

/// The tolerances whose tiers are checked.
const TIERS: [f64; 4] = [1e-3, 1e-4, 1e-5, 1e-6];

/// One geometry (A/D, B/A, ν) by the knobs for `tol`.
fn run(g: (f64, f64, f64), tol: f64) -> HoledContact {
    run_with(g, &HoledParams::for_tolerance(tol))
}

/// One geometry (A/D, B/A, ν), A = 0.1, uniform load, by the knobs `params`.
pub(crate) fn run_with(g: (f64, f64, f64), params: &HoledParams) -> HoledContact {
    two_plate_hole(&plate(g), params).unwrap()
}

/// The infinite plate of geometry (A/D, B/A, ν), A = 0.1, uniform load.
pub(crate) fn plate(g: (f64, f64, f64)) -> SinglePlate {
    plate_with(g, OuterRadius::Infinite)
}

/// The plate of geometry (A/D, B/A, ν), A = 0.1, uniform load, outer radius `c`.
pub(crate) fn plate_with(g: (f64, f64, f64), c: OuterRadius) -> SinglePlate {
    let (a_over_d, b_over_a, nu) = g;
    SinglePlate::new(
        A,
        c,
        A / a_over_d,
        Material::new(3.0e7, nu).unwrap(),
        FaceLoad::uniform(A, b_over_a * A, 1.0).unwrap(),
    )
    .unwrap()
}

/// Each tier's (error, estimate, claims converged) on `g`, all relative to R_o, after checking
/// that the error against the run at 1e-9 is within the tier's estimate plus the reference's.
fn check(g: (f64, f64, f64)) -> Vec<(f64, f64, bool)> {
    let reference = run(g, 1e-9);
    TIERS
        .iter()
        .map(|&tol| {
            let out = run(g, tol);
            let err = (out.r_o - reference.r_o).abs();
            let bound = out.info.r_o_error + reference.info.r_o_error;
            assert!(
                err <= bound,
                "(A/D, B/A, ν) = {g:?}, tol {tol:e}: R_o {} vs {} at 1e-9, error {err:e} beyond \
                 the estimates {bound:e}",
                out.r_o,
                reference.r_o
            );
            let est = out.info.r_o_error / out.r_o;
            (err / out.r_o, est, out.meets(tol))
        })
        .collect()
}

#[test]
fn two_geometries_are_within_every_tiers_estimate() {
    // Table 1's narrowest load (1, 1.3), where the half-terms variant sets the estimate, and a
    // thinner plate with a wider load (B/D = 4.5: 1.3 times the Nyström points) and ν = 0.1.
    // Measured: errors 1.7e-10 … 6.4e-6 of R_o against estimates 6.1e-8 … 2.0e-4, at most 0.37
    // of the estimate; every tier claims convergence on both.
    for g in [(1.0, 1.3, 0.3), (1.5, 3.0, 0.1)] {
        for (tol, (err, est, converged)) in TIERS.iter().zip(check(g)) {
            println!(
                "{g:?} tol {tol:e}: error {err:.1e}, estimate {est:.1e}, converged {converged}"
            );
        }
    }
}

/// A small xorshift generator (the survey's geometries, reproducible; also the survey of
/// `two_plate_hole_tier8.rs`).
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    pub(crate) fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A geometry (A/D, B/A, ν) from the holed routes' whole reach: A/D log-uniform from the
    /// smallest hole the two-plate route takes (`MIN_A_OVER_D`, 0.04) to 15, B/A log-uniform in
    /// `ba_lo`–`ba_hi`, ν uniform in −0.95–0.499, drawn again until B/D ≤ `MAX_B_OVER_D` (16).
    pub(crate) fn reach_geometry(&mut self, ba_lo: f64, ba_hi: f64) -> (f64, f64, f64) {
        use boltzone::hankel::receding::{MAX_B_OVER_D, MIN_A_OVER_D};
        loop {
            let ad = self.uniform(MIN_A_OVER_D.ln(), 15f64.ln()).exp();
            let ba = self.uniform(ba_lo.ln(), ba_hi.ln()).exp();
            let nu = self.uniform(-0.95, 0.499);
            if ad * ba <= MAX_B_OVER_D {
                return (ad, ba, nu);
            }
        }
    }

    /// A survey geometry (A/D, B/A, ν): A/D in 0.3–3 and B/A in 1.1–4 log-uniform (B/D ≤ 12,
    /// within the route's reach of 16), ν uniform in 0–0.45.
    pub(crate) fn geometry(&mut self) -> (f64, f64, f64) {
        (
            self.uniform(0.3f64.ln(), 3f64.ln()).exp(),
            self.uniform(1.1f64.ln(), 4f64.ln()).exp(),
            self.uniform(0.0, 0.45),
        )
    }
}

/// The survey's size: SURVEY_N, else `default`.
pub(crate) fn survey_n(default: usize) -> usize {
    std::env::var("SURVEY_N")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Measured (SURVEY_N = 40, 141 s, with the scan from B + 0.45D and the final 1e-5 tier): the
/// error never above 0.43 of the estimate (largest ratio by tier 0.41, 0.43, 0.34, 0.16 for
/// 1e-3 … 1e-6); the largest estimates 5.9e-4, 4.3e-5, 1.6e-5, 1.5e-5 of R_o; converged on 40,
/// 40, 39 and 36 of 40. Not converged: at 1e-5 (A/D, B/A) = (0.341, 1.175), error 2.3e-8 against
/// an estimate of 1.6e-5 (the half-terms variant, 8 modes, on a plate 3A thick); at 1e-6 four
/// narrow loads on thick plates, A/D 0.34–0.58, B/A 1.18–1.35, estimates 1.1e-6 … 1.5e-5,
/// errors 4.9e-9 … 1.5e-8. The tier's first choice for 1e-5 (12 modes, 16 heights, ξ_l 18/D,
/// tail 9D) converged on all 40 with the error up to 0.66 of its estimate.
///
/// Re-measured 2026-11-25 (46 s, idle machine) on main after the tier for 1e-6 doubles its
/// modes to 2e-6 P and splits its variants, the Newton search, the hole tables and the variants
/// at the search's last radius: largest error/estimate 0.37, 0.37, 0.39, 0.21 for 1e-3 … 1e-6
/// (the 0.16 above was stale before that: 0.23 on (0.649, 1.181) with the scan's binary);
/// largest estimates 5.8e-4, 4.3e-5, 1.6e-5, 6.4e-7 of R_o; converged on 40, 40, 39, 40 (at
/// 1e-5 still (0.341, 1.175): error 1.6e-6, estimate 1.6e-5 of R_o, its half-modes variant).
/// With the tier for 1e-5's modes doubled to 2e-6 P as the tier for 1e-6's (module
/// `holed_params`; 45 s): largest error/estimate 0.37, 0.37, 0.39, 0.21, largest estimates
/// 5.8e-4, 4.3e-5, 1.0e-6, 6.4e-7 of R_o, converged on 40 of 40 at every tier ((0.341, 1.175)
/// at 1e-5: error 3.5e-8, estimate 3.9e-7).
/// With the tiers for 1e-3 and 1e-4 doubling their modes to 1e-3 and 1e-4 P, and `converged`
/// as `HoledContact::meets` (the hole resolved to its modes' target too; 40 s, idle): largest
/// error/estimate 0.37, 0.29, 0.39, 0.21, largest estimates 3.8e-4, 4.3e-5, 1.0e-6, 6.4e-7 of
/// R_o, converged (hole resolved) on 40 of 40 at every tier.
#[test]
#[ignore = "survey: about 2.5 s per geometry (SURVEY_N, default 40)"]
fn random_geometries_are_within_every_tiers_estimate() {
    let n = survey_n(40);
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    // per tier: largest error/estimate, largest estimate, runs claiming convergence
    let mut worst = [(0.0f64, 0.0f64, 0usize); 4];
    for _ in 0..n {
        let g = rng.geometry();
        let rows = check(g);
        let line: Vec<String> = rows
            .iter()
            .map(|(e, s, _)| format!("{e:.1e}/{s:.1e}"))
            .collect();
        println!(
            "A/D {:.3} B/A {:.3} nu {:.3}: error/estimate by tier {}",
            g.0,
            g.1,
            g.2,
            line.join("  ")
        );
        for (w, (e, s, c)) in worst.iter_mut().zip(rows) {
            *w = (w.0.max(e / s), w.1.max(s), w.2 + usize::from(c));
        }
    }
    for (tol, (ratio, est, conv)) in TIERS.iter().zip(worst) {
        println!(
            "tier {tol:e}: largest error/estimate {ratio:.2}, largest estimate {est:.1e}, \
             converged {conv} of {n}"
        );
    }
}
