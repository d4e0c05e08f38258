//! Figures as SVG or PNG (by the file's extension) with plotters: curves against one axis with
//! marked radii ([`CurveFigure`]), heat maps over a log–log grid with colour bars and contour
//! lines ([`HeatMapFigure`], [`contour`]), and cross-section drawings at equal scales
//! ([`SectionFigure`]). Files are written whole or not at all ([`crate::fsutil`]: a temporary
//! name beside the target, renamed into place; [`write_atomic`]), so a reader never sees half a
//! figure; [`svg_string`] gives the SVG text for inlining (the HTML report).
//!
//! Colours: give each series of a figure its own entry of [`PALETTE`] (Okabe & Ito's,
//! distinguishable with the common colour-vision deficiencies). PNG is anti-aliased by drawing
//! three times larger and averaging ([`raster`]).
//!
//! PNG text is drawn with the DejaVu Sans font shipped in `assets/` (licence beside it), compiled
//! in and registered on first use: plotters' `ab_glyph` backend has no system fonts.
//!
//! # Accuracy
//!
//! Not numerical: what each figure shows is read back from its SVG by `tests/io/plot_out.rs`,
//! `tests/io/figure_joint.rs` and `tests/io/figure_map.rs` (markers at the computed radii, equal
//! scales, round ticks); the PNG rasterisation by `tests/io/figure_png.rs`.
//!
//! # Cost
//!
//! A figure draws in milliseconds (SVG) to tens of milliseconds (PNG, 9× the pixels); measured
//! in `tests/io/figure_joint.rs`'s `two --plot` run.
//!
//! ```
//! use boltzone::plot::{write_figure, Curve, CurveFigure};
//! let fig = CurveFigure {
//!     title: "y = x²".into(), x_label: "x".into(), y_label: "y".into(),
//!     curves: vec![Curve { label: "x²".into(), points: (0..11).map(|i| (i as f64, (i * i) as f64)).collect(), color: (0, 0, 200) }],
//!     markers: vec![], x_range: (0.0, 10.0), y_range: (0.0, 100.0),
//! };
//! let path = std::env::temp_dir().join(format!("boltzone_doc_{}.svg", std::process::id()));
//! write_figure(&fig, &path, (640, 480))?;
//! assert!(std::fs::read_to_string(&path)?.contains("<svg"));
//! std::fs::remove_file(&path)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod contour;
mod heat;
pub mod joint_diagram;
pub mod raster;
pub mod section;

pub use heat::{diverging, viridis, HeatMapFigure, HeatPanel};
pub use section::{Outline, SectionFigure};

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// Okabe & Ito's eight colours (2008), distinguishable with the common colour-vision
/// deficiencies: black, orange, sky blue, bluish green, yellow, blue, vermilion, reddish purple.
/// Give each series of a figure its own entry (yellow is pale on white: last resort).
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0, 0, 0),
    (230, 159, 0),
    (86, 180, 233),
    (0, 158, 115),
    (240, 228, 66),
    (0, 114, 178),
    (213, 94, 0),
    (204, 121, 167),
];

/// Failures of figure output.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The file name's extension is neither .svg nor .png.
    #[error("figure file '{0}': the extension must be .svg or .png")]
    Format(PathBuf),
    /// Drawing failed.
    #[error("drawing the figure: {0}")]
    Draw(String),
    /// Writing the file failed.
    #[error("writing '{path}': {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

pub(crate) fn pe<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// Writes `bytes` to `path` atomically ([`crate::fsutil::write_atomic`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    crate::fsutil::write_atomic(path, bytes).map_err(|source| PlotError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Registers the shipped DejaVu Sans as "sans-serif" for plotters' text (once per process;
/// [`write_figure`] and [`svg_string`] call it): needed before drawing on a backend directly.
pub fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let font: &'static [u8] = include_bytes!("../assets/DejaVuSans.ttf");
        plotters::style::register_font("sans-serif", FontStyle::Normal, font)
            .unwrap_or_else(|_| panic!("the shipped DejaVu Sans font is a valid TTF"));
    });
}

/// A figure that can draw itself on any plotters backend.
pub trait Figure {
    /// Draws on `root`.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError>;
}

/// `fig` as SVG text of `size` pixels (for inlining in HTML).
pub fn svg_string<F: Figure>(fig: &F, size: (u32, u32)) -> Result<String, PlotError> {
    register_font();
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, size).into_drawing_area();
        fig.draw(&root)?;
        root.present().map_err(pe)?;
    }
    Ok(s)
}

/// Writes `fig` as SVG or PNG (by `path`'s extension) of `size` pixels, atomically.
pub fn write_figure<F: Figure>(fig: &F, path: &Path, size: (u32, u32)) -> Result<(), PlotError> {
    // Both backends measure text with the registered font (SVG for layout, PNG to draw).
    register_font();
    match path.extension().and_then(|e| e.to_str()) {
        Some("svg") => write_atomic(path, svg_string(fig, size)?.as_bytes()),
        Some("png") => {
            // drawn FACTOR times larger and averaged down: anti-aliased ([`raster`])
            let k = raster::FACTOR as usize;
            let mut big = vec![255u8; size.0 as usize * size.1 as usize * 3 * k * k];
            {
                let root = raster::Supersampled::new(&mut big, size).into_drawing_area();
                fig.draw(&root)?;
                root.present().map_err(pe)?;
            }
            let small = raster::downsample(&big, size);
            let io = |source| PlotError::Io {
                path: path.to_path_buf(),
                source,
            };
            let draw = |tmp: &Path| {
                let root = BitMapBackend::new(tmp, size).into_drawing_area();
                root.draw(
                    &plotters::element::BitMapElement::with_owned_buffer(
                        (0, 0),
                        size,
                        small.clone(),
                    )
                    .ok_or_else(|| PlotError::Draw("internal: bitmap size".into()))?,
                )
                .map_err(pe)?;
                root.present().map_err(pe)
            };
            crate::fsutil::replace_with(path, draw, io)
        }
        _ => Err(PlotError::Format(path.to_path_buf())),
    }
}

/// One curve of a [`CurveFigure`].
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Legend text.
    pub label: String,
    /// (x, y) points.
    pub points: Vec<(f64, f64)>,
    /// RGB colour.
    pub color: (u8, u8, u8),
}

/// A vertical dashed line at `x` with a legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// Legend text.
    pub label: String,
    /// Abscissa.
    pub x: f64,
    /// RGB colour.
    pub color: (u8, u8, u8),
}

/// Curves y(x) with vertical markers and a legend.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveFigure {
    /// Caption.
    pub title: String,
    /// x axis label.
    pub x_label: String,
    /// y axis label.
    pub y_label: String,
    /// The curves.
    pub curves: Vec<Curve>,
    /// Vertical markers.
    pub markers: Vec<Marker>,
    /// x range.
    pub x_range: (f64, f64),
    /// y range.
    pub y_range: (f64, f64),
}

/// Text as a figure shows it: the report's R_o with a subscript o (Rₒ), not an underscore.
pub fn typeset(text: &str) -> String {
    text.replace("R_o", "R\u{2092}")
}

pub(crate) fn rgb(c: (u8, u8, u8)) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

impl Figure for CurveFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        root.fill(&WHITE).map_err(pe)?;
        let (x0, x1) = self.x_range;
        let (y0, y1) = self.y_range;
        let mut chart = ChartBuilder::on(root)
            .caption(typeset(&self.title), ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(pe)?;
        chart
            .configure_mesh()
            .x_desc(typeset(&self.x_label))
            .y_desc(typeset(&self.y_label))
            .x_label_formatter(&|v| contour::axis_label(*v, x1 - x0))
            .y_label_formatter(&|v| contour::axis_label(*v, y1 - y0))
            .label_style(("sans-serif", 15))
            .draw()
            .map_err(pe)?;
        chart
            .draw_series(LineSeries::new(
                [(x0, 0.0), (x1, 0.0)],
                BLACK.stroke_width(1),
            ))
            .map_err(pe)?;
        for c in &self.curves {
            let col = rgb(c.color);
            chart
                .draw_series(LineSeries::new(
                    c.points.iter().copied(),
                    col.stroke_width(2),
                ))
                .map_err(pe)?
                .label(typeset(&c.label))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], col.stroke_width(2)));
        }
        draw_markers(&mut chart, &self.markers, (y0, y1))?;
        draw_legend(&mut chart)
    }
}

/// Draws the legend of `chart`'s labelled series in its upper right corner.
pub(crate) fn draw_legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
) -> Result<(), PlotError> {
    chart
        .configure_series_labels()
        .label_font(("sans-serif", 15))
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(pe)
}

/// Draws `markers` as dashed vertical lines from y0 to y1 with dashed legend entries.
pub(crate) fn draw_markers<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    markers: &[Marker],
    (y0, y1): (f64, f64),
) -> Result<(), PlotError> {
    for m in markers {
        let col = rgb(m.color);
        chart
            .draw_series(DashedLineSeries::new(
                [(m.x, y0), (m.x, y1)],
                6,
                4,
                col.stroke_width(2),
            ))
            .map_err(pe)?
            .label(typeset(&m.label))
            .legend(move |(x, y)| {
                // dashed in the legend as on the plot: three dashes of 4 px
                let dash = |a: i32| PathElement::new([(a, 0), (a + 4, 0)], col.stroke_width(2));
                EmptyElement::at((x, y)) + dash(0) + dash(8) + dash(16)
            });
    }
    Ok(())
}
