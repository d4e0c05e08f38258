//! `[outputs] plot = "FILE.svg"` (or .png) of a two-plate scene, written by `boltzone solve`:
//! the interface pressure p(r) to FILE and the gap g(r) to FILE-gap, against r with B, R_o and
//! the rules of thumb's radii marked — the figures of `two --plot` ([`super::figure`]), in the
//! scene's units. One joint only: a `[sweep]` or `--geometries` run refuses the key.
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/scene/outputs.rs` checks the marked radii against the run's
//! JSON.
//!
//! # Cost
//!
//! Milliseconds per figure, after the solve.

use super::figure::{radius_plot, sibling, RadiusCurve};
use boltzone::scene::{Method, Scene, Solution};
use std::path::Path;

/// Writes the pressure and the gap figure of `s` (the answer to `scene`) to `path` and its
/// `-gap` sibling.
pub fn write(path: &Path, scene: &Scene, s: &Solution) -> anyhow::Result<()> {
    let Some(c) = &s.interface else {
        anyhow::bail!("the scene's answer has no interface curve to plot");
    };
    let (l, st, _) = scene.units.symbols();
    let d = scene.plates[0].thickness;
    let d2 = scene.plates.last().map_or(d, |p| p.thickness);
    let geom = (scene.load.outer_radius, d, d2, scene.joint.outer_radius);
    let model = format!(
        "model: {}, method: {}",
        scene_model(scene),
        s.method.as_str()
    );
    let (p_label, g_label) = (format!("p [{st}]"), format!("g [{l}]"));
    let curve = |title: &str, y_label, label, y| RadiusCurve {
        title: format!("{title}; {model}"),
        y_label,
        label,
        r: &c.radius,
        y,
        r_o: (s.r_o, s.r_o_error),
        length: l,
    };
    if s.method == Method::Hankel {
        // the semi-analytic curve ends at R_o, where p vanishes; beyond it p = 0 exactly, and
        // the route gives no gap there
        let end = super::figure::rule_radii(geom)
            .iter()
            .map(|r| r.1)
            .fold(s.r_o, f64::max)
            * 1.6;
        let (mut r, mut p) = (c.radius.clone(), c.pressure.clone());
        r.extend([s.r_o, end]);
        p.extend([0.0, 0.0]);
        let mut fig = curve("Interface pressure", &p_label, "p(r)", &p);
        fig.r = &r;
        radius_plot(path, &fig, geom)?;
        eprintln!(
            "note: outputs.plot: no gap figure, the semi-analytic route gives the gap only where \
             the plates touch (method = \"fem\" draws it)"
        );
        return Ok(());
    }
    let p = curve("Interface pressure", &p_label, "p(r)", &c.pressure);
    radius_plot(path, &p, geom)?;
    let g = curve("Gap between the plates", &g_label, "g(r)", &c.gap);
    radius_plot(&sibling(path, "gap"), &g, geom)?;
    Ok(())
}

/// The interface model as the scene names it.
fn scene_model(scene: &Scene) -> String {
    serde_json::to_value(scene.joint.interface)
        .ok()
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_default()
}
