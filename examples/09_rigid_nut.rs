//! The single plate under a rigid, frictionless nut (report Fig. 21: a uniform displacement of
//! the face over A..B) against the uniform bearing pressure of Table 1: R_o/A for Table 1's
//! geometries with A/D = 1, both by Q9 finite elements with the level-change error estimate. A rigid nut
//! concentrates the bearing pressure at the load's edges (square-root singular at r = B), which
//! moves R_o outward; the estimate converges more slowly (the singularity is stronger).
//!
//! Self-checks (exit code 1): the pressure column agrees with the Hankel route with the hole
//! and the same rim (`boltzone::hankel::hole`, an independent method) within the two error
//! estimates; the nut's R_o lies beyond the pressure's by more than both estimates.
//! `BOLTZONE_QUICK=1` runs 3 levels (the test suite does).
//!
//! Run: `cargo run --release --example 09_rigid_nut [levels]` (default 5).
//!
//! Builds on: examples 03 (the FE single plate) and 05 (the Hankel check).

use boltzone::compare::Geometry;
use boltzone::fem::single::{single_plate_r_o, FaceCondition, SingleParams};
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::SeparationParams;
use boltzone::OuterRadius;

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        return run(3);
    }
    let levels: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse())
        .transpose()?
        .unwrap_or(5);
    run(levels)
}

/// The comparison with `levels` refinements.
pub fn run(levels: usize) -> anyhow::Result<()> {
    let a = 0.1;
    println!(
        "{:>5} | {:>18} | {:>18} | {:>7}",
        "B/A", "pressure R_o/A", "rigid nut R_o/A", "shift"
    );
    for row in boltzone::reference::table1()
        .into_iter()
        .filter(|r| r.a_over_d == 1.0)
    {
        let plate = Geometry::new(a, row.b(), row.d(), 1.54, 0.3)?
            .single_plate(OuterRadius::Finite(1.54))?;
        let mut res = Vec::new();
        for loading in [FaceCondition::Pressure, FaceCondition::UniformDisplacement] {
            let params = SingleParams {
                loading,
                levels,
                ..SingleParams::default()
            };
            let (r, info) = single_plate_r_o(&plate, &params)?;
            res.push((r / a, info.error_estimate / a));
        }
        // the pressure column against the Hankel route with the hole and the same rim
        let (hankel, _) =
            single_plate_separation(&plate, &SeparationParams::default(), &HoleParams::default())?;
        let gap = (res[0].0 - hankel.r_o / a).abs();
        if gap > res[0].1 + hankel.r_o_error / a {
            anyhow::bail!(
                "B/A {}: FE R_o/A {} and Hankel {} differ by {gap:e}, more than their estimates",
                row.b_over_a,
                res[0].0,
                hankel.r_o / a
            );
        }
        // the rigid nut concentrates the bearing pressure at the load's edges: R_o moves out
        if res[1].0 - res[1].1 <= res[0].0 + res[0].1 {
            anyhow::bail!(
                "B/A {}: the rigid nut did not move R_o outward",
                row.b_over_a
            );
        }
        println!(
            "{:>5} | {:>9.4} ± {:<6.4} | {:>9.4} ± {:<6.4} | {:>+7.3}",
            row.b_over_a,
            res[0].0,
            res[0].1,
            res[1].0,
            res[1].1,
            res[1].0 - res[0].0
        );
    }
    Ok(())
}
