//! Lamé thick cylinder (a = 1, b = 2, internal pressure, plane strain): relative L2 displacement
//! error against the exact solution u = C₁r + C₂/r for every element kind, observed orders
//! (least-squares slope), and ν = 0.499 to show volumetric locking of Q4 and its cure (B-bar, Q9).
//!
//! Run: `cargo run --release --example 02_lame_convergence [max_n]` (default 64).
//!
//! Builds on: nothing (the finite elements, `boltzone::fem`).

use boltzone::fem::lame::{lame_error, LameCase};
use boltzone::fem::ElementKind;
use boltzone::numerics::convergence::{log_log_slope, order_between};
use std::time::Instant;

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        return run(16);
    }
    let max_n: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse())
        .transpose()?
        .unwrap_or(64);
    run(max_n)
}

/// The study on n = 4, 8, …, `max_n` elements; fails if an observed order is off by > 0.1
/// (locked Q4 at ν = 0.499 is reported, not checked).
pub fn run(max_n: usize) -> anyhow::Result<()> {
    let ns: Vec<usize> = (2..).map(|k| 1 << k).take_while(|&n| n <= max_n).collect();
    for nu in [0.3, 0.499] {
        let case = LameCase { a: 1.0, b: 2.0, nu };
        println!("nu = {nu}");
        println!(
            "{:>8} {:>6} {:>12} {:>8}",
            "element", "n", "L2 error", "rate"
        );
        for kind in [
            ElementKind::Cst4,
            ElementKind::Q4,
            ElementKind::Q4Bbar,
            ElementKind::Q9,
        ] {
            let t = Instant::now();
            let errs: Vec<f64> = ns
                .iter()
                .map(|&n| lame_error(&case, kind, n))
                .collect::<Result<_, _>>()?;
            for (i, (n, e)) in ns.iter().zip(&errs).enumerate() {
                let rate = if i > 0 {
                    format!(
                        "{:8.3}",
                        order_between(1.0 / ns[i - 1] as f64, errs[i - 1], 1.0 / *n as f64, *e)
                    )
                } else {
                    String::new()
                };
                println!("{:>8} {:>6} {:>12.3e} {rate}", format!("{kind:?}"), n, e);
            }
            let expected = if kind == ElementKind::Q9 { 3.0 } else { 2.0 };
            let last: Vec<(f64, f64)> =
                ns.iter().zip(&errs).map(|(&n, &e)| (n as f64, e)).collect();
            let p = -log_log_slope(&last[last.len().saturating_sub(3)..]);
            println!(
                "  observed order (last 3 levels) {p:.3}, expected {expected}, {:.2} s",
                t.elapsed().as_secs_f64()
            );
            let locked = nu > 0.49 && kind == ElementKind::Q4;
            if !locked && max_n >= 16 && p < expected - 0.1 {
                anyhow::bail!("{kind:?} at nu = {nu}: order {p:.3} < {expected}");
            }
        }
    }
    Ok(())
}
