//! The 10 × 10 grid study of issue 15 (item 4): two equal infinite frictionless plates
//! (ν = 0.3, hole A = 0.1 in), A/D ∈ [0.25, 2.5] × B/A ∈ [1.2, 4], both log-spaced with 10
//! values each. On every geometry R_o comes from two routes that share no code: the
//! semi-analytic route with the hole (`hankel::receding::holed::two_plate_hole`: Hankel
//! transforms, Papkovich–Fadle modes, a Nyström solve) and the finite elements
//! (`contact::two_plate::solve` at `tolerance` 1e-4: graded Q9 meshes, an LCP, level
//! extrapolation). Asserted: |FE − semi| ≤ FE estimate + semi estimate on every FE run that
//! says converged. Printed: the table (semi R_o/A ± estimate, FE R_o/A ± estimate, the ratio
//! |FE − semi| / FE estimate, the FE's levels, its observed rate against the semi route) and
//! the distribution of that ratio (median, p99, max). Geometries where the semi route fails are
//! listed, not dropped.
//!
//! **Measured** (2026-11-24, release, sequential under nice, load average 2–3 on the 2 cores),
//! with the FE's cut carrying the exact exterior of the free plate (`fem::exterior`):
//! - level estimate max(|d₃|, |d₂|/4, |d₁|/16), no floor (701 s wall for both tolerances; the FE
//!   19 s in all at 1e-4, 77 s at 1e-5): all 100 converged at both tolerances, every one within
//!   its estimate: |FE − semi| / FE estimate median 0.29, p99 0.39, max 0.42 at 1e-4; median
//!   0.19, p99 0.85, max 0.86 at 1e-5 (the largest on the thick plates, A/D ≤ 0.7 at B/A = 1.2,
//!   where the FE sits 3–5e-6 high).
//! - as shipped (below the default tolerance the cautious estimate max(2|d₃|, |d₂|, |d₁|/2) and
//!   a floor of 2e-5 of R_o, `contact::two_plate`, after random plates without a hole showed
//!   a slow hump the levels cannot see): at 1e-4 all 100 converged (6–8 levels, FE 24 s in all,
//!   218 s wall with the semi route; 146 s after the semi route's speed-ups of this date, the
//!   same figures), ratio median 0.02, p99 0.07, max 0.08; at 1e-5 no FE run
//!   claims the tolerance (the floor is above it), so nothing is compared there.
//!
//! Before (same day, the cut face left free and its C⁻² error estimated from two coarse levels):
//! the FE was low on every geometry at 1e-4 and 95 of 100 at 1e-5; the ratio reached 1.19 at 1e-4
//! (one geometry beyond both estimates) and 1.56 at 1e-5 (18 of 87 converged beyond both), the
//! cut's estimated share being 53–90 % of the FE estimate there: the free cut, not the mesh, was
//! the error, and its C⁻² estimate undershot it.
//!
//! Run: `BOLTZONE_GRID_TOLERANCES=1e-4,1e-5 nice cargo test --release --test hankel grid_study --
//! --ignored --nocapture` (default tolerance list: 1e-4).

use boltzone::contact::params::TwoPlateParams;
use boltzone::contact::two_plate::{solve, TwoPlateSolution};
use boltzone::hankel::receding::holed::{two_plate_hole, HoledContact, HoledParams};
use boltzone::numerics::convergence::log_log_slope;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, SinglePlate};

/// Hole radius, inches (Table 1's).
const A: f64 = boltzone::reference::TABLE1_HOLE_RADIUS;
/// Grid points per axis.
const N: usize = 10;

/// `N` log-spaced values from `lo` to `hi` (both included).
fn log_spaced(lo: f64, hi: f64) -> Vec<f64> {
    (0..N)
        .map(|k| lo * (hi / lo).powf(k as f64 / (N - 1) as f64))
        .collect()
}

fn semi(ad: f64, ba: f64) -> Result<HoledContact, String> {
    let material = Material::new(3.0e7, 0.3).map_err(|e| e.to_string())?;
    let load = FaceLoad::uniform(A, A * ba, 1.0).map_err(|e| e.to_string())?;
    let plate = SinglePlate::new(A, OuterRadius::Infinite, A / ad, material, load)
        .map_err(|e| e.to_string())?;
    two_plate_hole(&plate, &HoledParams::default()).map_err(|e| e.to_string())
}

fn fe(ad: f64, ba: f64, tolerance: f64) -> Result<TwoPlateSolution, String> {
    let material = Material::new(3.0e7, 0.3).map_err(|e| e.to_string())?;
    let joint = Joint::symmetric(A, A * ba, A / ad, material).map_err(|e| e.to_string())?;
    let params = TwoPlateParams {
        tolerance,
        ..TwoPlateParams::default()
    };
    solve(&joint, &params).map_err(|e| e.to_string())
}

/// Least-squares slope of ln e against ln h over the levels with e > 0: the FE's observed
/// rate of convergence to the semi route's R_o (None with fewer than two such levels).
fn rate_against(reference: f64, fe: &TwoPlateSolution) -> Option<f64> {
    let pts: Vec<(f64, f64)> = fe
        .info
        .levels
        .iter()
        .map(|l| (l.h, (l.r_o - reference).abs()))
        .filter(|p| p.1 > 0.0)
        .collect();
    (pts.len() >= 2).then(|| log_log_slope(&pts))
}

/// The value below which a fraction `q` of the sorted `v` lies (nearest rank).
fn quantile(v: &[f64], q: f64) -> f64 {
    let k = ((q * v.len() as f64).ceil() as usize).clamp(1, v.len());
    v[k - 1]
}

/// The FE tolerances of the study: `BOLTZONE_GRID_TOLERANCES` (comma-separated), default 1e-4.
fn tolerances() -> Vec<f64> {
    std::env::var("BOLTZONE_GRID_TOLERANCES")
        .ok()
        .map(|v| v.split(',').filter_map(|t| t.trim().parse().ok()).collect())
        .filter(|v: &Vec<f64>| !v.is_empty())
        .unwrap_or_else(|| vec![1e-4])
}

/// What one tolerance's runs gave.
#[derive(Default)]
struct Tally {
    ratios: Vec<f64>,
    unconverged: Vec<(f64, f64)>,
    failures: Vec<(f64, f64, String)>,
    beyond: Vec<(f64, f64, f64, f64, f64)>,
}

#[test]
#[ignore = "study: ~6–12 min in release (100 geometries, semi route ~3 s each)"]
fn grid_study() {
    let tols = tolerances();
    let start = std::time::Instant::now();
    println!(
        "Two equal infinite plates, A = {A} in, ν = 0.3: R_o/A by the semi route and the FE \
         (tolerances {tols:?}); estimates relative to R_o; ratio = |FE − semi| / FE estimate; \
         rate = slope of ln|R_o(level) − semi| against ln h; cut est = the FE's estimate of its outer \
         cut's share (in its est); t = FE wall time"
    );
    println!(
        "{:>6} {:>6} | {:>13} {:>8} | {:>6} {:>11} {:>8} {:>4} | {:>9} {:>6} {:>6} {:>7} {:>8} {:>7}",
        "A/D",
        "B/A",
        "semi R_o/A",
        "est",
        "tol",
        "FE R_o/A",
        "est",
        "conv",
        "FE−semi",
        "ratio",
        "levels",
        "rate",
        "cut est",
        "t [s]"
    );
    let mut tally: Vec<Tally> = tols.iter().map(|_| Tally::default()).collect();
    for ad in log_spaced(0.25, 2.5) {
        for ba in log_spaced(1.2, 4.0) {
            let s = match semi(ad, ba) {
                Ok(s) => s,
                Err(why) => {
                    println!("{ad:>6.3} {ba:>6.3} | semi route FAILED: {why}");
                    for t in &mut tally {
                        t.failures.push((ad, ba, format!("semi: {why}")));
                    }
                    continue;
                }
            };
            for (&tol, t) in tols.iter().zip(&mut tally) {
                let f = match fe(ad, ba, tol) {
                    Ok(f) => f,
                    Err(why) => {
                        println!("{ad:>6.3} {ba:>6.3} | FE at {tol:e} FAILED: {why}");
                        t.failures.push((ad, ba, format!("FE: {why}")));
                        continue;
                    }
                };
                let diff = f.r_o - s.r_o;
                let ratio = diff.abs() / f.r_o_error;
                let rate = rate_against(s.r_o, &f).map_or("-".into(), |r| format!("{r:.2}"));
                println!(
                    "{ad:>6.3} {ba:>6.3} | {:>13.10} {:>8.1e} | {tol:>6.0e} {:>11.8} {:>8.1e} {:>4} | {:>+9.1e} {:>6.2} {:>6} {:>7} {:>8.1e} {:>7.2}",
                    s.r_o / A,
                    s.info.r_o_error / s.r_o,
                    f.r_o / A,
                    f.r_o_error / s.r_o,
                    if f.converged { "yes" } else { "no" },
                    diff / s.r_o,
                    ratio,
                    f.info.levels.len(),
                    rate,
                    f.info.truncation_error / s.r_o,
                    f.info.seconds
                );
                if !f.converged {
                    t.unconverged.push((ad, ba));
                    continue;
                }
                t.ratios.push(ratio);
                if diff.abs() > f.r_o_error + s.info.r_o_error {
                    t.beyond.push((ad, ba, diff, f.r_o_error, s.info.r_o_error));
                }
            }
        }
    }
    for (tol, t) in tols.iter().zip(&mut tally) {
        t.ratios.sort_by(f64::total_cmp);
        println!(
            "\ntolerance {tol:e}: {} geometries compared (FE converged), {} FE not converged {:?}, {} failed {:?}",
            t.ratios.len(),
            t.unconverged.len(),
            t.unconverged,
            t.failures.len(),
            t.failures
        );
        if let Some(max) = t.ratios.last() {
            println!(
                "|FE − semi| / FE estimate: median {:.2}, p99 {:.2}, max {max:.2}; above 1 on {}",
                quantile(&t.ratios, 0.5),
                quantile(&t.ratios, 0.99),
                t.ratios.iter().filter(|&&r| r > 1.0).count()
            );
        }
    }
    println!("wall time {:.0} s", start.elapsed().as_secs_f64());
    for (tol, t) in tols.iter().zip(&tally) {
        assert!(
            t.beyond.is_empty(),
            "tolerance {tol:e}: FE and semi route disagree beyond both estimates \
             (A/D, B/A, FE − semi, FE est, semi est; absolute, in): {:?}",
            t.beyond
        );
    }
}
