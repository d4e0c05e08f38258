//! Example 23: Table 1's two-plate R_o by the finite elements with the fitted contact edge
//! (issue 36), beside the holed semi-analytic route, and the cost.
//!
//! For each Table 1 row (A = 0.1 in, C = 1.54 in, ν = 0.3, equal plates): the semi-analytic
//! R_o at 1e-7 ([`boltzone::hankel::receding::holed::two_plate_hole_to`], its rim included)
//! and the FE with `fitted_edge` at the tolerance 2e-6 (its floor is 1e-6), with its estimate, the
//! difference in units of the two bars added, and the wall time; then the FE at the default
//! 5e-4 with and without the fitted edge (best of three, one thread).
//!
//! Arguments: `[tolerance] [row index …]` (default 2e-6 on every row: 10–11 levels, 3–10 s a
//! row at a load average of 6). `BOLTZONE_QUICK=1` runs the first row at 1e-4 against the route at 1e-6 (the
//! test suite does). Self-check (error): every difference within the two bars added.

use anyhow::ensure;
use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::reference::{self, TABLE1_HOLE_RADIUS, TABLE1_OUTER_RADIUS, TABLE1_POISSON};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate, SinglePlate};
use std::time::Instant;

/// Best wall time of three solves of `joint` with `params`, seconds.
fn best_of_three(joint: &Joint, params: &TwoPlateParams) -> anyhow::Result<f64> {
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let t = Instant::now();
        solve(joint, params)?;
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok();
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (rows, tols, reference_tol) = if quick {
        (reference::table1()[..1].to_vec(), vec![1e-4], 1e-6)
    } else {
        let all = reference::table1();
        let tols = match args.first() {
            Some(t) => vec![t.parse::<f64>()?],
            None => vec![2e-6],
        };
        let picked: Vec<_> = args[1.min(args.len())..]
            .iter()
            .filter_map(|i| i.parse::<usize>().ok())
            .filter_map(|i| all.get(i).cloned())
            .collect();
        (if picked.is_empty() { all } else { picked }, tols, 1e-7)
    };
    let (a, c) = (TABLE1_HOLE_RADIUS, TABLE1_OUTER_RADIUS);
    let m = Material::unit(TABLE1_POISSON)?;
    println!("Table 1, two plates, FE with the fitted edge beside the semi-analytic route");
    for row in &rows {
        let (b, d) = (row.b(), row.d());
        let load = FaceLoad::uniform(a, b, 1.0)?;
        let single = SinglePlate::new(a, OuterRadius::Finite(c), d, m, load.clone())?;
        let (exact, _) = two_plate_hole_to(&single, reference_tol, &[])?;
        let plate = Plate::new(d, m)?;
        let joint = Joint::new(a, OuterRadius::Finite(c), plate, plate, load)?;
        println!(
            "A/D {} B/A {}: semi-analytic R_o {:.10} ± {:.1e} in",
            row.a_over_d, row.b_over_a, exact.r_o, exact.info.r_o_error
        );
        for &tol in &tols {
            let t = Instant::now();
            let s = solve(
                &joint,
                &TwoPlateParams {
                    tolerance: tol,
                    fitted_edge: true,
                    max_levels: 12,
                    ..Default::default()
                },
            )?;
            let secs = t.elapsed().as_secs_f64();
            let diff = s.r_o - exact.r_o;
            let bars = s.r_o_error + exact.info.r_o_error;
            println!(
                "  FE at {tol:e}: {:.10} ± {:.1e} in ({:.1e} R_o), converged {}, {} levels, \
                 {secs:.3} s; difference {diff:+.2e} = {:.2} of the bars",
                s.r_o,
                s.r_o_error,
                s.r_o_error / s.r_o,
                s.converged,
                s.info.levels.len(),
                diff.abs() / bars
            );
            ensure!(diff.abs() <= bars, "outside both bars");
        }
        if !quick {
            let default = TwoPlateParams::default();
            let fitted = TwoPlateParams {
                fitted_edge: true,
                ..default
            };
            println!(
                "  at 5e-4: {:.3} s gap-shape, {:.3} s fitted (best of three)",
                best_of_three(&joint, &default)?,
                best_of_three(&joint, &fitted)?
            );
        }
    }
    Ok(())
}
