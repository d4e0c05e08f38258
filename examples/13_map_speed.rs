//! # Design-map speed: time per point against the error achieved
//!
//! `boltzone map` computes, at every point of A/D × B/A, the single-plate R_o (FE, finite rim
//! C = 15.4 A) and the two-plate R_o, each to a relative tolerance (default 1e-3) by its own
//! error estimate. This example times both models at sample points of the map and checks each
//! estimate against a reference converged 50 times tighter:
//!
//! - single plate: [`boltzone::compare::single::single_fem`] (graded refinement levels, error
//!   max(|d₃|, |d₂|/4, |d₁|/16) of the last three level changes, no extrapolation);
//! - two plates: [`boltzone::contact::two_plate::solve`] (same estimate).
//!
//! For each point it prints CPU milliseconds (this thread's, from /proc/thread-self/schedstat
//! on Linux; wall time elsewhere), levels, equations of the finest mesh, the estimate and the
//! actual error relative to R_o, and their ratio. It fails if an estimate exceeds the
//! tolerance or if an actual error exceeds its estimate plus the reference's own estimate.
//!
//! Run: `cargo run --release --example 13_map_speed [n] [tolerance]`: an n × n log-spaced grid
//! over A/D ∈ [0.2, 5] × B/A ∈ [1.1, 5] plus Table 1's twelve geometries (default n = 6,
//! tolerance 1e-3).
//!
//! Builds on: examples 03 and 04 (the two models, timed over the map).

use boltzone::compare::map::log_spaced;
use boltzone::compare::single::single_fem;
use boltzone::compare::Geometry;
use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::OuterRadius;
use std::time::Instant;

/// One model at one point.
#[derive(Debug, Clone, Copy)]
pub struct ModelRun {
    /// CPU (or wall) seconds at the tolerance.
    pub seconds: f64,
    /// Levels solved.
    pub levels: usize,
    /// Equations of the finest level.
    pub dofs: usize,
    /// Estimated relative error.
    pub estimate: f64,
    /// Actual relative error against the reference.
    pub actual: f64,
    /// The reference's own estimated relative error.
    pub reference_estimate: f64,
}

/// Both models at one point.
#[derive(Debug, Clone, Copy)]
pub struct PointRun {
    /// A/D.
    pub a_over_d: f64,
    /// B/A.
    pub b_over_a: f64,
    /// Single plate (FE).
    pub single: ModelRun,
    /// Two plates.
    pub two: ModelRun,
}

/// The quick set: the four corners of the map's range and Table 1's narrowest load (A/D 1,
/// B/A 1.3).
pub const QUICK_POINTS: [(f64, f64); 5] =
    [(0.2, 1.1), (0.2, 5.0), (5.0, 1.1), (5.0, 5.0), (1.0, 1.3)];

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        return run(&QUICK_POINTS, 1e-3).map(|runs| summary(&runs, 1e-3));
    }
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(6);
    let tol: f64 = args.next().map(|s| s.parse()).transpose()?.unwrap_or(1e-3);
    let mut points = Vec::new();
    for &ad in &log_spaced(0.2, 5.0, n) {
        for &ba in &log_spaced(1.1, 5.0, n) {
            points.push((ad, ba));
        }
    }
    points.extend(
        Geometry::table1()
            .iter()
            .map(|g| (g.a_over_d(), g.b_over_a())),
    );
    let runs = run(&points, tol)?;
    summary(&runs, tol);
    Ok(())
}

/// This thread's CPU seconds (Linux), or None.
fn cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = s.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}

/// Seconds spent in `f`: CPU time of this thread where available, else wall time.
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let (c0, w0) = (cpu_seconds(), Instant::now());
    let out = f();
    let s = match (c0, cpu_seconds()) {
        (Some(a), Some(b)) => b - a,
        _ => w0.elapsed().as_secs_f64(),
    };
    (out, s)
}

/// Times both models at `points` (A/D, B/A) with C = 15.4 A, ν = 0.3 at tolerance `tol`,
/// checks their estimates against references converged to `tol`/50, prints one line per point.
pub fn run(points: &[(f64, f64)], tol: f64) -> anyhow::Result<Vec<PointRun>> {
    let tight = tol / 50.0;
    println!(
        "{:>6} {:>6} | single: {:>6} {:>3} {:>6} {:>8} {:>8} {:>5} | two: {:>6} {:>3} {:>6} {:>8} {:>8} {:>5}",
        "A/D", "B/A", "ms", "lv", "dofs", "est", "actual", "ratio", "ms", "lv", "dofs", "est",
        "actual", "ratio"
    );
    let mut out = Vec::new();
    for &(ad, ba) in points {
        let g = Geometry::from_ratios(0.1, ad, ba, 1.54, 0.3)?;
        let plate = g.single_plate(OuterRadius::Finite(g.c))?;
        let (res, seconds) = timed(|| single_fem(&plate, tol));
        let (s, study) = res?;
        let (reference, _) = single_fem(&plate, tight)?;
        let single = ModelRun {
            seconds,
            levels: study.levels,
            dofs: study.dofs,
            estimate: s.error / s.value,
            actual: (s.value - reference.value).abs() / reference.value,
            reference_estimate: reference.error / reference.value,
        };
        let joint = g.joint()?;
        let params = |tolerance| TwoPlateParams {
            tolerance,
            max_levels: 12,
            ..Default::default()
        };
        let (res, seconds) = timed(|| solve(&joint, &params(tol)));
        let t = res?;
        let reference = solve(&joint, &params(tight))?;
        let two = ModelRun {
            seconds,
            levels: t.info.levels.len(),
            dofs: t.info.levels.last().map_or(0, |l| l.dofs),
            estimate: t.r_o_error / t.r_o,
            actual: (t.r_o - reference.r_o).abs() / reference.r_o,
            reference_estimate: reference.r_o_error / reference.r_o,
        };
        let show = |m: &ModelRun| {
            format!(
                "{:>6.1} {:>3} {:>6} {:>8.1e} {:>8.1e} {:>5.2}",
                m.seconds * 1e3,
                m.levels,
                m.dofs,
                m.estimate,
                m.actual,
                m.actual / m.estimate
            )
        };
        println!(
            "{ad:>6.3} {ba:>6.3} | single: {} | two: {}",
            show(&single),
            show(&two)
        );
        for (name, m) in [("single", &single), ("two-plate", &two)] {
            if m.estimate > tol {
                anyhow::bail!(
                    "{name} at A/D {ad}, B/A {ba}: estimate {:e} > tolerance",
                    m.estimate
                );
            }
            if m.actual > m.estimate + m.reference_estimate {
                anyhow::bail!(
                    "{name} at A/D {ad}, B/A {ba}: actual error {:e} > estimate {:e} (+ reference's {:e})",
                    m.actual,
                    m.estimate,
                    m.reference_estimate
                );
            }
        }
        out.push(PointRun {
            a_over_d: ad,
            b_over_a: ba,
            single,
            two,
        });
    }
    Ok(out)
}

/// Prints means and worst cases over the runs.
pub fn summary(runs: &[PointRun], tol: f64) {
    let n = runs.len() as f64;
    for (name, pick) in [
        (
            "single",
            (|r: &PointRun| r.single) as fn(&PointRun) -> ModelRun,
        ),
        ("two-plate", |r: &PointRun| r.two),
    ] {
        let ms = runs.iter().map(|r| pick(r).seconds).sum::<f64>() / n * 1e3;
        let worst = runs
            .iter()
            .map(|r| pick(r).actual / pick(r).estimate)
            .fold(0.0, f64::max);
        let worst_actual = runs.iter().map(|r| pick(r).actual).fold(0.0, f64::max);
        let levels = runs.iter().map(|r| pick(r).levels as f64).sum::<f64>() / n;
        println!(
            "{name}: {ms:.1} ms per point, {levels:.2} levels on average; actual/estimate ≤ {worst:.2}; \
             actual ≤ {worst_actual:.1e} (tolerance {tol:e})"
        );
    }
}
