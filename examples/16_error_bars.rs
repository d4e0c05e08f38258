//! # Error bars that hold: every route's estimate against a much tighter reference
//!
//! Every R_o comes with an estimated error and a `converged` flag. This example draws random
//! geometries (seeded, so every run draws the same) and holds each route's estimate, at each of
//! its working tolerances, against a reference 100 times tighter or a second method:
//!
//! | route (key) | working `tolerance`s | reference |
//! |---|---|---|
//! | slab, no hole, Hankel (`slab`) | 1e-4, 1e-6, 1e-8, 1e-10 | the same route at 1e-12 |
//! | single plate, Hankel + hole (`hankel`) | 1e-3, 1e-4, 1e-5 | the same route at 1e-7 |
//! | single plate, FE (`fe`; `fe1`: Table 1's range) | 1e-3, 1e-4, 1e-5 | the Hankel route with hole and rim at 1e-7 (shares no code) |
//! | two plates, equal (`two`) | 1e-3, 1e-4 | the same route on eight levels |
//! | two plates, unequal, frictionless (`two2`) | 1e-3, 1e-4 | the same route on eight levels |
//! | two equal infinite plates, no hole (`two0`; the case's B, A = 0) | 1e-4, 1e-5, 1e-6 | the receding contact, Hankel (~1e-12, shares no code) |
//! | two unequal infinite plates, no hole, frictionless (`two0u`; own B, D₂, E₂, ν₂) | 1e-4, 1e-5 | the receding contact of the pair, Hankel (~1e-12, shares no code) |
//!
//! The two-plate reference (eight levels) carries the 2e-5 of R_o that every two-plate estimate
//! carries; its own estimate is added to the bar. Geometry (D = 1): A/D log-uniform in [0.1, 10], B/A in [1.05, 10] (`fe1`: A/D in
//! [0.3, 1.5], B/A in [1.2, 8]), ν in [0, 0.45]; half the plates finite with C/B in [1.5, 20];
//! the lower plate of an unequal pair 0.3–3 times as thick. A case whose reference did not
//! converge is skipped. For every run that says `converged` the actual error |R − R_ref| must
//! not exceed its estimate plus the reference's (the example fails otherwise); it prints, per
//! route and tolerance, the median, 99th percentile and maximum of actual/estimate.
//!
//! Measured (200 cases per route, 2026-11-24, release build at load 10–17; skipped: reference
//! not converged or outside the route's reach):
//!
//! | route | tol | converged | actual/estimate median | p99 | max | > 1 |
//! |---|---|---|---|---|---|---|
//! | slab | 1e-4 / 1e-6 / 1e-8 / 1e-10 | 200 each | 9.4e-2 / 7.0e-4 / 3.3e-2 / 3.6e-5 | 0.40 / 0.45 / 0.30 / 0.42 | 0.45 / 0.46 / 0.41 / 0.46 | 0 |
//! | single, Hankel + hole | 1e-3 / 1e-4 / 1e-5 | 171 each | 2.9e-4 / 4.7e-4 / 3.4e-3 | 5.7e-3 / 0.29 / 0.51 | 0.018 / 0.58 / 0.83 | 0 |
//! | single, FE | 1e-3 / 1e-4 / 1e-5 | 172 each | 0.066 / 0.086 / 0.14 | 0.34 / 0.42 / 0.54 | 0.42 / 0.84 / 0.84 | 0 |
//! | single FE, Table 1 range | 1e-4 / 1e-5 | 184 each | 0.073 / 0.14 | 0.49 / 0.58 | 0.71 / 0.80 | 0 |
//! | two plates, equal | 1e-3 / 1e-4 | 171 each | 0.092 / 0.015 | 0.55 / 0.14 | 0.60 / 0.16 | 0 |
//! | two plates, unequal | 1e-3 / 1e-4 | 188 each | 0.096 / 0.018 | 0.49 / 0.20 | 0.57 / 0.26 | 0 |
//! | two plates, no hole, vs Hankel | 1e-4 / 1e-5 / 1e-6 | 200 / 0 / 0 | 0.057 | 0.25 | 0.50 | 0 |
//! | two unequal plates, no hole, vs Hankel | 1e-4 / 1e-5 | 200 / 0 | 0.078 | 0.32 | 0.33 | 0 |
//!
//! (The three two-plate rows: 2026-11-24 15:00–15:24 UTC, release, load 3–4, after the cut of
//! an infinite plate became exact (`fem::exterior`) and the two-plate estimate gained its floor
//! of 2e-5 of R_o and, below the default tolerance, its cautious form (`contact::two_plate`):
//! no run claims 1e-5 or 1e-6 any more. The two-plate references are eight levels, used where
//! their bar is below 5e-5 of R_o, so those rows hold the estimate against a reference only
//! 2–5× tighter at 1e-4; the `two0` row's reference is the receding contact, ~1e-12. With the
//! exterior but the old estimate, `two0` had 32 converged runs beyond their bars, 1 at 1e-4
//! (2.56×), 12 at 1e-5 and 19 at 1e-6 (up to 10×): the slow hump of the FE's R_o that the
//! floor now covers. Earlier, 166 / 142 converged equal / unequal runs held at 1e-3 and 1e-4
//! with maxima 0.81 / 0.79 against the FE at 1e-5.)
//!
//! The `two0u` row (2026-11-24 17:30–18:04 UTC, release, load 5–8, 2,030 s for 200 cases, none
//! skipped): B/D₁ in [0.1, 10], D₂/D₁ in [0.25, 4], E₂/E₁ in [1e-2, 1e2], ν₁, ν₂ in [0, 0.45], A = 0,
//! infinite plates, frictionless; the reference is `hankel::receding::Pair` (estimates ~1e-12 of
//! R_o, shares no code with the FE). At 1e-4 all 200 FE runs say `converged` and every one is
//! within its bar (largest actual/estimate 0.33); at 1e-5 none says `converged` (the 2e-5 floor).
//!
//! (The single-Hankel row: 2026-11-24, before 18:30 UTC, after R_o alone learned to leave a far rim
//! unfitted with its bound in the estimate and to sample the slab to 2e-3 of the tolerance,
//! `HoleParams::for_tolerance`; before, 172 converged each, maxima 0.16 / 0.84 / 0.85, 0 over.)
//!
//! Before the single plate's grading shrank from h = D/8 at tolerances below 1e-4
//! (`fem::single::FIXED_GRADING_TOLERANCE`) its FE at 1e-5 had 5 of 172 (wide) and 10 of 183
//! (Table 1 range) converged runs over their estimate, up to 1.71×.
//!
//! Run: `cargo run --release --example 16_error_bars [cases per route] [route keys…]`
//! (default 200 cases, every route; `BOLTZONE_QUICK=1`: 2 cases).
//!
//! Builds on: examples 01 (slab), 05 (hole correction), 03 and 04 (the FE single and two-plate
//! models), and the `Value` convention of `boltzone::value` (error and `converged` everywhere).

use boltzone::contact::two_plate::{solve as solve_two, InterfaceModel, TwoPlateParams};
use boltzone::fem::single::{solve as solve_single, SingleParams};
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::receding::{Layer, Pair, RecedingParams};
use boltzone::hankel::{SeparationParams, Slab};
use boltzone::numerics::random::SplitMix64 as Rng;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate, SinglePlate};

/// One random geometry (D = 1).
#[derive(Debug, Clone, Copy)]
struct Case {
    a: f64,
    b: f64,
    c: Option<f64>,
    nu: f64,
    d2: f64,
}

/// A/D log-uniform in [a_lo, a_hi], B/A in [b_lo, b_hi]; C/B in [1.5, 20] or infinite.
fn draw(rng: &mut Rng, (a_lo, a_hi, b_lo, b_hi): (f64, f64, f64, f64)) -> Case {
    let a = rng.log_uniform(a_lo, a_hi);
    let b = a * rng.log_uniform(b_lo, b_hi);
    let c = (rng.unit() < 0.5).then(|| b * rng.log_uniform(1.5, 20.0));
    Case {
        a,
        b,
        c,
        nu: 0.45 * rng.unit(),
        d2: rng.log_uniform(0.3, 3.0),
    }
}

/// The wide range of every route, and Table 1's neighbourhood.
const WIDE: (f64, f64, f64, f64) = (0.1, 10.0, 1.05, 10.0);
const TABLE1: (f64, f64, f64, f64) = (0.3, 1.5, 1.2, 8.0);

/// (value, estimate, converged) of one run.
type Run = (f64, f64, bool);

/// The working runs of a route (one per tolerance) and the reference (value, estimate), or
/// None where the route declines the case or its reference did not converge.
type Outcome = Option<(Vec<Run>, (f64, f64))>;

fn outer(c: Option<f64>) -> OuterRadius {
    c.map_or(OuterRadius::Infinite, OuterRadius::Finite)
}

fn slab(k: &Case, tols: &[f64]) -> anyhow::Result<Outcome> {
    let s = Slab::new(
        1.0,
        Material::unit(k.nu)?,
        FaceLoad::uniform(k.a, k.b, 1.0)?,
    )?;
    let at = |t: f64| -> anyhow::Result<Run> {
        let v = s.separation_radius(&SeparationParams {
            rel_tol: t,
            ..Default::default()
        })?;
        Ok((v.r_o, v.r_o_error, v.converged))
    };
    let r = at(1e-12)?;
    let runs = tols.iter().map(|&t| at(t)).collect::<anyhow::Result<_>>()?;
    Ok(r.2.then_some((runs, (r.0, r.1))))
}

fn hankel(plate: &SinglePlate, tol: f64) -> anyhow::Result<Run> {
    let sep = SeparationParams {
        rel_tol: 1e-3 * tol,
        ..Default::default()
    };
    // as `single --method hankel` and the scenes
    let hole = HoleParams::for_tolerance(tol);
    let (s, _) = single_plate_separation(plate, &sep, &hole)?;
    Ok((s.r_o, s.r_o_error, s.converged))
}

fn single_plate(k: &Case) -> anyhow::Result<SinglePlate> {
    Ok(SinglePlate::new(
        k.a,
        outer(k.c),
        1.0,
        Material::unit(k.nu)?,
        FaceLoad::uniform(k.a, k.b, 1.0)?,
    )?)
}

/// The Hankel route with the hole, at 1e-7 (100× the tightest working tolerance, 1e-5).
fn hankel_reference(p: &SinglePlate) -> anyhow::Result<Option<(f64, f64)>> {
    let r = hankel(p, 1e-7)?;
    Ok(r.2.then_some((r.0, r.1)))
}

fn single_hankel(k: &Case, tols: &[f64]) -> anyhow::Result<Outcome> {
    let p = single_plate(k)?;
    let Some(r) = hankel_reference(&p)? else {
        return Ok(None);
    };
    let runs = tols
        .iter()
        .map(|&t| hankel(&p, t))
        .collect::<anyhow::Result<_>>()?;
    Ok(Some((runs, r)))
}

fn single_fem(k: &Case, tols: &[f64]) -> anyhow::Result<Outcome> {
    let p = single_plate(k)?;
    let Some(r) = hankel_reference(&p)? else {
        return Ok(None);
    };
    let at = |t: f64| -> anyhow::Result<Run> {
        let params = SingleParams {
            tolerance: t,
            levels: 8,
            ..Default::default()
        };
        let s = solve_single(&p, &params)?;
        Ok((s.r_o, s.r_o_error, s.converged))
    };
    let runs = tols.iter().map(|&t| at(t)).collect::<anyhow::Result<_>>()?;
    Ok(Some((runs, r)))
}

fn two(k: &Case, tols: &[f64], unequal: bool) -> anyhow::Result<Outcome> {
    let m = Material::unit(k.nu)?;
    let joint = Joint::new(
        k.a,
        outer(k.c),
        Plate::new(1.0, m)?,
        Plate::new(if unequal { k.d2 } else { 1.0 }, m)?,
        FaceLoad::uniform(k.a, k.b, 1.0)?,
    )?;
    let at = |t: f64| -> anyhow::Result<Run> {
        let s = solve_two(
            &joint,
            &TwoPlateParams {
                tolerance: t,
                interface: InterfaceModel::Frictionless,
                ..Default::default()
            },
        )?;
        Ok((s.r_o, s.r_o_error, s.converged))
    };
    // the two-plate model's reach (README): B within 10³ thicknesses of the thinner plate
    if k.b / k.d2.min(1.0) > 1e3 {
        return Ok(None);
    }
    // the reference: eight levels (no FE two-plate run claims 1e-5 any more: every estimate
    // carries 2e-5 of R_o, `contact::two_plate`), used where its bar is below 5e-5 of R_o
    let s = solve_two(
        &joint,
        &TwoPlateParams {
            tolerance: 1e-12,
            min_levels: 8,
            max_levels: 8,
            interface: InterfaceModel::Frictionless,
            ..Default::default()
        },
    )?;
    let r = (s.r_o, s.r_o_error, s.r_o_error < 5e-5 * s.r_o);
    if !r.2 {
        return Ok(None);
    }
    let runs = tols.iter().map(|&t| at(t)).collect::<anyhow::Result<_>>()?;
    Ok(Some((runs, (r.0, r.1))))
}

/// The FE two-plate model with a frictionless interface at each tolerance of `tols`.
fn frictionless_runs(joint: &Joint, tols: &[f64]) -> anyhow::Result<Vec<Run>> {
    let at = |t: f64| -> anyhow::Result<Run> {
        let params = TwoPlateParams {
            tolerance: t,
            interface: InterfaceModel::Frictionless,
            ..Default::default()
        };
        let s = solve_two(joint, &params)?;
        Ok((s.r_o, s.r_o_error, s.converged))
    };
    tols.iter().map(|&t| at(t)).collect()
}

/// Two equal infinite plates without a hole (A = 0, the load over r ≤ B of the case) against the
/// semi-analytic receding contact (`hankel::receding`, ~1e-12, shares no code with the FE).
fn two_no_hole(k: &Case, tols: &[f64]) -> anyhow::Result<Outcome> {
    let m = Material::unit(k.nu)?;
    let load = FaceLoad::uniform(0.0, k.b, 1.0)?;
    let reference =
        Layer::new(1.0, m, load.clone())?.receding_contact(&RecedingParams::default())?;
    let joint = Joint::new(
        0.0,
        OuterRadius::Infinite,
        Plate::new(1.0, m)?,
        Plate::new(1.0, m)?,
        load,
    )?;
    let runs = frictionless_runs(&joint, tols)?;
    Ok(Some((runs, (reference.r_o, reference.info.r_o_error))))
}

/// Two unequal infinite plates without a hole, frictionless, against the semi-analytic pair
/// (`hankel::receding::Pair`, ~1e-12, shares no code with the FE). The geometry comes from its
/// own generator seeded by the case (so the other routes' draws stay as they were): B/D₁
/// log-uniform in [0.1, 10], D₂/D₁ in [0.25, 4], E₂/E₁ in [1e-2, 1e2], ν₁ the case's, ν₂ in
/// [0, 0.45]; the reference is used where its estimate is below 1e-9 of R_o.
fn two_unequal_no_hole(k: &Case, tols: &[f64]) -> anyhow::Result<Outcome> {
    let (upper, lower, load) = unequal_pair(k)?;
    let reference =
        Pair::new(upper, lower, load.clone()).receding_contact(&RecedingParams::default())?;
    if reference.info.r_o_error > 1e-9 * reference.r_o {
        return Ok(None);
    }
    let joint = Joint::new(0.0, OuterRadius::Infinite, upper, lower, load)?;
    let runs = frictionless_runs(&joint, tols)?;
    let (rv, re) = (reference.r_o, reference.info.r_o_error);
    if runs.iter().any(|&(v, e, c)| c && (v - rv).abs() > e + re) {
        // the case's printout does not hold this route's geometry
        let (m1, m2) = (upper.material(), lower.material());
        println!(
            "  two0u geometry: B = {}, D1 = 1, E1 = 1, nu1 = {}, D2 = {}, E2 = {}, nu2 = {}",
            joint.load().outer(),
            m1.poisson_ratio(),
            lower.thickness(),
            m2.youngs_modulus(),
            m2.poisson_ratio()
        );
    }
    Ok(Some((runs, (rv, re))))
}

/// The plates and load of route `two0u` for case `k` (D₁ = 1, E₁ = 1).
fn unequal_pair(k: &Case) -> anyhow::Result<(Plate, Plate, FaceLoad)> {
    let mut rng = Rng::new(k.a.to_bits() ^ k.b.to_bits().rotate_left(17));
    let b = rng.log_uniform(0.1, 10.0);
    let d2 = rng.log_uniform(0.25, 4.0);
    let e2 = rng.log_uniform(1e-2, 1e2);
    let nu2 = 0.45 * rng.unit();
    Ok((
        Plate::new(1.0, Material::new(1.0, k.nu)?)?,
        Plate::new(d2, Material::new(e2, nu2)?)?,
        FaceLoad::uniform(0.0, b, 1.0)?,
    ))
}

type Solver = fn(&Case, &[f64]) -> anyhow::Result<Outcome>;

/// A route of the survey: name, solver, working tolerances, geometry range.
struct Route {
    key: &'static str,
    name: &'static str,
    solve: Solver,
    tols: &'static [f64],
    range: (f64, f64, f64, f64),
}

#[rustfmt::skip]
const ROUTES: [Route; 8] = [
    route("slab", "slab (Hankel)", slab, &[1e-4, 1e-6, 1e-8, 1e-10], WIDE),
    route("hankel", "single, Hankel + hole", single_hankel, &[1e-3, 1e-4, 1e-5], WIDE),
    route("fe", "single, FE vs Hankel", single_fem, &[1e-3, 1e-4, 1e-5], WIDE),
    route("fe1", "single FE, Table 1 range", single_fem, &[1e-4, 1e-5], TABLE1),
    route("two", "two plates, equal", |k, t| two(k, t, false), &[1e-3, 1e-4], WIDE),
    route("two2", "two plates, unequal", |k, t| two(k, t, true), &[1e-3, 1e-4], WIDE),
    route("two0", "two plates, no hole, vs Hankel", two_no_hole, &[1e-4, 1e-5, 1e-6], WIDE),
    route("two0u", "two unequal, no hole, vs Hankel", two_unequal_no_hole, &[1e-4, 1e-5], WIDE),
];

const fn route(
    key: &'static str,
    name: &'static str,
    solve: Solver,
    tols: &'static [f64],
    range: (f64, f64, f64, f64),
) -> Route {
    Route {
        key,
        name,
        solve,
        tols,
        range,
    }
}

/// The p-quantile of sorted `v` (NaN when empty).
fn quantile(v: &[f64], p: f64) -> f64 {
    v.get(((v.len() as f64 - 1.0) * p).round() as usize)
        .copied()
        .unwrap_or(f64::NAN)
}

/// Runs `n` cases of `route`; returns the number of converged estimates exceeded.
fn run_route(route: &Route, n: usize) -> anyhow::Result<usize> {
    let mut rng = Rng::new(0xE44_0B42);
    let nt = route.tols.len();
    let (mut ratios, mut conv) = (vec![Vec::new(); nt], vec![0; nt]);
    let (mut skipped, mut exceeded) = (0, 0);
    let t0 = std::time::Instant::now();
    for _ in 0..n {
        let k = draw(&mut rng, route.range);
        let Ok(Some((runs, (rv, re)))) = (route.solve)(&k, route.tols) else {
            skipped += 1;
            continue;
        };
        for (i, &(v, e, c)) in runs.iter().enumerate() {
            let actual = (v - rv).abs();
            if !c {
                continue;
            }
            conv[i] += 1;
            ratios[i].push(actual / e.max(f64::MIN_POSITIVE));
            if actual > e + re {
                exceeded += 1;
                println!(
                    "  EXCEEDED {} at {:.0e}: {k:?}: R = {v} ± {e:.2e}, reference {rv} ± {re:.1e}, actual {actual:.2e} ({:.2}×)",
                    route.name, route.tols[i], actual / e
                );
            }
        }
    }
    for (i, r) in ratios.iter_mut().enumerate() {
        r.sort_by(f64::total_cmp);
        println!(
            "{:<26} {:>7.0e} {n:>5} {skipped:>5} {:>5}  {:>9.2e} {:>9.2e} {:>9.2e} {:>5}",
            route.name,
            route.tols[i],
            conv[i],
            quantile(r, 0.5),
            quantile(r, 0.99),
            quantile(r, 1.0),
            r.iter().filter(|&&x| x > 1.0).count()
        );
    }
    println!("  ({} s)", t0.elapsed().as_secs());
    Ok(exceeded)
}

/// Runs `n` cases of the routes whose keys are in `keys` (all when empty); returns the number
/// of converged estimates exceeded.
pub fn run(n: usize, keys: &[String]) -> anyhow::Result<usize> {
    println!(
        "{:<26} {:>7} {:>5} {:>5} {:>5}  actual/estimate: median, p99, max, > 1",
        "route", "tol", "cases", "skip", "conv."
    );
    let mut exceeded = 0;
    for route in ROUTES
        .iter()
        .filter(|r| keys.is_empty() || keys.iter().any(|k| k == r.key))
    {
        exceeded += run_route(route, n)?;
    }
    Ok(exceeded)
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let args: Vec<String> = if quick {
        Vec::new()
    } else {
        std::env::args().skip(1).collect()
    };
    let n = match args.first() {
        Some(s) => s.parse()?,
        None if quick => 2,
        None => 200,
    };
    let exceeded = run(n, args.get(1..).unwrap_or(&[]))?;
    anyhow::ensure!(
        exceeded == 0,
        "{exceeded} converged estimates exceeded by their actual error"
    );
    Ok(())
}
