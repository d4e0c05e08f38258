//! The interface curve of the semi-analytic two-plate routes (`two --method hankel --curve`,
//! [`super::two_hankel`] with the hole, [`super::two_pair`] without one) in the FE's CSV layout
//! (r, p, g, τ), with the units and the route named in its notes.
//!
//! # Accuracy
//!
//! The routes' (their modules); the layout is the FE's, checked by `tests/hankel/pair_cli.rs`
//! and `tests/hankel/two_plate_hole.rs`.
//!
//! # Cost
//!
//! One line per point.

use super::two_args::Args;

/// The interface curve in the FE's layout (r, p, g, τ): on A ≤ r ≤ R_o the gap is 0 and, the
/// interface being frictionless, so is τ; `method` names the route in the notes, `r_o` is
/// (R_o, its error).
pub(super) fn curve_csv(
    curve: &[(f64, f64)],
    method: &str,
    r_o: (f64, f64),
    converged: bool,
    args: &Args,
) -> String {
    let (l, st) = (args.units.length(), args.units.stress());
    let notes = [
        format!("method: {method}"),
        "p = interface pressure (compression > 0), g = gap between the plates (0 on the \
         contact zone), tau = interface shear (0: frictionless)"
            .to_string(),
        super::output::r_o_note_in(l, r_o.0, r_o.1, converged),
    ];
    let cols = [
        format!("r [{l}]"),
        format!("p [{st}]"),
        format!("g [{l}]"),
        format!("tau [{st}]"),
    ];
    let cols: Vec<&str> = cols.iter().map(String::as_str).collect();
    let rows: Vec<Vec<f64>> = curve.iter().map(|&(r, q)| vec![r, q, 0.0, 0.0]).collect();
    super::output::curve_csv_in(args.units.units, &cols, &notes, &rows)
}
