//! Drawing a [`FigureData`] with plotters (SVG or PNG through [`crate::plot::write_figure`]):
//! the curves in [`super::PALETTE`]'s colours, a short dashed tick at each curve's R_o in its
//! colour with its error bar, and the point series (the report's values as triangles,
//! measurements as open circles, computed points as dots) with their bars, all in one legend.
//! Axes are padded around the data, with room above for the legend; [`FigureData`]s whose
//! curves are outlines in inches (Fig. 29) are drawn with equal scales on both axes.
//!
//! # Accuracy
//!
//! No numerics: the R_o ticks and bars are the [`FigureData`]'s own values.
//! `tests/figures/gallery.rs` (`files_and_gallery_are_complete`) checks that every figure is
//! written as SVG and PNG; the doc example below draws one.
//!
//! # Cost
//!
//! Drawing only, timed with the figures: `boltzone figures` prints each figure's time; the whole
//! set is timed by `every_curve_separates_at_its_r_o` (tests/figures/gallery.rs, which runs the
//! whole set once, about 6 s).
//!
//! ```
//! use boltzone::figures::{compute, draw::SIZE, FiguresParams};
//! use boltzone::plot::write_figure;
//! let fig = compute("20", &FiguresParams::default())?; // the load profiles: no solve
//! let path = std::env::temp_dir().join(format!("boltzone_fig20_{}.svg", std::process::id()));
//! write_figure(&fig, &path, SIZE)?;
//! assert!(std::fs::read_to_string(&path)?.contains("Fig. 20"));
//! std::fs::remove_file(&path)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{FigureData, Source, PALETTE};
use crate::plot::{draw_legend, pe, rgb, typeset, Figure, PlotError};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Pixel size of every figure.
pub const SIZE: (u32, u32) = (1000, 660);

/// Colours of successive point series.
const POINT_COLOURS: [(u8, u8, u8); 6] = [
    (150, 0, 0),
    (0, 120, 120),
    (120, 80, 0),
    (90, 0, 150),
    (200, 0, 130),
    (60, 110, 0),
];

/// The data's extent: (x_min, x_max, y_min, y_max) over curves and points (bars included).
fn extent(fig: &FigureData) -> (f64, f64, f64, f64) {
    let mut e = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    let mut add = |x: f64, y: f64| {
        if x.is_finite() && y.is_finite() {
            e = (e.0.min(x), e.1.max(x), e.2.min(y), e.3.max(y));
        }
    };
    for c in &fig.curves {
        c.x.iter().zip(&c.y).for_each(|(x, y)| add(*x, *y));
    }
    for p in fig.points.iter().flat_map(|s| &s.points) {
        add(p.x_bar.0, p.y_bar.0);
        add(p.x_bar.1, p.y_bar.1);
    }
    if !e.0.is_finite() {
        return (0.0, 1.0, 0.0, 1.0);
    }
    e
}

/// Whether the figure is a drawing in inches on both axes (equal scales).
fn is_drawing(fig: &FigureData) -> bool {
    fig.x_label.starts_with("x [") && fig.y_label.starts_with("y [")
}

impl Figure for FigureData {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        root.fill(&WHITE).map_err(pe)?;
        let (x0, x1, y0, y1) = extent(self);
        let (w, h) = root.dim_in_pixel();
        let entries = self.curves.len() + self.points.len();
        let (xr, yr) = if is_drawing(self) {
            // equal scales: the plotting area is about (w − 110) × (h − 120) pixels, the legend
            // (24 px per entry) above the drawing, never over it
            let legend_px = 24.0 * entries as f64 + 30.0;
            let per_px = f64::max(
                (x1 - x0) * 1.04 / (w as f64 - 110.0),
                (y1 - y0) * 1.04 / (h as f64 - 120.0 - legend_px).max(50.0),
            );
            let span = per_px * (w as f64 - 110.0);
            let tall = (h as f64 - 120.0) * per_px;
            let cx = 0.5 * (x0 + x1);
            let spare = tall - (y1 - y0) - legend_px * per_px;
            let bottom = y0 - 0.5 * spare.max(0.04 * tall);
            ((cx - span / 2.0, cx + span / 2.0), (bottom, bottom + tall))
        } else {
            let dy = (y1 - y0).max(f64::MIN_POSITIVE);
            let pad = 0.05 * dy;
            // the legend takes about 24 px per entry in the upper right
            let room = (24.0 * entries as f64 + 30.0) / (h as f64 - 120.0);
            let top = y1 + pad + dy * room / (1.0 - room).max(0.2);
            let dx = (x1 - x0).max(f64::MIN_POSITIVE);
            ((x0 - 0.02 * dx, x1 + 0.02 * dx), (y0 - pad, top))
        };
        let mut chart = ChartBuilder::on(root)
            .caption(typeset(&self.title), ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
            .map_err(pe)?;
        chart
            .configure_mesh()
            .x_desc(typeset(&self.x_label))
            .y_desc(typeset(&self.y_label))
            .label_style(("sans-serif", 14))
            .x_label_formatter(&|x| super::units::number(*x))
            .y_label_formatter(&|y| super::units::number(*y))
            .draw()
            .map_err(pe)?;
        if yr.0 < 0.0 && yr.1 > 0.0 {
            chart
                .draw_series(LineSeries::new([(xr.0, 0.0), (xr.1, 0.0)], BLACK.mix(0.6)))
                .map_err(pe)?;
        }
        let tick = 0.04 * (yr.1 - yr.0);
        for (i, c) in self.curves.iter().enumerate() {
            let col = rgb(PALETTE[i % PALETTE.len()]);
            chart
                .draw_series(LineSeries::new(
                    c.x.iter().copied().zip(c.y.iter().copied()),
                    col.stroke_width(2),
                ))
                .map_err(pe)?
                .label(typeset(&c.label))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], col.stroke_width(2)));
            if let (Some(v), false) = (c.r_o, is_drawing(self)) {
                // R_o: a dashed tick across the axis and its error bar, in the curve's colour
                chart
                    .draw_series(DashedLineSeries::new(
                        [(v.value, -tick), (v.value, tick)],
                        4,
                        3,
                        col.stroke_width(2),
                    ))
                    .map_err(pe)?;
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        [(v.value - v.error, 0.0), (v.value + v.error, 0.0)],
                        col.stroke_width(3),
                    )))
                    .map_err(pe)?;
            }
        }
        for (k, s) in self.points.iter().enumerate() {
            let col = rgb(POINT_COLOURS[k % POINT_COLOURS.len()]);
            let style = col.stroke_width(2);
            let bars = s.points.iter().flat_map(|p| {
                [
                    PathElement::new([(p.x_bar.0, p.y), (p.x_bar.1, p.y)], style),
                    PathElement::new([(p.x, p.y_bar.0), (p.x, p.y_bar.1)], style),
                ]
            });
            chart.draw_series(bars).map_err(pe)?;
            macro_rules! series {
                ($make:expr) => {{
                    let make = $make;
                    chart
                        .draw_series(
                            s.points
                                .iter()
                                .map(|p| EmptyElement::at((p.x, p.y)) + make()),
                        )
                        .map_err(pe)?
                        .label(typeset(&s.label))
                        .legend(move |(x, y)| EmptyElement::at((x + 10, y)) + make());
                }};
            }
            match s.source {
                Source::Report => series!(move || TriangleMarker::new((0, 0), 7, col.filled())),
                Source::Measured => series!(move || Circle::new((0, 0), 6, col.stroke_width(2))),
                Source::Computed => series!(move || Circle::new((0, 0), 4, col.filled())),
            }
        }
        draw_legend(&mut chart)
    }
}
