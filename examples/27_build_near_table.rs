//! Builds the near-region table `src/table/data/near.json` (`boltzone::table::near`): y =
//! (R_o − B)/D of two equal infinite plates with a hole, frictionless, uniform pressure on
//! A..B, over A/D ∈ [0.25, 4], (B − A)/D ∈ [0.15, 5], ν ∈ [0, 0.5], sampled by the holed
//! route at 1e-8 ([`two_plate_hole_to`]) on a tensor grid of Chebyshev points of the first kind
//! per panel, and validates it on random points that were not used to build it.
//!
//! **Method.** Five panels in w = (B − A)/D: [0.15, 0.45] and [0.45, 1.2] mapped by ln w (the
//! load narrows onto the hole's corner as w → 0), [1.2, 2.4], [2.4, 3.5] and [3.5, 5] linear;
//! ln(A/D) and ν linear. The linear panels are short because the hole's faster
//! Papkovich–Fadle modes (e^(−5.4w) and beyond) still vary there (`docs/tables.md`). Each sample
//! keeps its own estimate (the route's), which the table's bar carries through the cardinal functions.
//!
//! Run (from a scratch folder is not needed: it writes only the paths given):
//! - `cargo run --release --example 27_build_near_table build K SAMPLES_K.csv` solves the nodes
//!   of panel K (0 … 4; appending to the file, resuming where a previous run stopped), then
//!   `… table SAMPLES_0.csv … SAMPLES_4.csv` writes `src/table/data/near.json` from them;
//! - `… validate N SEED OUT.csv [TOL]` solves N random points (log-uniform A/D and w, uniform
//!   ν) by the route at TOL (default 1e-8; appending, resuming); `… check OUT.csv` compares the
//!   shipped table with them: the distribution of |table − route|/(bar + the route's estimate);
//! - `… time` times the route across the domain; `… lookup` times one R_o from the tables.
//!
//! Run time: `docs/tables.md` (measured).

use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::route::single_plate;
use boltzone::table::near::{Panel, A_MAX, A_MIN};
use boltzone::table::Model;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use std::io::Write;
use std::time::Instant;

/// The panels: (w_lo, w_hi, ln-mapped, points per axis (A/D, w, ν)).
const PANELS: [(f64, f64, bool, [usize; 3]); 5] = [
    (0.15, 0.45, true, [12, 8, 8]),
    (0.45, 1.2, true, [12, 8, 8]),
    (1.2, 2.4, false, [8, 8, 6]),
    (2.4, 3.5, false, [8, 8, 4]),
    (3.5, 5.0, false, [8, 8, 4]),
];

/// (R_o/D, estimate/D, converged, seconds) of `model`'s holed route at `tol` (1e-8 for the
/// build), D = 1 (the single plate 2D thick): two plates by [`two_plate_hole_to`] (at 1e-6
/// where a tighter run fails), the single plate by [`single_plate_separation`] with the route
/// layer's knobs for the tolerance, the hole's residual to 1e-8 P, up to 128 modes and the
/// slab's hole tractions to 1e-10 P where the quadrature confirms it (the route layer's knobs
/// stop the slab at 1e-8 P, which leaves estimates of 0.7–4e-7 of R_o at tolerance 1e-8:
/// `docs/tables.md`).
fn solve(
    model: Model,
    a: f64,
    w: f64,
    nu: f64,
    tol: f64,
) -> Result<(f64, f64, bool, f64), Box<dyn std::error::Error>> {
    let t = Instant::now();
    let m = Material::unit(nu)?;
    let load = FaceLoad::uniform(a, a + w, 1.0)?;
    let p = SinglePlate::new(a, OuterRadius::Infinite, 1.0, m, load)?;
    let (r_o, err) = match model {
        Model::TwoPlates => {
            let (h, _) = match two_plate_hole_to(&p, tol, &[]) {
                Ok(h) => h,
                Err(_) => two_plate_hole_to(&p, tol.max(1e-6), &[])?,
            };
            (h.r_o, h.info.r_o_error)
        }
        Model::SinglePlate => {
            // the slab's hole tractions to 1e-10 P, else 1e-9, else 1e-8 (the route layer's
            // floor): where the quadrature cannot confirm the tighter target its slab error,
            // and so R_o's estimate, grows; the smallest estimate is kept
            let (search, hole) = single_plate::hankel_params(tol);
            let mut best = (f64::NAN, f64::INFINITY);
            for slab in [1e-10, 1e-9, 1e-8] {
                let hole = HoleParams {
                    slab_tolerance: slab,
                    residual_target: 1e-8,
                    max_terms: 128,
                    ..hole
                };
                let (s, _) = single_plate_separation(&p, &search, &hole)?;
                if s.r_o_error < best.1 {
                    best = (s.r_o, s.r_o_error);
                }
                if best.1 <= tol * best.0 {
                    break;
                }
            }
            best
        }
    };
    Ok((r_o, err, err <= tol * r_o, t.elapsed().as_secs_f64()))
}

fn read_csv(path: &str) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap_or_default()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('a'))
        .map(|l| {
            l.split(',')
                .map(|x| x.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect()
}

/// Appends the route's answer at each of `points` to `path` (a, w, nu, r_o, error, converged,
/// seconds), skipping the first rows already there.
fn solve_into(
    model: Model,
    path: &str,
    points: &[[f64; 3]],
    tol: f64,
) -> Result<(), Box<dyn std::error::Error>> {
    let done = read_csv(path).len();
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?;
    if done == 0 {
        writeln!(f, "a,w,nu,r_o,error,converged,seconds")?;
    }
    for (k, p) in points.iter().enumerate().skip(done) {
        let (r, e, ok, s) = solve(model, p[0], p[1], p[2], tol)?;
        writeln!(
            f,
            "{:e},{:e},{:e},{:e},{:e},{},{:.3}",
            p[0],
            p[1],
            p[2],
            r,
            e,
            u8::from(ok),
            s
        )?;
        f.flush()?;
        println!(
            "{k}/{}: a {:.4} w {:.4} nu {:.3}: R_o {r:.10} ± {e:.1e} {s:.2} s",
            points.len(),
            p[0],
            p[1],
            p[2]
        );
    }
    Ok(())
}

/// The sample points of panel `k`.
fn nodes(k: usize) -> Vec<[f64; 3]> {
    let (lo, hi, log, n) = PANELS[k];
    Panel::nodes(lo, hi, log, n)
}

/// The panels through the samples of `paths` (one file per panel, in the order of [`nodes`]).
fn panels(paths: &[String]) -> Result<Vec<Panel>, Box<dyn std::error::Error>> {
    let mut out = Vec::new();
    for (&(lo, hi, log, n), path) in PANELS.iter().zip(paths) {
        let m: usize = n.iter().product();
        let rows = read_csv(path);
        let rows = rows
            .get(..m)
            .ok_or("samples file incomplete: run build first")?;
        let y: Vec<f64> = rows.iter().map(|r| r[3] - r[0] - r[1]).collect();
        let e: Vec<f64> = rows.iter().map(|r| r[4]).collect();
        out.push(Panel::from_samples(lo, hi, log, n, &y, &e));
    }
    Ok(out)
}

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    // `--single`, anywhere: the single plate's table (else the two plates')
    let all: Vec<String> = std::env::args().collect();
    let model = match all.iter().any(|a| a == "--single") {
        true => Model::SinglePlate,
        false => Model::TwoPlates,
    };
    let args: Vec<String> = all.into_iter().filter(|a| a != "--single").collect();
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    if quick || args.get(1).is_some_and(|a| a == "show") {
        return show(model);
    }
    let arg = |k: usize| args.get(k).cloned().ok_or(format!("argument {k} missing"));
    match args.get(1).map(String::as_str) {
        Some("time") => {
            for a in [0.25, 1.0, 4.0] {
                for w in [0.15, 0.3, 1.0, 2.0, 5.0] {
                    let (r, e, ok, s) = solve(model, a, w, 0.3, 1e-8)?;
                    println!("a {a} w {w}: R_o {r:.10} ± {e:.1e} converged {ok} {s:.2} s");
                }
            }
        }
        Some("lookup") => {
            // one R_o from the tables, timed over a sweep of 10⁶ lookups (near and far)
            use boltzone::table::lookup::separation_radius;
            let n = 1_000_000;
            let t = Instant::now();
            let mut sum = 0.0;
            for k in 0..n {
                let b = 0.12 + 3.0 * (k % 1000) as f64 / 1000.0;
                sum += separation_radius(model, 0.1, b, 0.1, 0.3, 1e-3).map_or(0.0, |v| v.value);
            }
            let per = t.elapsed().as_secs_f64() / n as f64;
            println!("{:.3} µs per R_o (B/D 1.2–31, A/D = 1; checksum {sum:.6})", per * 1e6);
        }
        Some("build") => {
            let t = Instant::now();
            let k: usize = arg(2)?.parse()?;
            solve_into(model, &arg(3)?, &nodes(k), 1e-8)?;
            println!("{} nodes in {:.0} s", nodes(k).len(), t.elapsed().as_secs_f64());
        }
        Some("validate") => {
            let n: usize = arg(2)?.parse()?;
            let mut rng = boltzone::numerics::random::SplitMix64::new(arg(3)?.parse()?);
            let points: Vec<[f64; 3]> = (0..n)
                .map(|_| {
                    let a = rng.log_uniform(A_MIN, A_MAX);
                    let w = rng.log_uniform(PANELS[0].0, PANELS[PANELS.len() - 1].1);
                    [a, w, 0.5 * rng.unit()]
                })
                .collect();
            let tol = match args.get(5) {
                Some(t) => t.parse()?,
                None => 1e-8,
            };
            solve_into(model, &arg(4)?, &points, tol)?;
        }
        Some("table") => {
            let samples = (0..PANELS.len())
                .map(|k| arg(2 + k))
                .collect::<Result<Vec<_>, _>>()?;
            let rows: Vec<Vec<f64>> = samples.iter().flat_map(|p| read_csv(p)).collect();
            let secs: f64 = rows.iter().map(|r| r[6]).sum();
            let route = match model {
                Model::TwoPlates => "boltzone::hankel::receding::holed::two_plate_hole_to at tolerance 1e-8 (1e-6 where that failed)",
                Model::SinglePlate => "boltzone::hankel::hole::single_plate_separation with route::single_plate::hankel_params(1e-8), residual target 1e-8, at most 128 modes, slab tolerance 1e-10 (else 1e-9, else 1e-8: the smallest estimate)",
            };
            let mut out = format!(
                "{{\n  \"provenance\": \"examples/27_build_near_table.rs: {} samples of {route}, D = 1, C = infinite; {:.0} s of solves; built at commit {} on {}\",\n  \"panels\": [\n",
                rows.len(),
                secs,
                git(&["rev-parse", "--short", "HEAD"]),
                date()
            );
            let ps = panels(&samples)?;
            for (k, p) in ps.iter().enumerate() {
                let list = |v: &[f64]| v.iter().map(|x| format!("{x:e}")).collect::<Vec<_>>().join(", ");
                out += &format!(
                    "    {{ \"w_lo\": {:e}, \"w_hi\": {:e}, \"log_w\": {}, \"n\": [{}, {}, {}], \"errors\": [{}], \"coefficients\": [{}] }}{}\n",
                    p.w_lo, p.w_hi, p.log_w, p.n[0], p.n[1], p.n[2], list(&p.errors), list(&p.coefficients),
                    if k + 1 < ps.len() { "," } else { "" }
                );
                for axis in 0..3 {
                    let m = p.axis_magnitudes(axis);
                    println!("panel {k} axis {axis}: {}", m.iter().map(|x| format!("{x:.1e}")).collect::<Vec<_>>().join(" "));
                }
                println!("panel {k}: tails {:?}", p.tails());
            }
            out += "  ]\n}\n";
            let path = std::path::Path::new(match model {
                Model::TwoPlates => "src/table/data/near.json",
                Model::SinglePlate => "src/table/data/near_single.json",
            });
            boltzone::fsutil::write_atomic(path, out.as_bytes())?;
            println!("wrote {} ({} bytes)", path.display(), out.len());
        }
        Some("check") => {
            // the shipped table (src/table/data/near.json) against the fresh solves of V.csv
            let mut ratios = Vec::new();
            let mut worst = (0.0, [0.0; 3]);
            // the largest ratio per panel of the shipped table (the panel answering w)
            let panels = &boltzone::table::near::table(model).panels;
            let mut per_panel = vec![0.0f64; panels.len()];
            for r in read_csv(&arg(2)?) {
                let t = boltzone::table::near::separation_radius(model, r[0], r[0] + r[1], 1.0, r[2], 1.0)?;
                let err = (t.value - r[3]).abs();
                let q = err / (t.error + r[4]);
                let k = panels.iter().position(|p| r[1] <= p.w_hi).unwrap_or(panels.len() - 1);
                per_panel[k] = per_panel[k].max(q);
                if q > worst.0 {
                    worst = (q, [r[0], r[1], r[2]]);
                }
                ratios.push((q, err, t.error, r[3]));
            }
            println!("largest ratio per panel: {per_panel:.3?}");
            ratios.sort_by(|a, b| a.0.total_cmp(&b.0));
            let n = ratios.len();
            let quant = |f: f64| ratios[((n - 1) as f64 * f) as usize].0;
            println!("{n} points: |table − route|/(bar + route estimate): median {:.3}, 90 % {:.3}, 99 % {:.3}, max {:.3} at {:?}", quant(0.5), quant(0.9), quant(0.99), worst.0, worst.1);
            let rel_err = ratios.iter().map(|r| r.1 / r.3).fold(0.0, f64::max);
            let mut bars: Vec<f64> = ratios.iter().map(|r| r.2 / r.3).collect();
            bars.sort_by(f64::total_cmp);
            println!("largest |table − route|/R_o {rel_err:.2e}; bar/R_o median {:.2e}, max {:.2e}", bars[n / 2], bars[n - 1]);
        }
        _ => return Err("usage: 27_build_near_table [--single] time | build K S_K.csv | table S_0.csv … S_4.csv | validate N SEED V.csv [TOL] | check V.csv | lookup".into()),
    }
    Ok(())
}

/// `model`'s shipped table's provenance, and its answer at Table 1's row (A/D 1, B/A 2.2,
/// C = ∞) against one fresh solve by the route at 1e-4 (within the table's bar plus the
/// solve's).
fn show(model: Model) -> Result<(), Box<dyn std::error::Error>> {
    let t = boltzone::table::near::table(model);
    println!("{}", t.provenance);
    let r = boltzone::table::near::separation_radius(model, 1.0, 2.2, 1.0, 0.3, 1e-2)?;
    let (r_o, e, _, _) = solve(model, 1.0, 1.2, 0.3, 1e-4)?;
    let diff = (r.value - r_o).abs();
    println!(
        "A/D 1, B/A 2.2: table {:.7} ± {:.1e}, route (1e-4) {r_o:.7} ± {e:.1e}, |difference| {diff:.1e}",
        r.value, r.error
    );
    if diff > r.error + e {
        return Err("the near table misses its bar on Table 1's row".into());
    }
    Ok(())
}

fn git(args: &[&str]) -> String {
    std::process::Command::new("git")
        .args(args)
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map_or("unknown".into(), |s| s.trim().to_string())
}

fn date() -> String {
    std::process::Command::new("date")
        .args(["-u", "+%Y-%m-%d"])
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map_or("unknown".into(), |s| s.trim().to_string())
}
