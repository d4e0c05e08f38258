//! Fig. 29: the aluminium lap joint of Chapter V as [`crate::heat::lap::LapJoint::chapter5`]
//! assumes it (the report's node layout is lost with its figures), in plan view (and a side view
//! below it, thickness exaggerated): the two strips
//! W wide, hot edge at x = −L/2 and cold edge at x = +L/2, overlapping over l_o around the bolt;
//! the two-dimensional cell grids (overlap and a margin on each side), the hole A, the bearing
//! face B (2B = 0.26 in) and the contact zone A ≤ r ≤ R_o through which the heat crosses, R_o
//! from the two-plate model (D = 0.1 in, ν = 0.33, C = 1.54 in, as example 15).
//!
//! Drawn as outlines (curves of kind [`CurveKind::Other`]) in inches; the contact zone's
//! radius is the figure's one computed value, with its error bar.
//!
//! # Accuracy
//!
//! The one computed value, R_o, is the two-plate model's (`tests/contact/two_plate.rs`); the lap
//! joint's geometry is `tests/heat/lap.rs` (`chapter5_lap_and_bad_geometry`); the figure is written
//! by `tests/figures/gallery.rs` (`files_and_gallery_are_complete`).
//!
//! # Cost
//!
//! One two-plate solve (`cargo bench --bench contact`; example 15 builds on the same joint);
//! `boltzone figures` prints each figure's time; the whole set is timed by the ignored test
//! `every_curve_separates_at_its_r_o` (tests/figures/gallery.rs, which runs the whole set once,
//! about 6 s).
//!
//! ```no_run
//! use boltzone::figures::{lap::fig29, FiguresParams};
//! let fig = fig29(&FiguresParams::default())?; // one two-plate solve (about a second)
//! assert!(fig.curves.iter().any(|c| c.r_o.is_some()));
//! # Ok::<(), boltzone::figures::FigureError>(())
//! ```

use super::{
    value, CurveKind, DataPoint, DataSeries, FigCurve, FigureData, FigureError, FiguresParams,
    Source,
};
use crate::contact::two_plate::{solve, TwoPlateParams};
use crate::heat::lap::LapJoint;
use crate::joint::{Joint, OuterRadius};
use crate::material::Material;
use crate::reference;
use std::f64::consts::PI;

/// How much the side view exaggerates the thickness.
const EXAGGERATION: f64 = 3.0;

/// 2B of Chapter V's joint (in).
const TWO_B: f64 = 0.26;

fn rectangle(label: String, (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> FigCurve {
    FigCurve {
        label,
        kind: CurveKind::Other,
        x: vec![x0, x1, x1, x0, x0],
        y: vec![y0, y0, y1, y1, y0],
        b: 0.0,
        r_o: None,
    }
}

fn circle(label: String, radius: f64) -> FigCurve {
    let n = 96;
    let t = |i: usize| 2.0 * PI * i as f64 / n as f64;
    FigCurve {
        label,
        kind: CurveKind::Other,
        x: (0..=n).map(|i| radius * t(i).cos()).collect(),
        y: (0..=n).map(|i| radius * t(i).sin()).collect(),
        b: 0.0,
        r_o: None,
    }
}

/// Fig. 29 (`id` = `fig29`).
pub fn fig29(params: &FiguresParams) -> Result<FigureData, FigureError> {
    let lap = LapJoint::chapter5();
    let inch = |l: crate::heat::units::Length| l.to_inches();
    let (w, l, lo, margin) = (
        inch(lap.width),
        inch(lap.length),
        inch(lap.overlap),
        inch(lap.margin),
    );
    let (a, d, b) = (inch(lap.hole_radius), inch(lap.thickness), TWO_B / 2.0);
    let joint = Joint::symmetric(a, b, d, Material::new(1.0e7, 0.33)?)?
        .with_outer_radius(OuterRadius::Finite(1.54))?;
    let tp = TwoPlateParams {
        tolerance: params.tolerance,
        ..Default::default()
    };
    let s = solve(&joint, &tp).map_err(|source| FigureError::Contact {
        figure: "fig29".into(),
        source,
    })?;
    let half = w / 2.0;
    // the side view's interface, below the plan view
    let side = -half - 2.5 * EXAGGERATION * d;
    let grid = lo / 2.0 + margin;
    let mut zone = circle(
        format!("contact zone R_o = {:.4} ± {:.1e} in", s.r_o, s.r_o_error),
        s.r_o,
    );
    zone.r_o = Some(value(s.r_o, s.r_o_error, params.tolerance));
    zone.b = b;
    Ok(FigureData {
        id: "fig29".into(),
        title:
            "Fig. 29: location of nodes, steady state heat transfer analysis (lap joint as assumed)"
                .into(),
        note: format!(
            "Plan view of Chapter V's aluminium lap joint as boltzone::heat::lap assumes it: \
             strips W = {w:.4} in wide and t = {d} in thick, L = {l} in edge to edge (hot edge \
             left), overlap l_o = {lo:.4} in, a two-dimensional grid of {n} × {n} square cells \
             across W over the overlap and a margin of {margin:.4} in each side (one-dimensional \
             strips beyond), hole A = {a} in, bearing face 2B = {TWO_B} in, and the contact zone \
             A ≤ r ≤ R_o (two-plate model, ν = 0.33, C = 1.54 in) that joins facing cells.",
            n = lap.cells
        ),
        x_label: "x [in] (along the strips)".into(),
        y_label: "y [in]".into(),
        curves: vec![
            circle(format!("hole A = {a} in"), a),
            zone,
            circle(format!("bearing face B = {b} in"), b),
            rectangle(
                "upper strip (hot edge at left)".into(),
                (-l / 2.0, lo / 2.0),
                (-half, half),
            ),
            rectangle(
                "lower strip (cold edge at right)".into(),
                (-lo / 2.0, l / 2.0),
                (-half, half),
            ),
            rectangle(
                "2-D cell grid, upper strip".into(),
                (-grid, lo / 2.0),
                (-half, half),
            ),
            rectangle(
                "2-D cell grid, lower strip".into(),
                (-lo / 2.0, grid),
                (-half, half),
            ),
            rectangle(
                format!("side view below (thickness × {EXAGGERATION}): upper strip"),
                (-l / 2.0, lo / 2.0),
                (side, side + EXAGGERATION * d),
            ),
            rectangle(
                "side view: lower strip".into(),
                (-lo / 2.0, l / 2.0),
                (side - EXAGGERATION * d, side),
            ),
            rectangle(
                "side view: bolt and hole".into(),
                (-a, a),
                (side - 1.5 * EXAGGERATION * d, side + 1.5 * EXAGGERATION * d),
            ),
        ],
        points: vec![DataSeries {
            label: "report (Ch. V): outer radii of the contact rings".into(),
            source: Source::Report,
            points: reference::chapter5_interface()
                .iter()
                .map(|r| DataPoint::at(r.r_outer, 0.0))
                .collect(),
        }],
        values: vec![],
        report_values: "Chapter V's table of the contact zone's annular increments (reference/\
                        chapter5_interface.csv): their outer radii on the x axis; the last, \
                        0.175 in, is the report's edge of the contact zone."
            .into(),
        seconds: 0.0,
    })
}
