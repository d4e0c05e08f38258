//! The files of `boltzone two` besides the figures and the report: the interface curve as CSV
//! (r, p, g, τ; with friction also the slip and the node state) and the finest mesh's field as
//! VTU, each labelled in the `--units` system.
//!
//! # Accuracy
//!
//! No numerics: `tests/scene/joint_units.rs` (headers and notes in mm-MPa-N),
//! `tests/contact/cli.rs` (`json_and_curve`) and `tests/io/csv_out.rs` (numpy reads the curve).
//!
//! # Cost
//!
//! Linear in the number of interface nodes and mesh nodes.

use super::args::Units;
use boltzone::contact::two_plate::{TwoPlateField, TwoPlateSolution};

/// r, p, g, τ of the finest mesh in the one curve layout ([`super::output`]), in `units`.
pub fn curve_csv(s: &TwoPlateSolution, p: f64, units: Units) -> String {
    let (l, st) = (units.length(), units.stress());
    let notes = [
        format!(
            "method: two-plate FE contact (boltzone::contact::two_plate), interface of the finest \
             mesh; model: {}",
            s.info.model
        ),
        format!(
            "p = interface pressure (compression > 0), g = gap between the plates, tau = \
             interface shear on the upper plate (welded and friction models, 0 otherwise); bearing pressure P = \
             {p:e} {st}"
        ),
        super::output::r_o_note_in(l, s.r_o, s.r_o_error, s.converged),
    ];
    let cols = [
        format!("r [{l}]"),
        format!("p [{st}]"),
        format!("g [{l}]"),
        format!("tau [{st}]"),
    ];
    if let Some(f) = &s.friction {
        return super::friction_out::curve_csv(s, f, &notes, (units, &cols));
    }
    let rows: Vec<Vec<f64>> = (0..s.radius.len())
        .map(|i| vec![s.radius[i], s.pressure[i], s.gap[i], s.shear[i]])
        .collect();
    let cols: Vec<&str> = cols.iter().map(String::as_str).collect();
    super::output::curve_csv_in(units.units, &cols, &notes, &rows)
}

/// The finest mesh's field as VTU ([`boltzone::io::vtu`]): plate 0 the lower plate, plate 1
/// the upper one; interface nodes of both carry the contact pressure, the gap and the status
/// (1 closed, 0 open), every other node 0.
pub fn field_vtu(
    s: &TwoPlateSolution,
    field: &TwoPlateField,
    units: Units,
) -> anyhow::Result<String> {
    let (l, st) = (units.length(), units.stress());
    let (grid, layout) = boltzone::scene::field::two_plate_grid(s, field)?;
    let note = format!(
        "method: two-plate FE contact, finest mesh, {} model; {layout}; units {}: coordinates \
         and displacements [{l}], stresses [{st}]; interface nodes carry contact_pressure [{st}] \
         (compression > 0), gap [{l}] (between the plates) and contact_status (1 closed, 0 \
         open); {}; command: {}",
        s.info.model,
        units.units.name(),
        super::output::r_o_note_in(l, s.r_o, s.r_o_error, s.converged),
        super::output::command_line()
    );
    Ok(grid.to_vtu(&note))
}
