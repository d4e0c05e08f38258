//! The built-in default case (`boltzone` with no subcommand): Table 1's first geometry, both
//! models' R_o with error bars, the rules of thumb and the report's values beside.
//!
//! # Accuracy
//!
//! No numerics: the numbers are `compare::compare`'s (`tests/compare/`); the command itself is run by `tests/cli/readme.rs`.
//!
//! # Cost
//!
//! One Table 1 row, about 0.1 s.

use super::exit::Status;
use boltzone::compare::{compare, show, CompareParams, Geometry, Value};
use boltzone::reference;

/// The built-in default case: Table 1's first geometry (A = D = 0.1 in, B = 0.31 in,
/// C = 1.54 in, ν = 0.3): both models' R_o, the rules of thumb, the report's values beside.
pub fn run() -> anyhow::Result<Status> {
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
    for r in c.rules.iter().flatten() {
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
