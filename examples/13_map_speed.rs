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
//! **By method** (`cargo run --release --example 13_map_speed map [n] [tolerance]`, default
//! n = 6): the n × n map over the part of the design map the two-plate Hankel route reaches
//! with the rim (A/D ∈ [0.2, 1.6] × B/A ∈ [1.1, 5]: B/D ≤ 8), computed as `boltzone map` does
//! (rayon over points), once by the FE (`--method fem`) and once by `--method hankel` (both
//! models by their Hankel routes, [`boltzone::compare::route`]; `auto` would keep the FE for the
//! two plates at tolerances above 3e-5), each timed by wall clock and by the process's
//! CPU (user + system, /proc/self/stat). Where a model ran by both routes it prints the
//! largest |FE − Hankel| / (e_FE + e_Hankel), which must not exceed 1 (the example fails
//! otherwise), and every point's estimate against the tolerance; then where the time goes:
//! each route's seconds per point (in-thread wall clock) by A/D row and by B/D, the slowest
//! points, and the schedule's efficiency CPU/(wall × threads). Quick mode (`BOLTZONE_QUICK=1`)
//! runs the per-point study on five points and this one on a 3 × 1 map (A/D 0.5, 1, 2 at
//! B/A 2.2: B/D 1.1, 2.2, 4.4).
//!
//! Builds on: examples 03 and 04 (the two models, timed over the map) and 19 (the two-plate
//! Hankel route).

use boltzone::compare::map::{compute, log_spaced, DesignMap, MapParams};
use boltzone::compare::single::single_fem;
use boltzone::compare::{compare, CompareParams, Comparison, Geometry, Method, Route, Value};
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
        summary(&run(&QUICK_POINTS, 1e-3)?, 1e-3);
        return by_method(&[0.5, 1.0, 2.0], &[2.2], 1e-3, false).map(|_| ());
    }
    let mut args = std::env::args().skip(1).peekable();
    if args.peek().is_some_and(|a| a == "map") {
        args.next();
        let n: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(6);
        let tol: f64 = args.next().map(|s| s.parse()).transpose()?.unwrap_or(1e-3);
        // B/D = (A/D)(B/A) ≤ 8 with the rim: the two-plate Hankel route's reach
        let axes = (log_spaced(0.2, 1.6, n), log_spaced(1.1, 5.0, n));
        return by_method(&axes.0, &axes.1, tol, true).map(|_| ());
    }
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

/// The process's CPU seconds, user + system of all threads (Linux, /proc/self/stat in clock
/// ticks of 1/100 s), or None.
fn process_cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/stat").ok()?;
    // fields after the command name in parentheses: state is field 3, utime 14, stime 15
    let rest = &s[s.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// Computes the map over `a_over_d` × `b_over_a` by the FE and by the Hankel routes (every
/// point within the two-plate route's reach), prints times, the agreement of the two routes and
/// where the time goes (with `per_point`, each point of the Hankel map again, one at a time, timed by the process's CPU: the Hankel routes use rayon
/// inside, so a thread's clock misses part of their work); fails if an FE–Hankel difference
/// exceeds the sum of the two estimates or a converged value's estimate exceeds `tol`. Returns
/// the largest |FE − Hankel| / (e_FE + e_Hankel) of each model (single, two plates; 0 where no
/// point ran by both routes).
pub fn by_method(
    a_over_d: &[f64],
    b_over_a: &[f64],
    tol: f64,
    per_point: bool,
) -> anyhow::Result<(f64, f64)> {
    let threads = rayon::current_num_threads();
    let mut maps = Vec::new();
    for method in [Method::Fem, Method::Hankel] {
        let params = MapParams {
            a_over_d: a_over_d.to_vec(),
            b_over_a: b_over_a.to_vec(),
            tolerance: tol,
            method,
            ..MapParams::default()
        };
        let (c0, w0) = (process_cpu_seconds(), Instant::now());
        let map = compute(&params, &|| ())?;
        let wall = w0.elapsed().as_secs_f64();
        let cpu = match (c0, process_cpu_seconds()) {
            (Some(a), Some(b)) => b - a,
            _ => f64::NAN,
        };
        let ((sh, th), n) = (map.count(Route::Hankel), map.points.len());
        println!(
            "map {} x {} by {method:?} at {tol:e}: wall {wall:.2} s, CPU {cpu:.2} s on {threads} \
             threads (efficiency CPU/(wall x threads) {:.2}); Hankel at {sh} (single) and {th} \
             (two plates) of {n} points",
            a_over_d.len(),
            b_over_a.len(),
            cpu / (wall * threads as f64)
        );
        for (k, c) in map.points.iter().enumerate() {
            for (name, v) in [("single", c.single), ("two-plate", c.two)] {
                if v.converged && v.error > tol * v.value {
                    anyhow::bail!("{name} at point {k}: estimate {:e} > tolerance", v.error);
                }
            }
        }
        let unconverged = map.points.iter().filter(|c| !c.converged()).count();
        println!("  points not converged: {unconverged} of {n}");
        maps.push(map);
    }
    let (fem, hankel) = (&maps[0], &maps[1]);
    let worst_ratio = agreement(fem, hankel)?;
    if per_point {
        let cp = CompareParams {
            tolerance: tol,
            method: Method::Hankel,
            ..CompareParams::default()
        };
        let mut cpu = Vec::new();
        for c in &hankel.points {
            let c0 = process_cpu_seconds();
            compare(&c.geometry, &cp)?;
            cpu.push(match (c0, process_cpu_seconds()) {
                (Some(a), Some(b)) => b - a,
                _ => c.info.seconds,
            });
        }
        time_breakdown(hankel, &cpu, threads);
    }
    Ok(worst_ratio)
}

/// |FE − Hankel| / (e_FE + e_Hankel) for each model where the second map took the Hankel
/// route; prints the largest and fails above 1.
fn agreement(fem: &DesignMap, hankel: &DesignMap) -> anyhow::Result<(f64, f64)> {
    type Pick = fn(&Comparison) -> (Value, Route);
    let models: [(&str, Pick); 2] = [
        ("single plate", |c| (c.single, c.single_method)),
        ("two plates", |c| (c.two, c.two_method)),
    ];
    let mut worst = [0.0; 2];
    for (m, (name, pick)) in models.iter().enumerate() {
        let mut at = None;
        let mut largest_estimate: f64 = 0.0;
        for (f, a) in fem.points.iter().zip(&hankel.points) {
            let ((vf, _), (va, route)) = (pick(f), pick(a));
            if route != Route::Hankel {
                continue;
            }
            largest_estimate = largest_estimate.max(va.error / va.value);
            let ratio = (vf.value - va.value).abs() / (vf.error + va.error);
            if ratio > worst[m] {
                worst[m] = ratio;
                at = Some((
                    a.geometry.a_over_d(),
                    a.geometry.b_over_a(),
                    a.over_a(vf),
                    a.over_a(va),
                ));
            }
        }
        match at {
            Some((ad, ba, vf, va)) => println!(
                "{name}: largest |FE - Hankel|/(e_FE + e_Hankel) = {:.3} at A/D {ad:.3}, B/A \
                 {ba:.3} (R_o/A FE {:.6} ± {:.1e}, Hankel {:.6} ± {:.1e}); largest Hankel \
                 estimate {largest_estimate:.1e} of R_o",
                worst[m], vf.value, vf.error, va.value, va.error
            ),
            None => println!("{name}: no point ran by the Hankel route"),
        }
        if worst[m] > 1.0 {
            anyhow::bail!("{name}: FE and Hankel differ by more than their two estimates");
        }
    }
    Ok((worst[0], worst[1]))
}

/// Where the Hankel map's time goes: `cpu[k]` is point k's CPU seconds run alone (both models);
/// split between the models by their in-thread wall-clock shares. Per route, and for the
/// two-plate Hankel route by A/D row and by B/D band; the slowest point against an even share.
fn time_breakdown(map: &DesignMap, cpu: &[f64], threads: usize) {
    let share = |c: &Comparison| c.info.seconds_two / (c.info.seconds_single + c.info.seconds_two);
    let mut parts = [0.0; 4]; // single hankel, single fem, two hankel, two fem
    for (c, &t) in map.points.iter().zip(cpu) {
        parts[usize::from(c.single_method == Route::Fem)] += t * (1.0 - share(c));
        parts[2 + usize::from(c.two_method == Route::Fem)] += t * share(c);
    }
    let sum: f64 = cpu.iter().sum();
    println!("  CPU per point, each point alone: {sum:.2} s in all");
    let names = [
        "single plate, hankel",
        "single plate, fem",
        "two plates, hankel",
        "two plates, fem",
    ];
    for (name, s) in names.iter().zip(parts) {
        println!("  {name}: {s:.2} s of CPU ({:.0} %)", 100.0 * s / sum);
    }
    println!(
        "  CPU seconds per point (both models) by A/D row, B/A increasing; * = two plates by fem:"
    );
    let nb = map.b_over_a.len();
    for (i, ad) in map.a_over_d.iter().enumerate() {
        let cells: Vec<String> = (i * nb..(i + 1) * nb)
            .map(|k| {
                let mark = if map.points[k].two_method == Route::Fem {
                    "*"
                } else {
                    " "
                };
                format!("{:6.2}{mark}", cpu[k])
            })
            .collect();
        println!("    A/D {ad:6.3}: {}", cells.join(" "));
    }
    let mut bands = [(0.0, 0usize); 4];
    for (c, &t) in map.points.iter().zip(cpu) {
        if c.two_method == Route::Hankel {
            let bd = c.geometry.b / c.geometry.d;
            let k = [1.0, 2.0, 4.0].iter().filter(|&&x| bd > x).count();
            bands[k].0 += t * share(c);
            bands[k].1 += 1;
        }
    }
    for (k, name) in ["B/D <= 1", "1 < B/D <= 2", "2 < B/D <= 4", "4 < B/D <= 8"]
        .iter()
        .enumerate()
    {
        if bands[k].1 > 0 {
            println!(
                "    two plates by Hankel, {name}: {:.2} s of CPU per point over {} points",
                bands[k].0 / bands[k].1 as f64,
                bands[k].1
            );
        }
    }
    let longest = cpu.iter().copied().fold(0.0, f64::max);
    println!(
        "  longest point {longest:.2} s of CPU; an even share of the sum over {threads} threads \
         {:.2} s; the parallel run's wall {:.2} s",
        sum / threads as f64,
        map.seconds
    );
}
