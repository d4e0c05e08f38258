//! Command-line front end: one module per command; errors are reported by `main`.
//!
//! # Accuracy
//!
//! No numerics: each command's test is named in its module; the command line's contract is
//! `tests/cli/`.
//!
//! # Cost
//!
//! None beyond the library calls.

mod args;
mod check;
mod deck;
pub mod exit;
mod figure;
mod figures;
mod friction_out;
mod hankel_curve;
mod joint_figs;
mod map;
mod output;
mod report;
mod serve;
mod single;
mod slab;
mod solve;
mod table1;
mod table2;
mod table_units;
mod two;
mod two_args;
mod two_files;
mod two_hankel;

use boltzone::compare::{compare, show, CompareParams, Geometry, Value};
use boltzone::reference;
use clap::{Parser, Subcommand};
use exit::Status;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::Path;

/// Contact zone and interface pressure of bolted plates (Gould & Mikic, MIT 1970, rebuilt).
///
/// Lengths in inches, pressures in psi (any consistent units work: results scale).
#[derive(Debug, Parser)]
#[command(name = "boltzone", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Infinite slab 2D thick, no hole, loaded on both faces (Hankel transforms): single-plate R_o.
    Slab(slab::Args),
    /// Single plate with a hole (Fernlund's substitution): R_o by finite elements or Hankel transforms.
    Single(single::Args),
    /// Two plates in unilateral contact (the report's two-plate model): R_o and interface pressure.
    Two(two::Args),
    /// Table 1 recomputed: single- vs two-plate R_o/A and the rules of thumb, report beside.
    Table1(table1::Args),
    /// Table 2 recomputed: two-plate 2R_o of the test joints beside the report's and the tests.
    Table2(table2::Args),
    /// Design map over A/D x B/A: both models and the rules' errors, as CSV and heat maps.
    Map(map::Args),
    /// The report's Figs. 12–29 and the classic slab curves as SVG, PNG and CSV, with a gallery.
    Figures(figures::Args),
    /// The teaching page and its JSON API (/api/joint) on a local HTTP server.
    Serve(serve::Args),
    /// Run 1970 card decks (Appendices B, C) on the report's element; --emit writes one.
    Deck(deck::Args),
    /// Answer a scene file (TOML: joint, load, model, outputs, units, sweep).
    Solve(solve::Args),
    /// Print the report's tables as stored in reference/ (data, not results).
    Reference,
}

/// Runs the chosen command; with none, the built-in default case. The status says whether
/// every value printed met its tolerance (exit codes: [`exit`]).
pub fn run(cli: Cli) -> anyhow::Result<Status> {
    match cli.command {
        None => default_case(),
        Some(Command::Slab(a)) => slab::run(a),
        Some(Command::Single(a)) => single::run(a),
        Some(Command::Two(a)) => two::run(a),
        Some(Command::Table1(a)) => table1::run(a),
        Some(Command::Table2(a)) => table2::run(a),
        Some(Command::Map(a)) => map::run(a),
        Some(Command::Figures(a)) => figures::run(a),
        Some(Command::Serve(a)) => serve::run(a),
        Some(Command::Deck(a)) => deck::run(a),
        Some(Command::Solve(a)) => solve::run(a),
        Some(Command::Reference) => reference().map(|()| Status::Converged),
    }
}

/// A progress bar on stderr (indicatif draws nothing when stderr is not a terminal).
fn progress(len: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::new(len);
    if let Ok(style) =
        ProgressStyle::with_template("{msg} {bar:40} {pos}/{len} [{elapsed} < {eta}]")
    {
        bar.set_style(style);
    }
    bar.set_message(what.to_string());
    bar
}

/// Keys whose value may be absent (printed as nothing rather than null).
const OPTIONAL_KEYS: [&str; 9] = [
    "rate",
    "cut",
    "observed_order",
    "r_o_over_a",
    "single_hankel",
    "autoradiographic",
    "discrepancy_autoradiographic_percent",
    "outer_radius",
    "hole_history",
];

/// Prints `value` as pretty JSON without its null entries: an absent quantity (no observed rate,
/// no hole) is left out rather than printed as null. serde_json prints a non-finite number as
/// null too: a null under any other key is therefore an error (exit 1), never a silent null.
fn print_json<T: serde::Serialize>(value: &T) -> anyhow::Result<()> {
    fn strip(v: &mut serde_json::Value, path: &str) -> anyhow::Result<()> {
        match v {
            serde_json::Value::Object(m) => {
                for (k, x) in m.iter() {
                    if x.is_null() && !OPTIONAL_KEYS.contains(&k.as_str()) {
                        anyhow::bail!("{path}.{k} is not a finite number (NaN or infinite)");
                    }
                }
                m.retain(|_, x| !x.is_null());
                for (k, x) in m.iter_mut() {
                    strip(x, &format!("{path}.{k}"))?;
                }
            }
            serde_json::Value::Array(a) => {
                for (i, x) in a.iter_mut().enumerate() {
                    if x.is_null() {
                        anyhow::bail!("{path}[{i}] is not a finite number (NaN or infinite)");
                    }
                    strip(x, &format!("{path}[{i}]"))?;
                }
            }
            _ => {}
        }
        Ok(())
    }
    let mut v = serde_json::to_value(value)?;
    strip(&mut v, "result")?;
    println!("{}", serde_json::to_string_pretty(&v)?);
    Ok(())
}

/// Writes `text` to `path` through a temporary file renamed into place.
fn write_output(path: &Path, text: &str) -> anyhow::Result<()> {
    boltzone::plot::write_atomic(path, text.as_bytes())?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// The built-in default case: Table 1's first geometry (A = D = 0.1 in, B = 0.31 in,
/// C = 1.54 in, ν = 0.3): both models' R_o, the rules of thumb, the report's values beside.
fn default_case() -> anyhow::Result<Status> {
    let report = reference::table1()[0];
    let g = Geometry::table1()[0];
    let params = CompareParams {
        hankel_check: true,
        ..CompareParams::default()
    };
    let c = compare(&g, &params)?;
    println!("boltzone: where do two bolted plates stay in contact?");
    println!(
        "Built-in default case = Table 1's first geometry (Gould & Mikic 1970): two equal plates\n\
         D = {} in thick, hole radius A = {} in, bearing face to B = {} in, plate radius C = {} in,\n\
         nu = {}, uniform bearing pressure. Contact for A <= r <= R_o. Ours ± error estimate [report].\n",
        short(g.d),
        short(g.a),
        short(g.b),
        short(g.c),
        g.nu
    );
    let line = |name: &str, v: Value, rep: Option<f64>, secs: f64| {
        let rep = rep.map(|x| format!("[{x}]")).unwrap_or_default();
        println!(
            "  {name:<38} R_o = {} in   R_o/A = {} {rep:>6}  {secs:.3} s",
            show(v, 5),
            show(c.over_a(v), 4)
        );
    };
    line(
        "two-plate model (the answer)",
        c.two,
        Some(report.two),
        c.info.seconds_two,
    );
    line(
        "single-plate substitution (FE, C)",
        c.single,
        Some(report.single),
        c.info.seconds_single,
    );
    if let Some(h) = c.single_hankel {
        line(
            "single plate, Hankel + hole (infinite C)",
            h,
            None,
            c.info.seconds_hankel,
        );
    }
    println!(
        "  discrepancy (single - two)/two: {} % [{} %]; in contact area: {} %",
        show(c.discrepancy_percent, 2),
        report.discrepancy_percent,
        show(c.area_discrepancy_percent, 1),
    );
    println!("\nRules of thumb (contact radius R, error against the two-plate R_o):");
    for r in &c.rules {
        println!(
            "  {:<16} half-angle {:>5.2}°   R = {:.4} in   R/A = {:.3}   {:+.1} ± {:.1} %",
            rule_name(r.name, r.half_angle_degrees),
            r.half_angle_degrees,
            r.radius,
            r.radius / g.a,
            r.error_percent.value,
            r.error_percent.error
        );
    }
    println!(
        "\nTotal {:.2} s. More: boltzone table1 | table2 | map | two | single --help",
        c.info.seconds
    );
    Ok(Status::from_converged(c.converged()))
}

/// A length without binary round-off noise (0.31, not 0.31000000000000005).
fn short(x: f64) -> String {
    format!("{}", (x * 1e9).round() / 1e9)
}

/// A rule's display name ("30° cone" for the extra cone).
fn rule_name(name: &str, degrees: f64) -> String {
    if name == "cone" {
        format!("{degrees:.0}° cone")
    } else {
        name.to_string()
    }
}

fn reference() -> anyhow::Result<()> {
    println!("Table 1 (Gould & Mikic 1970): R_o/A, single- and two-plate models");
    println!(
        "{:>6} {:>6} {:>8} {:>8} {:>8}",
        "A/D", "B/A", "single", "two", "disc %"
    );
    for r in boltzone::reference::table1() {
        println!(
            "{:>6} {:>6} {:>8} {:>8} {:>8}",
            r.a_over_d, r.b_over_a, r.single, r.two, r.discrepancy_percent
        );
    }
    Ok(())
}
