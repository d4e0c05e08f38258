//! `[outputs] report = "FILE.md"` (or `.html`) of a two-plate scene, written by `boltzone
//! solve`: the calculation report of `two --report` ([`super::report`]) for the scene's joint —
//! the version, units and command, the scene as understood (dotted keys, defaults filled in,
//! each with its unit), the route that answered and why (the scene's plan), R_o with its
//! error bar, the rules of thumb beside it, and the figures of `[outputs] plot`
//! ([`super::solve_plot::figures`]): Markdown links the plot files (none without `plot`), HTML
//! inlines them as SVG. One joint only: a `[sweep]` or `--geometries` run refuses the key.
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/scene/outputs.rs` checks the report's R_o, bar and rules
//! against the run's JSON.
//!
//! # Cost
//!
//! Milliseconds, after the solve.

use super::args::Units;
use super::report::{render, shown, two_report, Answer, ReportInputs};
use boltzone::scene::{Scene, Solution};
use std::f64::consts::PI;
use std::path::Path;

/// `v` flattened into (dotted key, value) pairs (`hole.radius`, `plates.0.thickness`).
fn flatten(
    prefix: &str,
    v: &serde_json::Value,
    out: &mut serde_json::Map<String, serde_json::Value>,
) {
    let key = |k: &str| match prefix {
        "" => k.to_string(),
        p => format!("{p}.{k}"),
    };
    match v {
        serde_json::Value::Object(m) => m.iter().for_each(|(k, v)| flatten(&key(k), v, out)),
        serde_json::Value::Array(a) if a.iter().any(|x| x.is_object()) => a
            .iter()
            .enumerate()
            .for_each(|(i, v)| flatten(&key(&i.to_string()), v, out)),
        v => {
            out.insert(prefix.to_string(), v.clone());
        }
    }
}

/// Writes the report of `s` (the answer to `scene`) to `path`.
pub fn write(path: &Path, scene: &Scene, s: &Solution) -> anyhow::Result<()> {
    let html = super::report::is_html(path);
    let figs = super::solve_plot::figures(scene, s)?;
    let shown = shown(&figs, scene.outputs.plot.as_deref(), html)?;
    let mut inputs = serde_json::Map::new();
    flatten("", &serde_json::to_value(&s.inputs)?, &mut inputs);
    let d = scene.plates[0].thickness;
    let d2 = scene.plates.last().map_or(d, |p| p.thickness);
    let (a, b) = (scene.hole.radius, scene.load.outer_radius);
    let pressure = match (scene.load.force, scene.load.pressure) {
        (Some(f), _) => f / (PI * (b * b - a * a)),
        (None, p) => p.unwrap_or(f64::NAN),
    };
    let ran: Vec<String> = s
        .plan
        .iter()
        .filter(|step| step.ran)
        .map(|step| format!("{}: {}", step.name, step.note))
        .collect();
    let answer = Answer {
        r_o: boltzone::Value {
            value: s.r_o,
            error: s.r_o_error,
            converged: s.converged,
        },
        full_contact: s.full_contact.unwrap_or(false),
        nut_deflection: s.nut_deflection,
        method: format!(
            "The two-plate model of Gould & Mikic (1970), Chapter II.B, by the route `{}` at the \
             relative tolerance {} (the scene's plan: {}).",
            s.method.as_str(),
            scene.tolerance,
            ran.join("; ")
        ),
    };
    let inputs = ReportInputs {
        inputs: inputs.into(),
        geometry: (a, b, d, d2, scene.joint.outer_radius),
        pressure,
        units: Units { units: scene.units },
    };
    let blocks = two_report(&answer, &inputs, shown);
    super::write_output(path, &render(path, &blocks))
}
