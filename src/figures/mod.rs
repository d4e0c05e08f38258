//! The report's figures recomputed (Gould & Mikic 1970, Figs. 12–29, whose drawings are lost
//! and whose captions survive), and the classic slab curves of the single-plate literature.
//!
//! Each figure is a [`FigureData`]: the report's caption as its title, curves computed from
//! the captions' cases (Chapter IV) by this crate's converged solvers, each curve with the
//! separation radius R_o it implies (value ± error estimate), and the report's printed values
//! beside them as [`DataSeries`] (Tables 1 and 2, the Chapter IV text). Sign convention:
//! compression negative for σ_z; interface pressure p ≥ 0 (compression positive), as the report
//! plots it; lengths in inches, stresses in psi.
//!
//! | figure | what | module |
//! |---|---|---|
//! | 12–14 | single plate 2D thick: midplane σ_z for D = 0.1, 0.1333, 0.2 in, four B each | [`single`] |
//! | 15–17 | two-plate interface pressure, the same twelve joints | [`single`] |
//! | 18–27 | Table 2's steel pairs: loads, nut displacement, deflection, edges, gap | [`pairs`] |
//! | 28 | computed against measured separation radii (Table 2) | [`experiments`] |
//! | 29 | the lap joint of Chapter V as assumed by [`crate::heat::lap`] | [`lap`] |
//! | slab | the no-hole slab's midplane σ_z for several B/D (Sneddon 1946) | [`slab`] |
//!
//! **Method.** The single plate by [`crate::fem::single`] (finest level of the study; its R_o
//! from the level estimate), the two plates by [`crate::contact::two_plate`], the slab by
//! [`crate::hankel::Slab`]; all at [`FiguresParams::tolerance`] relative to R_o.
//!
//! # Accuracy
//!
//! `tests/figures/main.rs`: every curve's sign change brackets its R_o within the curve's node
//! spacing and R_o's error bar (all 42 curves, `gallery.rs`); every marker is at the value of
//! the `reference/` files read independently (`markers.rs`); Fig. 22's nut curve is flat at the
//! prescribed −50 µin and its shape converged (`deflection.rs`); the units (`units.rs`).
//!
//! # Cost
//!
//! `boltzone figures` prints the time of each figure; the whole set at the default tolerance 5e-3
//! takes seconds (the test runs a few with `--only`).
//!
//! ```
//! use boltzone::figures::{compute, FiguresParams};
//! let fig = compute("slab", &FiguresParams::default())?;
//! assert!(fig.curves.iter().all(|c| c.r_o.is_some()));
//! # Ok::<(), boltzone::figures::FigureError>(())
//! ```

pub mod draw;
pub mod experiments;
pub mod lap;
pub mod pairs;
mod pairs_report;
pub mod single;
pub mod slab;
pub mod units;

use crate::value::Value;
use serde::Serialize;

/// Knobs of the figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiguresParams {
    /// Wanted error of every R_o relative to R_o (default 5e-3: the set in seconds; the
    /// report's resolution was one nodal interval, 0.015 in ≈ 4 % of R_o).
    pub tolerance: f64,
}

impl Default for FiguresParams {
    fn default() -> Self {
        Self { tolerance: 5e-3 }
    }
}

/// Why a figure could not be made.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// The id names no figure.
    #[error("no figure '{0}' (known: {known})", known = IDS.join(", "))]
    Unknown(String),
    /// Bad input to a solver.
    #[error(transparent)]
    Input(#[from] crate::error::InputError),
    /// The single-plate FE failed.
    #[error("figure {figure}: {source}")]
    Fem {
        /// The figure.
        figure: String,
        /// The cause.
        source: crate::fem::FemError,
    },
    /// The two-plate model failed.
    #[error("figure {figure}: {source}")]
    Contact {
        /// The figure.
        figure: String,
        /// The cause.
        source: crate::contact::ContactError,
    },
    /// The slab's separation search failed.
    #[error("figure {figure}: {source}")]
    Slab {
        /// The figure.
        figure: String,
        /// The cause.
        source: crate::hankel::separation::SeparationError,
    },
}

/// What a curve's ordinate is, which says where its separation is read (tests use it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CurveKind {
    /// Midplane σ_z (compression negative): R_o is its first upward zero beyond B.
    SigmaZ,
    /// Interface pressure or midplane compression −σ_z (compression positive): R_o is where it
    /// first stops being positive beyond B.
    Pressure,
    /// Gap between the plates: zero in contact, R_o where it first opens beyond B.
    Gap,
    /// Anything else (loads, deflections, the 1:1 line): no separation read from it.
    Other,
}

/// One computed curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FigCurve {
    /// Legend text (with units of the case).
    pub label: String,
    /// What the ordinate is.
    pub kind: CurveKind,
    /// Abscissae (increasing).
    pub x: Vec<f64>,
    /// Ordinates.
    pub y: Vec<f64>,
    /// The bearing face's outer radius B of the case (the separation is sought beyond it).
    pub b: f64,
    /// The separation radius computed with the curve (value, error estimate, converged).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub r_o: Option<Value>,
}

impl FigCurve {
    /// A curve of `kind` through `points` = (x, y) with its separation radius `r_o` = (value,
    /// error) against `tolerance`, labelled "`what`: R_o = … ± … in"; `b` the bearing radius.
    pub fn with_r_o(
        what: &str,
        kind: CurveKind,
        (x, y): (Vec<f64>, Vec<f64>),
        b: f64,
        (r_o, error): (f64, f64),
        tolerance: f64,
    ) -> Self {
        Self {
            label: format!("{what}: R_o = {r_o:.4} ± {error:.1e} in"),
            kind,
            x,
            y,
            b,
            r_o: Some(value(r_o, error, tolerance)),
        }
    }
}

/// Where a point comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Source {
    /// The report's printed value (Tables 1, 2, the text).
    Report,
    /// A measurement printed in the report (Table 2's ranges).
    Measured,
    /// Computed here.
    Computed,
}

/// One data point (a report value, a measurement or a computed point) with its error bars or range (lo ≤ value ≤ hi in each direction).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DataPoint {
    /// Abscissa.
    pub x: f64,
    /// Ordinate.
    pub y: f64,
    /// Horizontal bar (lo, hi).
    pub x_bar: (f64, f64),
    /// Vertical bar (lo, hi).
    pub y_bar: (f64, f64),
}

impl DataPoint {
    /// A point without bars.
    pub fn at(x: f64, y: f64) -> Self {
        Self {
            x,
            y,
            x_bar: (x, x),
            y_bar: (y, y),
        }
    }

    /// A point at `x` on the axis y = 0 with the horizontal range (lo, hi).
    pub fn range(x: f64, lo: f64, hi: f64) -> Self {
        Self {
            x_bar: (lo, hi),
            ..Self::at(x, 0.0)
        }
    }
}

/// Points of one kind with a legend entry.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DataSeries {
    /// Legend text.
    pub label: String,
    /// Where the values come from.
    pub source: Source,
    /// The points.
    pub points: Vec<DataPoint>,
}

/// A figure: caption, axes, computed curves and the report's values.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FigureData {
    /// File stem and `--only` key: `fig12` … `fig29`, `slab`.
    pub id: String,
    /// The report's caption (or, for the slab, what it shows).
    pub title: String,
    /// A sentence on the case and the method (the gallery's caption).
    pub note: String,
    /// x axis label with unit.
    pub x_label: String,
    /// y axis label with unit.
    pub y_label: String,
    /// The computed curves.
    pub curves: Vec<FigCurve>,
    /// The report's values and measurements (and computed points, e.g. Fig. 28).
    pub points: Vec<DataSeries>,
    /// Computed values shown as points rather than curves (Fig. 28's 2R_o), with their errors.
    pub values: Vec<Value>,
    /// What the report prints for this figure (the source of its markers), or, starting with
    /// [`NO_REPORT_VALUES`], that it prints none and why.
    pub report_values: String,
    /// Seconds spent computing.
    pub seconds: f64,
}

impl FigureData {
    /// Whether every computed R_o met its tolerance.
    pub fn converged(&self) -> bool {
        self.curves
            .iter()
            .all(|c| c.r_o.is_none_or(|v| v.converged))
            && self.values.iter().all(|v| v.converged)
    }
}

/// How [`FigureData::report_values`] starts for a figure the report prints no value for.
pub const NO_REPORT_VALUES: &str = "The report prints no value for this figure";

/// Every figure's id, in the gallery's order.
pub const IDS: [&str; 19] = [
    "fig12", "fig13", "fig14", "fig15", "fig16", "fig17", "fig18", "fig19", "fig20", "fig21",
    "fig22", "fig23", "fig24", "fig25", "fig26", "fig27", "fig28", "fig29", "slab",
];

/// The id of figure `key`: `12` or `fig12` → `fig12`, `slab` → `slab`; None if unknown.
pub fn resolve(key: &str) -> Option<&'static str> {
    let key = key.trim().to_ascii_lowercase();
    let key = if key.chars().all(|c| c.is_ascii_digit()) {
        format!("fig{key}")
    } else {
        key
    };
    IDS.iter().copied().find(|id| *id == key)
}

/// Computes figure `id` (see [`IDS`] and [`resolve`]).
pub fn compute(id: &str, params: &FiguresParams) -> Result<FigureData, FigureError> {
    let start = std::time::Instant::now();
    let id = resolve(id).ok_or_else(|| FigureError::Unknown(id.to_string()))?;
    let mut fig = match id {
        "fig12" | "fig13" | "fig14" | "fig15" | "fig16" | "fig17" => {
            single::table1_figure(id, params)
        }
        "fig28" => experiments::fig28(params),
        "fig29" => lap::fig29(params),
        "slab" => slab::slab_figure(params),
        _ => pairs::pair_figure(id, params),
    }?;
    fig.seconds = start.elapsed().as_secs_f64();
    Ok(fig)
}

/// Colours of successive curves (dark, distinguishable, print-safe).
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0, 0, 0),
    (200, 30, 30),
    (30, 90, 200),
    (20, 150, 60),
    (150, 60, 170),
    (230, 130, 0),
    (0, 150, 170),
    (120, 120, 120),
];

/// `r_o ± error` as a [`Value`] against `tolerance`.
fn value(r_o: f64, error: f64, tolerance: f64) -> Value {
    Value::with_tolerance(r_o, error, tolerance)
}

/// The points of `x` and `y` with x ≤ `x_max`.
fn clip(x: &[f64], y: &[f64], x_max: f64) -> (Vec<f64>, Vec<f64>) {
    x.iter()
        .zip(y)
        .filter(|(x, _)| **x <= x_max)
        .map(|(x, y)| (*x, *y))
        .unzip()
}

/// `x` rounded to 6 decimals for labels (0.31, not 0.31000000000000005).
fn short(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

/// Moves the series of `points` that are ranges (measured, or the report's r/A ranges) off the
/// axis, one level each below it (−6 %, −12 %, … of `scale`), so that their bars hide neither
/// each other nor the curves' zeros and the report's points.
fn stagger(points: &mut [DataSeries], scale: f64) {
    let mut level = 0.0;
    let is_range = |s: &DataSeries| s.points.iter().any(|p| p.x_bar.0 < p.x_bar.1);
    for s in points.iter_mut().filter(|s| is_range(s)) {
        level += 0.06 * scale;
        for p in &mut s.points {
            p.y -= level;
            p.y_bar = (p.y_bar.0 - level, p.y_bar.1 - level);
        }
    }
}
