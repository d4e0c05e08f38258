//! `boltzone reference`: the report's Table 1 as stored in `reference/` (data, not results).
//!
//! # Accuracy
//!
//! No numerics: prints stored data; `tests/compare/reference.rs` checks that the transcribed numbers agree with one another
//! within their printed rounding.
//!
//! # Cost
//!
//! None.

/// Prints Table 1 as transcribed from the report.
pub fn run() -> anyhow::Result<()> {
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
