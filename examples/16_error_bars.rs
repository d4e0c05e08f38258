//! # Error bars that hold: every route's estimate against a much tighter reference
//!
//! Every R_o comes with an estimated error and a `converged` flag. This example draws random
//! geometries (seeded, so every run draws the same) and holds each route's estimate at a working
//! tolerance against a reference at least 100 times tighter, or against a second method:
//!
//! | route | working run | reference |
//! |---|---|---|
//! | slab (no hole, Hankel) | `rel_tol` 1e-6 | the same route at 1e-12 |
//! | single plate, Hankel + hole | `r_o_tolerance` 1e-4 | the same route at 1e-6 |
//! | single plate, FE, rim C | `tolerance` 1e-3 | the Hankel route with hole and rim C at 1e-6 (shares no code) |
//! | two plates, equal | `tolerance` 1e-3 | the same route at 1e-5 |
//! | two plates, unequal (frictionless) | `tolerance` 1e-3 | the same route at 1e-5 |
//!
//! Geometry (in units of the plate thickness D = 1): A/D log-uniform in [0.1, 10], B/A in
//! [1.05, 10], ν in [0, 0.45]; finite plates C/B in [1.5, 20], the rest infinite; the lower
//! plate of an unequal pair 0.3–3 times as thick. For every case that says `converged` the
//! actual error |R − R_ref| must not exceed the estimate plus the reference's own estimate
//! (the example fails otherwise); it prints the distribution of actual/estimate per route.
//!
//! Run: `cargo run --release --example 16_error_bars [cases per route]` (default 200;
//! `BOLTZONE_QUICK=1`: 3).
//!
//! Builds on: examples 01 (slab), 05 (hole correction), 03 and 04 (the FE single and two-plate
//! models), and the `Value` convention of `boltzone::value` (error and `converged` everywhere).

use boltzone::contact::two_plate::{solve as solve_two, InterfaceModel, TwoPlateParams};
use boltzone::fem::single::{solve as solve_single, SingleParams};
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
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

fn draw(rng: &mut Rng) -> Case {
    let a = rng.log_uniform(0.1, 10.0);
    let b = a * rng.log_uniform(1.05, 10.0);
    let c = (rng.unit() < 0.5).then(|| b * rng.log_uniform(1.5, 20.0));
    Case {
        a,
        b,
        c,
        nu: 0.45 * rng.unit(),
        d2: rng.log_uniform(0.3, 3.0),
    }
}

/// A route's (value, estimate, converged) and its reference's (value, estimate), or None where
/// the route declines the case (outside its reach).
type Outcome = Option<((f64, f64, bool), (f64, f64))>;

fn outer(c: Option<f64>) -> OuterRadius {
    c.map_or(OuterRadius::Infinite, OuterRadius::Finite)
}

fn slab(k: &Case) -> anyhow::Result<Outcome> {
    let s = Slab::new(
        1.0,
        Material::unit(k.nu)?,
        FaceLoad::uniform(k.a, k.b, 1.0)?,
    )?;
    let at = |t: f64| {
        s.separation_radius(&SeparationParams {
            rel_tol: t,
            ..Default::default()
        })
    };
    let (w, r) = (at(1e-6)?, at(1e-12)?);
    Ok(Some((
        (w.r_o, w.r_o_error, w.converged),
        (r.r_o, r.r_o_error),
    )))
}

fn hankel(plate: &SinglePlate, tol: f64) -> anyhow::Result<(f64, f64, bool)> {
    let sep = SeparationParams {
        rel_tol: 1e-3 * tol,
        ..Default::default()
    };
    let hole = HoleParams {
        r_o_tolerance: tol,
        ..Default::default()
    };
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

fn single_hankel(k: &Case) -> anyhow::Result<Outcome> {
    let p = single_plate(k)?;
    let w = hankel(&p, 1e-4)?;
    let r = hankel(&p, 1e-6)?;
    Ok(r.2.then_some((w, (r.0, r.1))))
}

fn single_fem(k: &Case) -> anyhow::Result<Outcome> {
    let p = single_plate(k)?;
    let s = solve_single(
        &p,
        &SingleParams {
            tolerance: 1e-3,
            levels: 8,
            ..Default::default()
        },
    )?;
    let r = hankel(&p, 1e-6)?;
    Ok(r.2.then_some(((s.r_o, s.r_o_error, s.converged), (r.0, r.1))))
}

fn two(k: &Case, unequal: bool) -> anyhow::Result<Outcome> {
    let m = Material::unit(k.nu)?;
    let joint = Joint::new(
        k.a,
        outer(k.c),
        Plate::new(1.0, m)?,
        Plate::new(if unequal { k.d2 } else { 1.0 }, m)?,
        FaceLoad::uniform(k.a, k.b, 1.0)?,
    )?;
    let at = |t: f64| {
        solve_two(
            &joint,
            &TwoPlateParams {
                tolerance: t,
                interface: InterfaceModel::Frictionless,
                ..Default::default()
            },
        )
    };
    // the two-plate model's reach (README): B within 10³ thicknesses of the thinner plate
    if k.b / k.d2.min(1.0) > 1e3 {
        return Ok(None);
    }
    let (w, r) = (at(1e-3)?, at(1e-5)?);
    Ok(r.converged
        .then_some(((w.r_o, w.r_o_error, w.converged), (r.r_o, r.r_o_error))))
}

/// Runs `n` cases of every route; returns the number of estimates exceeded.
pub fn run(n: usize) -> anyhow::Result<usize> {
    type Route = (&'static str, fn(&Case) -> anyhow::Result<Outcome>);
    let routes: [Route; 5] = [
        ("slab (Hankel)", slab),
        ("single, Hankel + hole", single_hankel),
        ("single, FE vs Hankel", single_fem),
        ("two plates, equal", |k| two(k, false)),
        ("two plates, unequal", |k| two(k, true)),
    ];
    let mut exceeded = 0;
    println!(
        "{:<24} {:>5} {:>5} {:>5}  actual/estimate: {:>8} {:>8} {:>8} {:>8}",
        "route", "cases", "conv.", "skip", "median", "p90", "max", "> 1"
    );
    for (name, route) in routes {
        let mut rng = Rng::new(0xE44_0B42);
        let (mut ratios, mut skipped, mut total) = (Vec::new(), 0, 0);
        for _ in 0..n {
            let k = draw(&mut rng);
            total += 1;
            match route(&k) {
                Ok(Some(((v, e, conv), (rv, re)))) => {
                    if !conv {
                        continue;
                    }
                    let actual = (v - rv).abs();
                    ratios.push(actual / e.max(f64::MIN_POSITIVE));
                    if actual > e + re {
                        exceeded += 1;
                        println!(
                            "  EXCEEDED {name}: {k:?}: R = {v} ± {e:.1e}, reference {rv} ± {re:.1e}, actual {actual:.1e}"
                        );
                    }
                }
                Ok(None) | Err(_) => skipped += 1,
            }
        }
        ratios.sort_by(f64::total_cmp);
        let q = |p: f64| {
            ratios
                .get(((ratios.len() as f64 - 1.0) * p).round() as usize)
                .copied()
                .unwrap_or(f64::NAN)
        };
        println!(
            "{name:<24} {total:>5} {:>5} {skipped:>5}  {:>24.2e} {:>8.2e} {:>8.2e} {:>8}",
            ratios.len(),
            q(0.5),
            q(0.9),
            q(1.0),
            ratios.iter().filter(|&&r| r > 1.0).count()
        );
    }
    Ok(exceeded)
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let n = if quick {
        3
    } else {
        std::env::args()
            .nth(1)
            .map(|s| s.parse())
            .transpose()?
            .unwrap_or(200)
    };
    let exceeded = run(n)?;
    anyhow::ensure!(
        exceeded == 0,
        "{exceeded} converged estimates exceeded by their actual error"
    );
    Ok(())
}
