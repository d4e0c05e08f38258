//! Table 1's twelve single-plate geometries (A = 0.1 in, C = 1.54 in, ν = 0.3,
//! D = A/(A/D), B = A·(B/A)) by finite elements: R_o/A on nested refinement levels, the observed
//! order, the last level's value with its error estimate (the level changes, no extrapolation), and the report's single-plate column
//! beside it (the 1970 mesh had a radial spacing of 0.015 in, so differences up to ~0.15 in R_o/A
//! are its resolution). Target: estimated error ≤ 0.05 % of R_o.
//!
//! Run: `cargo run --release --example 03_single_plate_table1 [levels] [rows]`
//! (default 5 levels, all 12 rows).
//!
//! Builds on: example 02 (the elements it refines).

use boltzone::compare::Geometry;
use boltzone::fem::single::{single_plate_r_o, SingleParams};
use boltzone::OuterRadius;

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        return run(5, 2, 0.05);
    }
    let mut args = std::env::args().skip(1);
    let levels: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(5);
    let rows: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(12);
    run(levels, rows, 0.05)
}

/// The study on the first `rows` rows of Table 1 with `levels` refinements; fails if an
/// estimated error exceeds `target_percent`.
pub fn run(levels: usize, rows: usize, target_percent: f64) -> anyhow::Result<()> {
    let params = SingleParams {
        levels,
        ..SingleParams::default()
    };
    let a = 0.1;
    println!(
        "{:>6} {:>5} | {:<40} | {:>6} {:>9} {:>8} {:>7} | {:>7} {:>7} {:>8} {:>6}",
        "A/D",
        "B/A",
        "R_o/A per level",
        "order",
        "R_o/A",
        "err %",
        "report",
        "diff",
        "nodes",
        "dofs",
        "s"
    );
    let mut worst: f64 = 0.0;
    for row in boltzone::reference::table1().into_iter().take(rows) {
        let plate = Geometry::new(a, row.b(), row.d(), 1.54, 0.3)?
            .single_plate(OuterRadius::Finite(1.54))?;
        let (r_o, info) = single_plate_r_o(&plate, &params)?;
        let lv: Vec<String> = info
            .levels
            .iter()
            .map(|r| format!("{:.4}", r / a))
            .collect();
        let rel = 100.0 * info.error_estimate / r_o;
        worst = worst.max(rel);
        println!(
            "{:>6} {:>5} | {:<40} | {:>6} {:>9.5} {:>8.4} {:>7.3} | {:>7.3} {:>7} {:>8} {:>6.2}",
            row.a_over_d,
            row.b_over_a,
            lv.join(" "),
            info.observed_order
                .map_or("-".into(), |p| format!("{p:.2}")),
            r_o / a,
            rel,
            row.single,
            r_o / a - row.single,
            info.nodes,
            info.dofs,
            info.seconds
        );
    }
    println!("worst estimated error {worst:.4} % (target {target_percent} %)");
    if worst > target_percent {
        anyhow::bail!("R_o not converged to 0.05 %: use more levels");
    }
    Ok(())
}
