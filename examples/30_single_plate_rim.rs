//! The single plate's tables with a free rim r = C (`boltzone::table::rim`): the survey that
//! measures the smallest midplane slope the rim bound divides by, and the check of the tables'
//! rimmed answers against fresh solves of the rimmed plate.
//!
//! - `cargo run --release --example 30_single_plate_rim slopes N SEED` solves N random
//!   infinite holed plates (D = 1, P = 1) by the Hankel route at 1e-6
//!   ([`single_plate_separation`]): half over the near table's domain (log-uniform A/D in
//!   [0.25, 4] and w = (B − A)/D in [0.15, 5], uniform ν in [0, 0.5]), half over the far
//!   table's (log-uniform A/D in [0.25, 4] and B/D in [2, 3000], the hole's handover x ≥ 2),
//!   after the corners of the near domain and the far one's smallest load (A/D 0.01, B/D 2),
//!   and prints the distribution of the slope |∂σ_z/∂r| at R_o in P/D, its smallest value and
//!   where;
//! - `… check N SEED [TOL]` draws N random plates over the near domain with a rim at
//!   C = R_o + u·D, u log-uniform in [0.5, 16], answers each from the tables
//!   ([`single_plate::table_answer`], the rim's bound in its bar) and by the Hankel route with
//!   the rim at TOL (default 1e-8; it bounds or fits the rim itself), and prints the
//!   distribution of |table − route| / (bar + the route's estimate) and how many of the table's
//!   answers met 1e-6 and 1e-4.
//!
//! Each fails when its check fails: a slope below twice [`SINGLE_PLATE_SLOPE_MIN`] (the margin
//! it was set with), a rimmed answer outside its bar.
//!
//! Run time and what they found: `docs/tables.md` (measured).

use boltzone::hankel::hole::single_plate_separation;
use boltzone::numerics::random::SplitMix64;
use boltzone::route::{single_plate, Method};
use boltzone::table::near::{A_MAX, A_MIN, W_MAX, W_MIN};
use boltzone::table::rim::SINGLE_PLATE_SLOPE_MIN;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use std::time::Instant;

fn plate(a: f64, b: f64, nu: f64, c: OuterRadius) -> Result<SinglePlate, boltzone::InputError> {
    let load = FaceLoad::uniform(a, b, 1.0)?;
    SinglePlate::new(a, c, 1.0, Material::unit(nu)?, load)
}

fn blocked(b: boltzone::route::two_plate::Blocker) -> String {
    format!("{:?}: {}", b.key, b.reason)
}

/// The quantile `q` of sorted `v`.
fn quantile(v: &[f64], q: f64) -> f64 {
    v[((v.len() - 1) as f64 * q).round() as usize]
}

fn slopes(n: usize, seed: u64) -> Result<(), Box<dyn std::error::Error>> {
    let mut rng = SplitMix64::new(seed);
    let (search, hole) = single_plate::hankel_params(1e-6);
    let mut found = Vec::new();
    let t = Instant::now();
    // the near domain's corners first, then the random points
    let mut corners = Vec::new();
    for nu in [0.0, 0.25, 0.499] {
        for a in [A_MIN, A_MAX] {
            for w in [W_MIN, W_MAX] {
                corners.push((a, a + w, nu));
            }
        }
        // the far table's smallest load and hole (it takes A/D below the near table's)
        corners.push((0.01, 2.0, nu));
    }
    for k in 0..corners.len() + n {
        let (a, b, nu) = match corners.get(k) {
            Some(c) => *c,
            None => {
                let a = rng.log_uniform(A_MIN, A_MAX);
                let b = match k % 2 {
                    0 => a + rng.log_uniform(W_MIN, W_MAX),
                    // far: x = R_o − A ≥ 2 holds with B ≥ A + 2 (R_o > B)
                    _ => rng.log_uniform(2.0, 3000.0).max(a + 2.0),
                };
                (a, b, 0.5 * rng.unit())
            }
        };
        let (s, _) =
            single_plate_separation(&plate(a, b, nu, OuterRadius::Infinite)?, &search, &hole)?;
        found.push((s.slope, a, b, nu, s.r_o));
    }
    found.sort_by(|x, y| x.0.total_cmp(&y.0));
    let v: Vec<f64> = found.iter().map(|f| f.0).collect();
    println!(
        "{} plates in {:.1} s: slope |dσ_z/dr| at R_o (P/D): min {:.4}, 1 % {:.4}, median {:.4}, max {:.4}",
        v.len(),
        t.elapsed().as_secs_f64(),
        v[0],
        quantile(&v, 0.01),
        quantile(&v, 0.5),
        v[v.len() - 1]
    );
    // the floor was set at half the smallest slope found
    if v[0] < 2.0 * SINGLE_PLATE_SLOPE_MIN {
        return Err(format!(
            "slope {} below twice the floor {SINGLE_PLATE_SLOPE_MIN}",
            v[0]
        )
        .into());
    }
    for f in found.iter().take(5) {
        println!(
            "  slope {:.5} at A/D {:.3}, B/D {:.3}, ν {:.3} (R_o {:.4} D)",
            f.0, f.1, f.2, f.3, f.4
        );
    }
    Ok(())
}

fn check(n: usize, seed: u64, tol: f64) -> Result<(), Box<dyn std::error::Error>> {
    let mut rng = SplitMix64::new(seed);
    let (search, hole) = single_plate::hankel_params(tol);
    let (mut ratios, mut served, mut met6, mut met4) = (Vec::new(), Vec::new(), 0, 0);
    let mut worst = (0.0, [0.0; 5]);
    let t = Instant::now();
    for _ in 0..n {
        let a = rng.log_uniform(A_MIN, A_MAX);
        let b = a + rng.log_uniform(W_MIN, W_MAX);
        let nu = 0.5 * rng.unit();
        let u = rng.log_uniform(0.5, 16.0);
        let infinite = plate(a, b, nu, OuterRadius::Infinite)?;
        let q = single_plate::Question {
            method: Method::Table,
            plate: Some(&infinite),
            tolerance: 1e-6,
            ..Default::default()
        };
        let c = single_plate::table_answer(&q).map_err(blocked)?.value + u;
        let rimmed = plate(a, b, nu, OuterRadius::Finite(c))?;
        let q = single_plate::Question {
            plate: Some(&rimmed),
            ..q
        };
        let table = single_plate::table_answer(&q).map_err(blocked)?;
        met6 += usize::from(table.error <= 1e-6 * table.value);
        met4 += usize::from(table.error <= 1e-4 * table.value);
        let (route, _) = single_plate_separation(&rimmed, &search, &hole)?;
        let r = (table.value - route.r_o).abs() / (table.error + route.r_o_error);
        if r > worst.0 {
            worst = (r, [a, b, nu, c, table.error]);
        }
        ratios.push(r);
        if table.error <= 1e-4 * table.value {
            served.push(r);
        }
    }
    served.sort_by(f64::total_cmp);
    ratios.sort_by(f64::total_cmp);
    println!(
        "{n} rimmed plates in {:.1} s: |table − route| / (bar + estimate): median {:.3}, 90 % {:.3}, 99 % {:.3}, max {:.3}",
        t.elapsed().as_secs_f64(),
        quantile(&ratios, 0.5),
        quantile(&ratios, 0.9),
        quantile(&ratios, 0.99),
        ratios[ratios.len() - 1]
    );
    let [a, b, nu, c, e] = worst.1;
    println!("  largest at A/D {a:.3}, B/D {b:.3}, ν {nu:.3}, C/D {c:.3} (bar {e:.2e} D)");
    println!("  the table's bar met 1e-6 of R_o on {met6}, 1e-4 on {met4} of {n}");
    if ratios[ratios.len() - 1] > 1.0 {
        return Err("a rimmed table answer is outside its bar".into());
    }
    if let Some(largest) = served.last() {
        println!(
            "  where it met 1e-4: ratio median {:.3}, max {largest:.3}",
            quantile(&served, 0.5)
        );
    }
    Ok(())
}

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        // the corners and a few random plates, then a few rimmed plates against the route
        slopes(4, 1)?;
        return check(6, 2, 1e-8);
    }
    let args: Vec<String> = std::env::args().collect();
    let arg = |k: usize| -> Result<&str, String> {
        args.get(k)
            .map(String::as_str)
            .ok_or_else(|| "usage: 30_single_plate_rim slopes N SEED | check N SEED [TOL]".into())
    };
    match arg(1)? {
        "slopes" => slopes(arg(2)?.parse()?, arg(3)?.parse()?),
        "check" => check(
            arg(2)?.parse()?,
            arg(3)?.parse()?,
            args.get(4).map_or(Ok(1e-8), |t| t.parse())?,
        ),
        other => Err(format!("unknown mode {other:?}: slopes | check").into()),
    }
}
