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
mod command;
mod deck;
mod default_case;
pub mod exit;
mod figure;
mod figures;
mod friction_out;
mod hankel_curve;
mod joint_figs;
mod map;
mod materials;
mod output;
mod print;
mod reference;
mod report;
mod serve;
mod single;
mod slab;
mod solve;
mod solve_plot;
mod solve_report;
mod table1;
mod table2;
mod table_units;
mod two;
mod two_args;
mod two_bolt;
mod two_bolt_args;
mod two_curve;
mod two_files;
mod two_hankel;
mod two_heat;
mod two_pair;
mod two_question;
mod two_rim;
mod two_table;

pub use command::{run, Cli};
use print::{print_json, progress, write_output};
