//! What `boltzone two --interface friction` adds to its outputs: the stick and slip zones as
//! radius intervals (text and JSON), and the slip s(r) and node state as two more columns of
//! the one curve layout ([`super::output`]).
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/contact/friction_cli.rs` (`zones_curve_and_json_agree`: the zones
//! printed, in the JSON and in the curve's state column agree).
//!
//! # Cost
//!
//! Formatting only; the frictional solve it reports is timed by `examples/21_friction.rs`.

use boltzone::contact::friction::FrictionZones;
use boltzone::contact::two_plate::TwoPlateSolution;

fn zones(s: &TwoPlateSolution, f: &FrictionZones, slip: bool) -> Vec<[f64; 2]> {
    f.zones(&s.radius, slip)
}

fn largest_slip(f: &FrictionZones, s: &TwoPlateSolution) -> f64 {
    f.max_slip(&s.pressure)
}

/// Adds `mu`, `stick_zones` and `slip_zones` ([r₁, r₂] in the --units length, node to node)
/// and `max_slip` (same length, inside the contact zone) to the JSON object `out`.
pub fn json(
    out: &mut serde_json::Value,
    s: &TwoPlateSolution,
    f: &FrictionZones,
) -> anyhow::Result<()> {
    out["mu"] = f.mu.into();
    out["stick_zones"] = serde_json::to_value(zones(s, f, false))?;
    out["slip_zones"] = serde_json::to_value(zones(s, f, true))?;
    out["max_slip"] = largest_slip(f, s).into();
    Ok(())
}

/// One line for the text output: μ, the zones and the largest slip in the length `l`.
pub fn summary(s: &TwoPlateSolution, f: &FrictionZones, l: &str) -> String {
    let show = |z: Vec<[f64; 2]>| {
        if z.is_empty() {
            "none".to_string()
        } else {
            z.iter()
                .map(|[a, b]| format!("{a:.4}-{b:.4}"))
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    format!(
        "friction mu = {}: stick r = {} {l}; slip r = {} {l}; largest slip {:.3e} {l}",
        f.mu,
        show(zones(s, f, false)),
        show(zones(s, f, true)),
        largest_slip(f, s)
    )
}

/// The curve with the friction columns: r, p, g, τ (headed `columns`, in `units`), the slip
/// s = u_upper − u_lower and the node state (0 open, 1 stick, 2 slip).
pub fn curve_csv(
    s: &TwoPlateSolution,
    f: &FrictionZones,
    notes: &[String],
    (units, columns): (super::args::Units, &[String]),
) -> String {
    let mut notes = notes.to_vec();
    notes.push(format!(
        "friction mu = {}: s = slip u_upper - u_lower (outward > 0), state 0 open, 1 stick, 2 slip",
        f.mu
    ));
    let rows: Vec<Vec<f64>> = (0..s.radius.len())
        .map(|i| {
            let st = f.state[i];
            vec![
                s.radius[i],
                s.pressure[i],
                s.gap[i],
                s.shear[i],
                f.slip[i],
                st.code(),
            ]
        })
        .collect();
    let slip = format!("s [{}]", units.length());
    let mut cols: Vec<&str> = columns.iter().map(String::as_str).collect();
    cols.extend([slip.as_str(), "state [-]"]);
    super::output::curve_csv_in(units.units, &cols, &notes, &rows)
}
