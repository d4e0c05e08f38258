//! Builds the far-region tables `src/table/data/far.json`: g(B/D) with R_o = B + D·g(B/D), the
//! separation radius of the no-hole disk load 0..B (uniform pressure), for the two-plate model
//! (equal plates, frictionless: [`Layer::receding_contact`] at 1e-12 D) and the single plate 2D
//! thick ([`Slab::separation_radius`] at 1e-12 of R_o). Neither depends on ν (the receding
//! layer's kernels and the slab's midplane σ_z are free of it) nor on the load's magnitude.
//!
//! **Method.** g is interpolated in t = D/B on [0, 1/`B_MIN`] at the N Chebyshev points of the
//! first kind, t_j = (1 + cos(π(j + ½)/N))/(2·`B_MIN`), which avoid t = 0 (B = ∞) but whose
//! interpolant covers it (`boltzone::table::far`); for two plates t_lo = 1/48 (the receding
//! solver's dense system takes B/D up to about 60), beyond which the table extrapolates with
//! its bar. The coefficients c_k (discrete cosine transform of type II) are stored with the
//! samples' largest error estimate and printed; `tests/table/far.rs` checks the table against
//! fresh solves not used to build it.
//!
//! Run: `cargo run --release --example 25_build_tables [N_two] [N_single]` (default 20, 28). It rewrites the file whole (`boltzone::fsutil::write_atomic`).
//! Run time (measured, stated in `docs/tables.md`).

use boltzone::hankel::receding::{Layer, RecedingParams};
use boltzone::hankel::{SeparationParams, Slab};
use boltzone::table::far::FarTable;
use boltzone::{FaceLoad, Material};
use std::time::Instant;

/// Smallest B/D the far tables cover.
const B_MIN: f64 = 2.0;

/// Largest B/D sampled for two plates (the receding solver takes up to about 60).
const T_LO_TWO: f64 = 48.0;

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    if quick || args.iter().any(|a| a == "show") {
        return show();
    }
    // points per table: two plates' coefficients reach their build's floor (≈ 2e-10) near
    // k = 19, the single plate's fall to ≈ 1e-11 by k = 28 (measured)
    let n_two: usize = if quick {
        6
    } else {
        args.get(1).map_or(Ok(20), |s| s.parse())?
    };
    let n_single: usize = if quick {
        6
    } else {
        args.get(2).map_or(Ok(28), |s| s.parse())?
    };
    if args.iter().any(|a| a == "time") {
        for b in [2.0, 8.0, 32.0, 128.0, 512.0] {
            let t = Instant::now();
            let (g, e) = two_plates(b)?;
            let t1 = t.elapsed().as_secs_f64();
            let t = Instant::now();
            let (h, f) = single_plate(b)?;
            println!(
                "B/D {b}: two g {g:.12} ± {e:.1e} {t1:.2} s; single g {h:.12} ± {f:.1e} {:.2} s",
                t.elapsed().as_secs_f64()
            );
        }
        return Ok(());
    }
    let start = Instant::now();
    let mut out = String::from("{\n");
    out += &format!(
        "  \"provenance\": \"examples/25_build_tables.rs, N = {n_two} (two plates), {n_single} (single plate) Chebyshev points of the first kind in t = D/B on [t_lo, t_hi]; two plates: hankel::receding::Layer::receding_contact (RecedingParams::default: root 1e-12 D, estimate from 3n/4 points); single plate: hankel::Slab::separation_radius (rel_tol 1e-12); built at commit {}\",\n",
        commit()
    );
    // (name, solver, t_lo, N): the receding contact's dense system stops near B/D = 60
    let models: [(&str, Solver, f64, usize); 2] = [
        ("two_plates", two_plates, 1.0 / T_LO_TWO, n_two),
        ("single_plate", single_plate, 0.0, n_single),
    ];
    for (k, (name, solve, t_lo, n)) in models.iter().enumerate() {
        let n = *n;
        let t_hi = 1.0 / B_MIN;
        let mut values = Vec::with_capacity(n);
        let mut build = 0.0f64;
        let t0 = Instant::now();
        for t in FarTable::nodes(*t_lo, t_hi, n) {
            let (g, e) = solve(1.0 / t)?;
            build = build.max(e);
            values.push(g);
        }
        let c = FarTable::from_samples(*t_lo, t_hi, &values, build).coefficients;
        let mags: Vec<String> = c.iter().map(|x| format!("{:.1e}", x.abs())).collect();
        println!(
            "{name}: build error ≤ {build:.1e} D, {:.1} s",
            t0.elapsed().as_secs_f64()
        );
        println!("  |c_k|: {}", mags.join(" "));
        out += &format!(
            "  \"{name}\": {{ \"t_lo\": {t_lo:e}, \"t_hi\": {t_hi:e}, \"build_error\": {build:e}, \"coefficients\": [{}] }}{}\n",
            c.iter().map(|x| format!("{x:e}")).collect::<Vec<_>>().join(", "),
            if k + 1 < models.len() { "," } else { "" }
        );
    }
    out += "}\n";
    if !quick {
        let path = std::path::Path::new("src/table/data/far.json");
        boltzone::fsutil::write_atomic(path, out.as_bytes())?;
        println!(
            "wrote {} in {:.1} s",
            path.display(),
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// The shipped tables' g and bar (in D) across B/D, both models.
fn show() -> Result<(), Box<dyn std::error::Error>> {
    use boltzone::table::Model;
    for model in [Model::TwoPlates, Model::SinglePlate] {
        let table = FarTable::of(model);
        println!("{model:?}:");
        for b in [2.0, 5.0, 10.0, 48.0, 60.0, 100.0, 1e3, 1e4, f64::INFINITY] {
            let (g, bar) = table.g(1.0 / b);
            println!(
                "  B/D {b:>8}: g = {g:.10}, bar {bar:.2e} D, of R_o {:.1e}",
                bar / (b + g)
            );
        }
    }
    Ok(())
}

type Solver = fn(f64) -> Result<(f64, f64), Box<dyn std::error::Error>>;

/// (g, its error) of two equal plates, disk load 0..B, D = 1.
fn two_plates(b: f64) -> Result<(f64, f64), Box<dyn std::error::Error>> {
    let layer = Layer::new(1.0, Material::unit(0.3)?, FaceLoad::uniform(0.0, b, 1.0)?)?;
    let c = layer.receding_contact(&RecedingParams::default())?;
    Ok((c.r_o - b, c.info.r_o_error))
}

/// (g, its error) of the single plate 2D thick, disk load 0..B, D = 1.
fn single_plate(b: f64) -> Result<(f64, f64), Box<dyn std::error::Error>> {
    let slab = Slab::new(1.0, Material::unit(0.3)?, FaceLoad::uniform(0.0, b, 1.0)?)?;
    let p = SeparationParams {
        rel_tol: 1e-12,
        ..Default::default()
    };
    let s = slab.separation_radius(&p)?;
    Ok((s.r_o - b, s.r_o_error))
}

fn commit() -> String {
    std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map_or("unknown".into(), |s| s.trim().to_string())
}
