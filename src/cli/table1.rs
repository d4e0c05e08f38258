//! `boltzone table1`: the report's Table 1 recomputed end to end ([`boltzone::compare::table1`]):
//! single-plate and two-plate R_o/A, the discrepancies and the rules of thumb for its twelve
//! geometries, the report's values beside ours.
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/compare/tables.rs` (`table1_end_to_end`) and
//! `tests/compare/cli.rs`.
//!
//! # Cost
//!
//! All of Table 1: `cargo bench --bench contact`.

use super::args::TableOutput;
use super::exit::Status;
use super::{progress, write_output};
use boltzone::compare::{table1, CompareParams};

/// Arguments of `boltzone table1`.
#[derive(Debug, clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    #[command(flatten)]
    out: TableOutput,
    #[command(flatten)]
    units: super::args::Units,
    /// Skip the second single-plate method (Hankel transforms with the hole correction, C = ∞).
    #[arg(long)]
    no_hankel: bool,
}

/// Runs `boltzone table1`.
pub fn run(args: Args) -> anyhow::Result<Status> {
    args.out.check()?;
    let params = CompareParams {
        tolerance: args.out.tol,
        hankel_check: !args.no_hankel,
        ..Default::default()
    };
    let t = std::time::Instant::now();
    let bar = progress(12, "Table 1");
    let rows = table1::compute(&params, &|| bar.inc(1))?;
    bar.finish_and_clear();
    if args.out.json {
        super::print_json(&super::table_units::rows_json(
            &rows,
            args.units.units,
            &[
                "ours.geometry.a",
                "ours.geometry.b",
                "ours.geometry.d",
                "ours.geometry.c",
                "ours.single.value",
                "ours.single.error",
                "ours.single_hankel.value",
                "ours.single_hankel.error",
                "ours.two.value",
                "ours.two.error",
                "ours.rules.*.radius",
            ],
        )?)?;
    } else {
        print!("{}", table1::text_in(&rows, args.units.units));
        println!(
            "\n{} geometries in {:.2} s (relative tolerance {:e} per R_o)",
            rows.len(),
            t.elapsed().as_secs_f64(),
            args.out.tol
        );
    }
    if let Some(path) = &args.out.csv {
        write_output(path, &table1::csv_in(&rows, args.units.units))?;
    }
    let converged = rows.iter().all(|r| r.ours.converged());
    if !converged && !args.out.json {
        println!("some values missed --tol (marked NOT converged): exit 3");
    }
    Ok(Status::from_converged(converged))
}
