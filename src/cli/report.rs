//! `two --report FILE.md`: a one-page calculation report of the user's joint in Markdown — the
//! boltzone version, units and command, the inputs as understood (defaults filled in), the method
//! and its error estimate, the results, the rules of thumb beside R_o with their errors, and the
//! figure of `--plot` when one is drawn. Checked by `tests/io/plot_out.rs` (the record against
//! the run's JSON, the rules against their closed forms).
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/io/plot_out.rs`
//! (`calculation_report_records_inputs_results_and_rules`) checks it against the run's JSON and the
//! cones' closed forms.
//!
//! # Cost
//!
//! Milliseconds, after the solve.

use super::figure::rule_radii;
use boltzone::contact::two_plate::TwoPlateSolution;
use std::fmt::Write;
use std::path::Path;

/// What the report shows besides the solution: the parsed arguments, the joint's A, B, D, D₂,
/// C (None: infinite), the bearing pressure P (psi), the tolerance and the figure's path.
pub struct ReportInputs<'a> {
    /// The arguments as understood (serialized).
    pub inputs: serde_json::Value,
    /// A, B, D, D₂, C.
    pub geometry: (f64, f64, f64, f64, Option<f64>),
    /// Mean bearing pressure P (psi).
    pub pressure: f64,
    /// Wanted relative error of R_o.
    pub tolerance: f64,
    /// The `--plot` file, if any.
    pub plot: Option<&'a Path>,
}

/// The report as Markdown.
pub fn two_report(s: &TwoPlateSolution, r: &ReportInputs<'_>) -> String {
    let (a, b, d, d2, c) = r.geometry;
    let mut m = String::new();
    let _ = writeln!(m, "# Calculation report: bolted joint, two-plate model\n");
    let _ = writeln!(
        m,
        "boltzone {}; units {} (lengths in, stresses psi, forces lbf).\n\nCommand: `{}`\n",
        env!("CARGO_PKG_VERSION"),
        super::output::UNITS,
        super::output::command_line()
    );
    m += "## Inputs\n\n| input | value | unit |\n|---|---|---|\n";
    if let serde_json::Value::Object(map) = &r.inputs {
        for (k, v) in map.iter().filter(|(_, v)| !v.is_null()) {
            let shown = match v {
                serde_json::Value::String(t) => t.clone(),
                v => v.to_string(),
            };
            let _ = writeln!(m, "| {k} | {shown} | {} |", unit_of(k));
        }
    }
    let last = s.info.levels.last();
    let _ = writeln!(
        m,
        "\n## Method\n\nThe two-plate model of Gould & Mikic (1970), Chapter II.B: axisymmetric \
         finite elements, unilateral contact at the interface ({} model). The mesh is refined \
         at A, B and R_o level by level until the error estimate of R_o (max(|d₃|, |d₂|/4, \
         |d₁|/16) of the last level changes, plus the error of cutting a wide plate) meets the \
         relative tolerance {}: {} levels, finest mesh {} nodes / {} unknowns, {:.2} s.\n",
        s.info.model,
        r.tolerance,
        s.info.levels.len(),
        last.map_or(0, |l| l.nodes),
        last.map_or(0, |l| l.dofs),
        s.info.seconds
    );
    m += "## Results\n\n| quantity | value |\n|---|---|\n";
    let _ = writeln!(
        m,
        "| separation radius R_o | {:.6} ± {:.1e} in |",
        s.r_o, s.r_o_error
    );
    if a > 0.0 {
        let _ = writeln!(m, "| R_o / A | {:.5} |", s.r_o / a);
    }
    let yes = |x: bool| if x { "yes" } else { "no" };
    let _ = writeln!(m, "| contact diameter 2R_o | {:.6} in |", 2.0 * s.r_o);
    let _ = writeln!(m, "| converged to the tolerance | {} |", yes(s.converged));
    let _ = writeln!(m, "| full contact (R_o = C) | {} |", yes(s.full_contact));
    let _ = writeln!(m, "| mean bearing pressure P | {:.6e} psi |", r.pressure);
    let _ = writeln!(
        m,
        "| deflection under the nut | {:.4e} in |",
        s.nut_deflection
    );
    m += "\n## Rules of thumb\n\nContact radius R of each rule and its error against the \
          computed R_o.\n\n| rule | R [in] | (R − R_o)/R_o |\n|---|---|---|\n";
    for (name, radius) in rule_radii((b, d, d2, c)) {
        let _ = writeln!(
            m,
            "| {name} | {radius:.4} | {:+.1} % |",
            100.0 * (radius - s.r_o) / s.r_o
        );
    }
    if let Some(p) = r.plot {
        let _ = writeln!(
            m,
            "\n## Figure\n\n![interface pressure against r]({})",
            p.display()
        );
    }
    m
}

/// The unit of a `two` flag's value ("" for counts, names, switches and ratios).
fn unit_of(flag: &str) -> &'static str {
    match flag {
        "a" | "b" | "c" | "d" | "d2" | "nut_displacement" => "in",
        "e" | "e2" | "p" => "psi",
        "force" => "lbf",
        _ => "",
    }
}
