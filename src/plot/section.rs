//! A drawing of a cross-section ([`SectionFigure`]): closed outlines in the (r, z) plane at equal
//! scale in r and z (one unit is the same number of pixels on both axes, so a plate looks like a
//! plate), filled or dashed, with the vertical markers of [`super::CurveFigure`]. Used for the
//! deformed joint of `two --plot` (displacements exaggerated, the undeformed outline dashed
//! beside it), in the style of the report's cross-section sketches.
//!
//! Method: the chart is laid out once to learn its plotting area in pixels; the shorter data
//! range is then widened (y about its centre, x to the right) until the pixels per unit agree.
//!
//! # Accuracy
//!
//! `tests/io/figure_joint.rs` parses the SVG of the deformed joint: the outlines' pixel extents
//! give equal scales in x and y, and the R_o marker sits at the computed R_o.
//!
//! # Cost
//!
//! One polygon per outline; negligible beside the solve.
//!
//! ```
//! use boltzone::plot::{write_figure, Outline, SectionFigure};
//! let square = vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
//! let fig = SectionFigure {
//!     title: "a unit square".into(), x_label: "r [in]".into(), y_label: "z [in]".into(),
//!     outlines: vec![Outline { label: "square".into(), points: square, color: (0, 114, 178),
//!                              filled: true, dashed: false }],
//!     markers: vec![], x_range: (0.0, 2.0), y_range: (-0.5, 1.5),
//! };
//! let path = std::env::temp_dir().join(format!("boltzone_section_{}.svg", std::process::id()));
//! write_figure(&fig, &path, (600, 500))?;
//! assert!(std::fs::read_to_string(&path)?.contains("<polygon"));
//! std::fs::remove_file(&path)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::contour::axis_label;
use super::{draw_legend, draw_markers, pe, rgb, typeset, Figure, Marker, PlotError};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// A closed outline of a [`SectionFigure`] (first point repeated last, or closed when drawn).
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// Legend text ("" for none).
    pub label: String,
    /// (r, z) points around the outline.
    pub points: Vec<(f64, f64)>,
    /// RGB colour.
    pub color: (u8, u8, u8),
    /// Filled with a light tint of the colour (else only the line).
    pub filled: bool,
    /// Dashed line (else solid).
    pub dashed: bool,
}

/// Outlines at equal scale in x and y, with vertical markers and a legend.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionFigure {
    /// Caption.
    pub title: String,
    /// x axis label.
    pub x_label: String,
    /// y axis label.
    pub y_label: String,
    /// The outlines, drawn in order.
    pub outlines: Vec<Outline>,
    /// Vertical markers.
    pub markers: Vec<Marker>,
    /// x range (widened to the right for equal scales).
    pub x_range: (f64, f64),
    /// y range (widened about its centre for equal scales).
    pub y_range: (f64, f64),
}

/// `range` widened to `len`: about its centre, or to the right when `right`.
fn widen((a, b): (f64, f64), len: f64, right: bool) -> (f64, f64) {
    if len <= b - a {
        (a, b)
    } else if right {
        (a, a + len)
    } else {
        let m = 0.5 * (a + b);
        (m - 0.5 * len, m + 0.5 * len)
    }
}

impl SectionFigure {
    fn build<'a, DB: DrawingBackend>(
        &self,
        root: &'a DrawingArea<DB, Shift>,
        (x, y): ((f64, f64), (f64, f64)),
    ) -> Result<ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>, PlotError> {
        ChartBuilder::on(root)
            .caption(typeset(&self.title), ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(pe)
    }
}

impl Figure for SectionFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        let (pw, ph) = self
            .build(root, (self.x_range, self.y_range))?
            .plotting_area()
            .dim_in_pixel();
        root.fill(&WHITE).map_err(pe)?;
        let (dx, dy) = (
            self.x_range.1 - self.x_range.0,
            self.y_range.1 - self.y_range.0,
        );
        // units per pixel equal on both axes
        let upp = (dx / f64::from(pw.max(1))).max(dy / f64::from(ph.max(1)));
        let x = widen(self.x_range, upp * f64::from(pw), true);
        let y = widen(self.y_range, upp * f64::from(ph), false);
        let mut chart = self.build(root, (x, y))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(typeset(&self.x_label))
            .y_desc(typeset(&self.y_label))
            .x_label_formatter(&|v| axis_label(*v, x.1 - x.0))
            .y_label_formatter(&|v| axis_label(*v, y.1 - y.0))
            .label_style(("sans-serif", 15))
            .draw()
            .map_err(pe)?;
        for o in &self.outlines {
            let col = rgb(o.color);
            let mut pts = o.points.clone();
            if pts.first() != pts.last() {
                pts.extend(pts.first().copied());
            }
            if o.filled {
                chart
                    .draw_series([Polygon::new(pts.clone(), col.mix(0.25).filled())])
                    .map_err(pe)?;
            }
            let anno = if o.dashed {
                chart
                    .draw_series(DashedLineSeries::new(pts, 5, 4, col.stroke_width(1)))
                    .map_err(pe)?
            } else {
                chart
                    .draw_series(LineSeries::new(pts, col.stroke_width(2)))
                    .map_err(pe)?
            };
            if !o.label.is_empty() {
                let dashed = o.dashed;
                anno.label(typeset(&o.label)).legend(move |(x, y)| {
                    let seg =
                        |a: i32, b: i32| PathElement::new([(a, 0), (b, 0)], col.stroke_width(2));
                    if dashed {
                        EmptyElement::at((x, y)) + seg(0, 4) + seg(8, 12) + seg(16, 20)
                    } else {
                        EmptyElement::at((x, y)) + seg(0, 20) + seg(20, 20) + seg(20, 20)
                    }
                });
            }
        }
        draw_markers(&mut chart, &self.markers, y)?;
        draw_legend(&mut chart)
    }
}
