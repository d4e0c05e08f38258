//! What every output carries: the provenance of a JSON object (version, units, the command line,
//! the inputs as understood) and the one CSV layout of every curve.
//!
//! CSV layout: ONE header row first, whose names carry their units (`r [in]`, `p [psi]`), then
//! `#` comment lines with the provenance, then the data. The comments come AFTER the header
//! because `numpy.genfromtxt(names=True)` takes its names from the first line even when that
//! line is a comment; `numpy.genfromtxt(FILE, comments="#", names=True, delimiter=",")` and
//! `pandas.read_csv(FILE, comment="#")` both skip the comment lines that follow. Numbers are
//! printed in Rust's shortest round-trip exponent form (`1.25e-1`): every reader gets the f64
//! back exactly. Checked by `tests/io/csv_out.rs` (numpy reads each command's curve) and
//! `tests/io/json_out.rs` (every JSON object's provenance).
//!
//! # Accuracy
//!
//! No numerics: `tests/io/json_out.rs`
//! (`every_json_object_carries_version_units_inputs_and_timing`) and `tests/io/csv_out.rs` (numpy
//! reads every curve back).
//!
//! # Cost
//!
//! Linear in the output.

use serde::Serialize;
use serde_json::Value;
use std::time::Instant;

/// The unit system of every command today: lengths in inches, stresses in psi, forces in lbf.
pub const UNITS: &str = "in-psi-lbf";

/// The command line as typed (arguments joined by spaces, quoted when they hold one).
pub fn command_line() -> String {
    std::env::args()
        .map(|a| {
            if a.contains(char::is_whitespace) || a.is_empty() {
                format!("'{a}'")
            } else {
                a
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Adds `version`, `units` (in-psi-lbf unless `v` names its own), `command` and `inputs` (the parsed arguments with defaults filled
/// in; flags not given and without a default are left out) to the JSON object `v`, and
/// `seconds` since `start` when `v` has no timing of its own. Existing keys are kept.
pub fn stamp<T: Serialize>(v: &mut Value, inputs: &T, start: Instant) -> anyhow::Result<()> {
    let mut inputs = serde_json::to_value(inputs)?;
    if let Value::Object(m) = &mut inputs {
        m.retain(|_, x| !x.is_null());
    }
    let Value::Object(m) = v else {
        anyhow::bail!("internal: only a JSON object carries provenance");
    };
    m.entry("units").or_insert_with(|| UNITS.into());
    m.insert("inputs".into(), inputs);
    stamp_run(v, start)
}

/// Adds `version`, `command` and `seconds` since `start` to the JSON object `v` where it has
/// none (a scene's result carries its own `units` and `inputs`, in the scene's units).
pub fn stamp_run(v: &mut Value, start: Instant) -> anyhow::Result<()> {
    let Value::Object(m) = v else {
        anyhow::bail!("internal: only a JSON object carries provenance");
    };
    m.entry("version")
        .or_insert_with(|| env!("CARGO_PKG_VERSION").into());
    m.entry("command").or_insert_with(|| command_line().into());
    m.entry("seconds")
        .or_insert_with(|| start.elapsed().as_secs_f64().into());
    Ok(())
}

/// A curve as CSV in the one layout of the module docs, in the unit system `units` (its units
/// line says which): `columns` (names with units, the first is `r [in]` or its length),
/// provenance `notes` (one `#` line each, after the standard lines: version, command, units)
/// and `rows` of equal length.
pub fn curve_csv_in(
    units: boltzone::scene::UnitSystem,
    columns: &[&str],
    notes: &[String],
    rows: &[Vec<f64>],
) -> String {
    let (l, st, f) = units.symbols();
    let mut out = columns.join(",");
    out += "\n";
    out += &format!("# boltzone {}\n", env!("CARGO_PKG_VERSION"));
    out += &format!("# command: {}\n", command_line());
    out += &format!(
        "# units: {} (lengths {l}, stresses {st}, forces {f})\n",
        units.name()
    );
    for n in notes {
        out += &format!("# {}\n", n.replace('\n', " "));
    }
    for row in rows {
        let line: Vec<String> = row.iter().map(|x| format!("{x:e}")).collect();
        out += &line.join(",");
        out += "\n";
    }
    out
}

/// The provenance line of an R_o with the length symbol `l`: value ± error, and whether it met
/// the tolerance.
pub fn r_o_note_in(l: &str, r_o: f64, error: f64, converged: bool) -> String {
    format!("R_o = {r_o:e} {l} +- {error:.2e} {l}, converged: {converged}")
}
