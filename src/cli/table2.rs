//! `boltzone table2`: the report's Table 2 recomputed ([`boltzone::compare::table2`]): our
//! two-plate 2R_o of the seven test joints beside the report's and the measured ranges.
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/compare/tables.rs` (`table2_end_to_end`).
//!
//! # Cost
//!
//! Seven two-plate solves (example 04).

use super::args::TableOutput;
use super::exit::Status;
use super::two::Interface;
use super::{progress, write_output};
use boltzone::compare::table2;
use boltzone::contact::two_plate::InterfaceModel;
use clap::ValueEnum;

/// Arguments of `boltzone table2`.
#[derive(Debug, clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    #[command(flatten)]
    out: TableOutput,
    #[command(flatten)]
    units: super::args::Units,
    /// Interface model of unequal pairs (welded is the report's).
    #[arg(long, value_enum, default_value_t = Interface::Welded)]
    interface: Interface,
}

const FRICTION_NOTE: &str =
    "table2 compares the welded and frictionless models; for friction run `boltzone two --interface friction --mu M`";

/// Runs `boltzone table2`.
pub fn run(args: Args) -> anyhow::Result<Status> {
    args.out.check()?;
    let model = match args.interface {
        Interface::Welded => InterfaceModel::Welded,
        Interface::Frictionless => InterfaceModel::Frictionless,
        Interface::Friction => return super::exit::usage("--interface", "friction", FRICTION_NOTE),
    };
    let t = std::time::Instant::now();
    let bar = progress(7, "Table 2");
    let rows = table2::compute(model, args.out.tol, &|| bar.inc(1))?;
    bar.finish_and_clear();
    if args.out.json {
        super::print_json(&super::table_units::rows_json(
            &rows,
            args.units.units,
            &[
                "two_r_o.value",
                "two_r_o.error",
                "report.computed",
                "report.d1",
                "report.d2",
                "report.d_table",
                "report.two_b",
                "report.rubbing.min",
                "report.rubbing.max",
                "report.rubbing.average",
                "report.autoradiographic.min",
                "report.autoradiographic.max",
                "report.autoradiographic.average",
            ],
        )?)?;
    } else {
        print!("{}", table2::text_in(&rows, args.units.units));
        let name = args
            .interface
            .to_possible_value()
            .map(|v| v.get_name().to_string());
        println!(
            "\nunequal pairs: {} interface; 7 cases in {:.2} s",
            name.unwrap_or_default(),
            t.elapsed().as_secs_f64()
        );
    }
    if let Some(path) = &args.out.csv {
        write_output(path, &table2::csv_in(&rows, args.units.units))?;
    }
    let converged = rows.iter().all(|r| r.two_r_o.converged);
    if !converged && !args.out.json {
        println!("some values missed --tol (marked NOT converged): exit 3");
    }
    Ok(Status::from_converged(converged))
}
