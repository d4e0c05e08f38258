//! Work–precision of the infinite-slab solver (no hole): R_o for Table 1's geometries and the
//! midplane curve at 1000 radii, for requested tolerances 1e-4 … 1e-12, against a run at
//! 1e-14. Prints tolerance, error achieved, error estimate, evaluations and time; then the
//! extremes of the solver's range (thin slabs take the real-space route). Checks that every
//! achieved error is below its estimate (exit code 1 otherwise). Timings are per call.
//!
//! Builds on: nothing (the slab, `boltzone::hankel`).
//! Reference: the same solver at rel_tol 1e-14 (errors), and the route's own estimates at the
//! extremes of its range.
//! Run: `cargo run --release --example 01_slab_work_precision [repeats]` (default 3);
//! `BOLTZONE_QUICK=1` times one repeat (the test suite does).

use boltzone::hankel::{MidplaneCurve, SeparationParams, Slab};
use boltzone::{FaceLoad, Material};
use std::time::Instant;

pub fn main() -> anyhow::Result<()> {
    let repeats: usize = if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        1
    } else {
        std::env::args().nth(1).map_or(Ok(3), |s| s.parse())?
    };
    let a = 0.1;
    let mut ok = true;
    println!("R_o/A of the no-hole slab, Table 1's geometries (A = 0.1, nu = 0.3):");
    println!(
        "{:>8} {:>9} {:>16} {:>9} {:>6}",
        "B/A", "D", "R_o/A", "error", "evals"
    );
    for &d in &[0.1, 0.4 / 3.0, 0.2] {
        for &ba in &[3.1, 2.2, 1.6, 1.3] {
            let slab = Slab::new(d, Material::unit(0.3)?, FaceLoad::uniform(a, ba * a, 1.0)?)?;
            let s = slab.separation_radius(&SeparationParams::default())?;
            println!(
                "{ba:>8} {d:>9.6} {:>16.12} {:>9.1e} {:>6}",
                s.r_o / a,
                s.r_o_error / a,
                s.evaluations
            );
        }
    }
    let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(a, 0.31, 1.0)?)?;
    let reference = slab.separation_radius(&SeparationParams {
        rel_tol: 1e-14,
        ..Default::default()
    })?;
    println!(
        "\nR_o, A = D = 0.1, B = 0.31; reference run at rel_tol 1e-14: R_o = {:.15}",
        reference.r_o
    );
    println!(
        "{:>8} {:>10} {:>10} {:>6} {:>8} {:>10}",
        "tol", "achieved", "estimate", "evals", "nodes", "time/us"
    );
    for &tol in &[1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
        let p = SeparationParams {
            rel_tol: tol,
            ..Default::default()
        };
        let t = Instant::now();
        let mut s = slab.separation_radius(&p)?;
        for _ in 1..repeats {
            s = slab.separation_radius(&p)?;
        }
        let us = 1e6 * t.elapsed().as_secs_f64() / repeats as f64;
        let achieved = (s.r_o - reference.r_o).abs();
        ok &= achieved <= s.r_o_error + reference.r_o_error;
        println!(
            "{tol:>8.0e} {achieved:>10.1e} {:>10.1e} {:>6} {:>8} {us:>10.0}",
            s.r_o_error, s.evaluations, s.nodes
        );
    }
    let r_end = 1.0;
    let reference = MidplaneCurve::new(&slab, 0.0, r_end, 1e-14)?;
    println!("\nMidplane curve sigma_z/P at 1000 radii in [0, 10A] (build + 1000 evaluations):");
    println!(
        "{:>8} {:>10} {:>10} {:>9} {:>10}",
        "tol", "achieved", "estimate", "J0 evals", "time/ms"
    );
    for &tol in &[1e-6, 1e-8, 1e-10, 1e-12] {
        let t = Instant::now();
        let mut worst: f64 = 0.0;
        let mut curve = MidplaneCurve::new(&slab, 0.0, r_end, tol)?;
        for rep in 0..repeats {
            if rep > 0 {
                curve = MidplaneCurve::new(&slab, 0.0, r_end, tol)?;
            }
            for k in 0..1000 {
                let r = r_end * k as f64 / 999.0;
                let v = curve.eval(r).value;
                if rep == 0 {
                    worst = worst.max((v - reference.eval(r).value).abs());
                }
            }
        }
        let ms = 1e3 * t.elapsed().as_secs_f64() / repeats as f64;
        ok &= worst <= curve.max_error() + reference.max_error();
        println!(
            "{tol:>8.0e} {worst:>10.1e} {:>10.1e} {:>9} {ms:>10.2}",
            curve.max_error(),
            curve.evaluations()
        );
    }
    println!("\nExtremes of the range (A = 1): route, R_o/A, error, time");
    println!(
        "{:>7} {:>7} {:>11} {:>20} {:>9} {:>9}",
        "D/A", "B/A", "route", "R_o/A", "error", "time/ms"
    );
    for &(da, ba) in &[
        (1e-3, 1.001),
        (1e-3, 1e3),
        (1e3, 1.001),
        (1e3, 1e3),
        (1.0, 1e3),
    ] {
        let slab = Slab::new(da, Material::unit(0.3)?, FaceLoad::uniform(1.0, ba, 1.0)?)?;
        let t = Instant::now();
        let s = slab.separation_radius(&SeparationParams::default())?;
        let ms = 1e3 * t.elapsed().as_secs_f64();
        let route = if s.nodes == 0 {
            "real-space"
        } else {
            "xi-rule"
        };
        ok &= s.r_o.is_finite() && s.r_o_error < 1e-9 * s.r_o;
        println!(
            "{da:>7.0e} {ba:>7} {route:>11} {:>20.12} {:>9.1e} {ms:>9.2}",
            s.r_o, s.r_o_error
        );
    }
    if !ok {
        anyhow::bail!("an achieved error exceeded its estimate");
    }
    Ok(())
}
