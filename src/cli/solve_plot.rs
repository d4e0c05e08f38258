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

use super::joint_figs::{interface_figures, sibling, Interface, JointFigure};
use boltzone::scene::{Method, Scene, Solution};
use std::path::Path;

/// The figures of `s` (the answer to `scene`): p(r) (file suffix "") and, from the finite
/// elements, g(r) ("gap"), each with its caption. The semi-analytic curve ends at R_o, where p
/// vanishes: it is drawn on to 1.6 × the largest marked radius at p = 0 (exact there), and the
/// route gives no gap beyond R_o.
pub fn figures(
    scene: &Scene,
    s: &Solution,
) -> anyhow::Result<Vec<(&'static str, &'static str, JointFigure)>> {
    let Some(c) = &s.interface else {
        anyhow::bail!("the scene's answer has no interface curve to plot");
    };
    let d = scene.plates[0].thickness;
    let d2 = scene.plates.last().map_or(d, |p| p.thickness);
    let geom = (scene.load.outer_radius, d, d2, scene.joint.outer_radius);
    let (mut r, mut p) = (c.radius.clone(), c.pressure.clone());
    let hankel = s.method == Method::Hankel;
    if hankel {
        let end = super::figure::rule_radii(geom)
            .iter()
            .map(|r| r.1)
            .fold(s.r_o, f64::max)
            * 1.6;
        r.extend([s.r_o, end]);
        p.extend([0.0, 0.0]);
    }
    let iface = Interface {
        r: &r,
        p: &p,
        gap: (!hankel).then_some(&c.gap[..]),
        r_o: (s.r_o, s.r_o_error),
        model: format!(
            "model: {}, method: {}",
            scene_model(scene),
            s.method.as_str()
        ),
        source: "",
        units: scene.units,
    };
    Ok(interface_figures(&iface, geom).0)
}

/// Writes the figures of `s` (the answer to `scene`, [`figures`]) to `path` and its `-gap`
/// sibling; notes on stderr when the route gives no gap figure.
pub fn write(path: &Path, scene: &Scene, s: &Solution) -> anyhow::Result<()> {
    for (suffix, _, fig) in figures(scene, s)? {
        match suffix {
            "" => fig.write(path)?,
            _ => fig.write(&sibling(path, suffix))?,
        }
    }
    super::joint_figs::write_joint_diagram(path, &s.joint, scene.units)?;
    if s.method == Method::Hankel {
        eprintln!(
            "note: outputs.plot: no gap figure, the semi-analytic route gives the gap only where \
             the plates touch (method = \"fem\" draws it)"
        );
    }
    Ok(())
}

/// The interface model as the scene names it.
fn scene_model(scene: &Scene) -> String {
    serde_json::to_value(scene.joint.interface)
        .ok()
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_default()
}
