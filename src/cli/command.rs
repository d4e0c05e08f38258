//! The command line's grammar and its dispatch: one subcommand per module of `cli/`, and the
//! built-in default case when none is given.
//!
//! ```text
//! boltzone                     # the default case (Table 1's first joint)
//! boltzone two --a 0.1 --b 0.31 --d 0.1 --c 1.54 --json
//! ```
//!
//! # Accuracy
//!
//! No numerics: every subcommand is run by `tests/cli/` (`readme.rs`, `fuzz.rs`, `regressions.rs`).
//!
//! # Cost
//!
//! Parsing only.

use super::exit::Status;
use super::{
    deck, default_case, figures, map, materials, reference, serve, single, slab, solve, table1,
    table2, two,
};
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
    Two(Box<two::Args>),
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
    /// List the material library scenes name: E, ν, α, k, hardness, with sources.
    Materials(materials::Args),
}

/// Runs the chosen command; with none, the built-in default case. The status says whether
/// every value printed met its tolerance (exit codes: [`exit`]).
pub fn run(cli: Cli) -> anyhow::Result<Status> {
    match cli.command {
        None => default_case::run(),
        Some(Command::Slab(a)) => slab::run(a),
        Some(Command::Single(a)) => single::run(a),
        Some(Command::Two(a)) => two::run(*a),
        Some(Command::Table1(a)) => table1::run(a),
        Some(Command::Table2(a)) => table2::run(a),
        Some(Command::Map(a)) => map::run(a),
        Some(Command::Figures(a)) => figures::run(a),
        Some(Command::Serve(a)) => serve::run(a),
        Some(Command::Deck(a)) => deck::run(a),
        Some(Command::Solve(a)) => solve::run(a),
        Some(Command::Reference) => reference::run().map(|()| Status::Converged),
        Some(Command::Materials(a)) => materials::run(a).map(|()| Status::Converged),
    }
}
