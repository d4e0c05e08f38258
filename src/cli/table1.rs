//! `boltzone table1`: the report's Table 1 recomputed end to end ([`boltzone::compare::table1`]):
//! single-plate and two-plate R_o/A, the discrepancies and the rules of thumb for its twelve
//! geometries, the report's values beside ours.

use super::{progress, write_output};
use boltzone::compare::{table1, CompareParams};
use std::path::PathBuf;

/// Arguments of `boltzone table1`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Print one JSON array (ours and the report's per row) instead of the text table.
    #[arg(long)]
    json: bool,
    /// Also write the table as CSV to FILE.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Relative tolerance of each R_o.
    #[arg(long, default_value_t = 5e-4)]
    tol: f64,
    /// Skip the second single-plate method (Hankel transforms with the hole correction, C = ∞).
    #[arg(long)]
    no_hankel: bool,
}

/// Runs `boltzone table1`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let params = CompareParams {
        tolerance: args.tol,
        hankel_check: !args.no_hankel,
        ..Default::default()
    };
    let t = std::time::Instant::now();
    let bar = progress(12, "Table 1");
    let rows = table1::compute(&params, &|| bar.inc(1))?;
    bar.finish_and_clear();
    if args.json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
    } else {
        print!("{}", table1::text(&rows));
        println!(
            "\n{} geometries in {:.2} s (relative tolerance {:e} per R_o)",
            rows.len(),
            t.elapsed().as_secs_f64(),
            args.tol
        );
    }
    if let Some(path) = &args.csv {
        write_output(path, &table1::csv(&rows))?;
    }
    Ok(())
}
