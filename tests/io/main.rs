//! Integration tests of `boltzone::io`: the 1970 card decks of Appendices B and C read as the
//! listing reads them, run on the report's element against exact solutions, written back, bad
//! decks named by line and field, and the `deck` command; the curve (CSV) and field (VTU)
//! outputs read back by independent readers.

mod cli;
#[path = "../common/mod.rs"]
mod common;
mod csv_out;
mod curve_hankel;
mod exact;
mod fields;
mod figure_joint;
mod figure_map;
mod figure_png;
mod json_out;
mod mutants;
mod plot_out;
mod py;
mod read;
mod report_cases;
mod svg_util;
mod thermal_vtu;
mod vtu;
