//! `two --plot FILE` and `single --plot FILE` (SVG or PNG by the extension): the interface
//! pressure p(r) of the user's joint, or the single plate's midplane σ_z, against r, with the bearing face's edge B, the computed separation radius R_o and the
//! rules of thumb's contact radii (45° cone R = B + D, VDI 2230 for a finite plate, 30° cone R =
//! B + D tan 30°, [`boltzone::rules`]) marked, in the style of the report's Figs. 15–27. Drawn
//! by [`boltzone::plot::CurveFigure`]; checked by `tests/io/plot_out.rs` (the markers against the
//! rules' closed forms, the PNG size).
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/io/plot_out.rs` (`plots_mark_r_o_and_the_rules`) checks the
//! marked radii against the run's JSON and the cones' closed forms.
//!
//! # Cost
//!
//! Milliseconds per figure, after the solve.

use super::exit::usage;
use boltzone::plot::{write_figure, Curve, CurveFigure, Marker, PALETTE};
use boltzone::route::rules_beside;
use boltzone::OuterRadius;
use std::path::{Path, PathBuf};

/// Pixel size of the figure.
pub const SIZE: (u32, u32) = (900, 600);

/// FILE with `-{what}` appended to its stem (`p.svg` → `p-gap.svg`).
pub fn sibling(path: &Path, what: &str) -> PathBuf {
    let stem = path
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let ext = path
        .extension()
        .map_or_else(String::new, |e| format!(".{}", e.to_string_lossy()));
    path.with_file_name(format!("{stem}-{what}{ext}"))
}

/// Rejects a `--plot` path whose extension is neither svg nor png (exit 2).
pub fn check_plot_path(flag: &str, path: &Path) -> anyhow::Result<()> {
    match path.extension().and_then(|e| e.to_str()) {
        Some("svg" | "png") => {
            super::check::output_path(flag, path)?;
            for what in ["gap", "deformed"] {
                super::check::output_path(flag, &sibling(path, what))?;
            }
            Ok(())
        }
        _ => usage(flag, path.display(), "must end in .svg or .png"),
    }
}

/// A curve against r for [`radius_plot`]: caption, y axis label, legend text, the points and
/// the computed R_o with its error.
pub struct RadiusCurve<'a> {
    /// Caption.
    pub title: String,
    /// y axis label (with unit).
    pub y_label: &'a str,
    /// Legend text of the curve.
    pub label: &'a str,
    /// Radii (increasing).
    pub r: &'a [f64],
    /// Values at the radii.
    pub y: &'a [f64],
    /// Computed separation radius and its error estimate (in `length`).
    pub r_o: (f64, f64),
    /// Symbol of the length unit of r, B, R_o (`in`, `mm`, `m`).
    pub length: &'a str,
}

/// Draws `curve` against r with B, R_o and the rules' radii marked to `path` ([`radius_figure`]).
/// Returns the right end of the r axis.
pub fn radius_plot(
    path: &Path,
    curve: &RadiusCurve<'_>,
    geom: (f64, f64, f64, Option<f64>),
) -> anyhow::Result<f64> {
    let (fig, x_end) = radius_figure(curve, geom);
    write_figure(&fig, path, SIZE)?;
    eprintln!("wrote {}", path.display());
    Ok(x_end)
}

/// `curve` against r with B, R_o and the rules' radii marked, and the right end of its r
/// axis. `b`, `d` and `d2` are the bearing radius and the plates' thicknesses, `c` the plate
/// radius (None: infinite).
pub fn radius_figure(
    curve: &RadiusCurve<'_>,
    (b, d, d2, c): (f64, f64, f64, Option<f64>),
) -> (CurveFigure, f64) {
    let (r_o, r_o_error) = curve.r_o;
    let l = curve.length;
    let mut markers = vec![
        Marker {
            label: format!("B = {b:.4} {l}"),
            x: b,
            color: PALETTE[1],
        },
        Marker {
            label: format!("Rₒ = {r_o:.4} ± {r_o_error:.1e} {l} (computed)"),
            x: r_o,
            color: PALETTE[6],
        },
    ];
    // one Okabe–Ito colour per series (curve black as in the report's figures)
    let colors = [PALETTE[5], PALETTE[3], PALETTE[7]];
    for ((name, radius), color) in rule_radii((b, d, d2, c)).into_iter().zip(colors) {
        markers.push(Marker {
            label: format!("{name}: R = {radius:.4} {l}"),
            x: radius,
            color,
        });
    }
    // room right of the markers for the legend (upper right), within the plate
    let x_end = markers.iter().map(|m| m.x).fold(r_o, f64::max) * 1.6;
    let x_end = x_end.min(curve.r.last().copied().unwrap_or(r_o));
    let points: Vec<(f64, f64)> = curve
        .r
        .iter()
        .zip(curve.y)
        .filter(|(r, _)| **r <= x_end)
        .map(|(r, y)| (*r, *y))
        .collect();
    let y_min = points.iter().map(|p| p.1).fold(0.0, f64::min);
    let y_max = points.iter().map(|p| p.1).fold(0.0, f64::max);
    let pad = 0.1 * (y_max - y_min).max(f64::MIN_POSITIVE);
    let fig = CurveFigure {
        title: curve.title.clone(),
        x_label: format!("r [{l}]"),
        y_label: curve.y_label.into(),
        curves: vec![Curve {
            label: curve.label.into(),
            points,
            color: PALETTE[0],
        }],
        markers,
        x_range: (curve.r.first().copied().unwrap_or(0.0), x_end),
        // room above the curve for the legend (a quarter of the plot's height and a margin)
        y_range: (
            y_min - if y_min < 0.0 { pad } else { 0.0 },
            y_max + 5.0 * pad,
        ),
    };
    (fig, x_end)
}

/// The rules of thumb's contact radii for bearing radius `b`, plates `d` (under the head) and
/// `d2` thick and plate radius `c` (None: infinite): the 45° cone, VDI 2230 (finite plates
/// only: it needs the plate's diameter) and the 30° cone, each with its name.
pub fn rule_radii((b, d, d2, c): (f64, f64, f64, Option<f64>)) -> Vec<(&'static str, f64)> {
    let c = c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    rules_beside::radii((b, d, d2, c), 30.0)
        .0
        .into_iter()
        .map(|(name, cone)| (name, cone.radius))
        .collect()
}
