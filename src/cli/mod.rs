//! Command-line front end: one module per command; errors are reported by `main`.

mod args;
mod single;
mod slab;
mod two;

use clap::{Parser, Subcommand};

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
    /// Print the report's tables as stored in reference/ (data, not results).
    Reference,
}

/// Runs the chosen command; with none, the built-in default case.
pub fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        None => default_case(),
        Some(Command::Slab(a)) => slab::run(a),
        Some(Command::Single(a)) => single::run(a),
        Some(Command::Two(a)) => two::run(a),
        Some(Command::Reference) => reference(),
    }
}

/// The built-in default case: Table 1's first geometry (A = D = 0.1 in, B = 0.31 in, ν = 0.3).
fn default_case() -> anyhow::Result<()> {
    reference()
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
