//! Figures as SVG or PNG (by the file's extension) with plotters: curves against one axis with
//! marked radii ([`CurveFigure`]), and heat maps over a log–log grid with colour bars
//! ([`HeatMapFigure`]). Files are written whole or not at all ([`crate::fsutil`]: a temporary
//! name beside the target, renamed into place; [`write_atomic`]), so a reader never sees half a
//! figure.
//!
//! PNG text is drawn with the DejaVu Sans font shipped in `assets/` (licence beside it), compiled
//! in and registered on first use: plotters' `ab_glyph` backend has no system fonts.
//!
//! # Accuracy
//!
//! Not numerical: the figures are checked by `tests/io/plot_out.rs`
//! (`plots_mark_r_o_and_the_rules`) and looked at by example 07.
//!
//! # Cost
//!
//! Milliseconds per figure (plotters' SVG and bitmap backends).
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

use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

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

fn pe<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// Writes `bytes` to `path` atomically ([`crate::fsutil::write_atomic`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), PlotError> {
    crate::fsutil::write_atomic(path, bytes).map_err(|source| PlotError::Io {
        path: path.to_path_buf(),
        source,
    })
}

fn register_font() {
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

/// Writes `fig` as SVG or PNG (by `path`'s extension) of `size` pixels, atomically.
pub fn write_figure<F: Figure>(fig: &F, path: &Path, size: (u32, u32)) -> Result<(), PlotError> {
    // Both backends measure text with the registered font (SVG for layout, PNG to draw).
    register_font();
    match path.extension().and_then(|e| e.to_str()) {
        Some("svg") => {
            let mut s = String::new();
            {
                let root = SVGBackend::with_string(&mut s, size).into_drawing_area();
                fig.draw(&root)?;
                root.present().map_err(pe)?;
            }
            write_atomic(path, s.as_bytes())
        }
        Some("png") => {
            let io = |source| PlotError::Io {
                path: path.to_path_buf(),
                source,
            };
            let draw = |tmp: &Path| {
                let root = BitMapBackend::new(tmp, size).into_drawing_area();
                fig.draw(&root)?;
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

fn rgb(c: (u8, u8, u8)) -> RGBColor {
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
        for m in &self.markers {
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
        chart
            .configure_series_labels()
            .label_font(("sans-serif", 15))
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(pe)
    }
}

/// One panel of a [`HeatMapFigure`]: z over the grid, row-major (x index outer).
#[derive(Debug, Clone, PartialEq)]
pub struct HeatPanel {
    /// Caption.
    pub title: String,
    /// Values, z\[i·len(y) + j\] at (x\[i\], y\[j\]).
    pub z: Vec<f64>,
}

/// Heat maps over a grid that is logarithmic in both x and y, one panel each, 2 per row.
#[derive(Debug, Clone, PartialEq)]
pub struct HeatMapFigure {
    /// x values (positive, increasing).
    pub x: Vec<f64>,
    /// y values (positive, increasing).
    pub y: Vec<f64>,
    /// x axis label.
    pub x_label: String,
    /// y axis label.
    pub y_label: String,
    /// The panels.
    pub panels: Vec<HeatPanel>,
}

/// The viridis colour map (five anchors, linear between them) at t ∈ [0, 1].
pub fn viridis(t: f64) -> RGBColor {
    const C: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let s = t.clamp(0.0, 1.0) * 4.0;
    let k = (s.floor() as usize).min(3);
    let f = s - k as f64;
    let mix = |a: f64, b: f64| (a + f * (b - a)).round() as u8;
    let (a, b) = (C[k], C[k + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Cell edges in log10 around log-spaced centres (geometric midpoints; half a step beyond ends).
fn edges(v: &[f64]) -> Vec<f64> {
    let l: Vec<f64> = v.iter().map(|x| x.log10()).collect();
    let n = l.len();
    if n == 1 {
        return vec![l[0] - 0.05, l[0] + 0.05];
    }
    let mut e = vec![l[0] - 0.5 * (l[1] - l[0])];
    e.extend(l.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    e.push(l[n - 1] + 0.5 * (l[n - 1] - l[n - 2]));
    e
}

impl Figure for HeatMapFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        root.fill(&WHITE).map_err(pe)?;
        let rows = self.panels.len().div_ceil(2);
        let areas = root.split_evenly((rows, 2));
        let (ex, ey) = (edges(&self.x), edges(&self.y));
        let ny = self.y.len();
        let fmt = |v: &f64| format!("{:.2}", 10f64.powf(*v));
        for (panel, area) in self.panels.iter().zip(&areas) {
            let (lo, hi) = panel
                .z
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &z| {
                    (a.min(z), b.max(z))
                });
            let span = if hi > lo { hi - lo } else { 1.0 };
            let w = area.dim_in_pixel().0;
            let (main, bar) = area.split_horizontally(w.saturating_sub(90));
            let mut chart = ChartBuilder::on(&main)
                .caption(typeset(&panel.title), ("sans-serif", 16))
                .margin(8)
                .x_label_area_size(40)
                .y_label_area_size(50)
                .build_cartesian_2d(ex[0]..ex[ex.len() - 1], ey[0]..ey[ey.len() - 1])
                .map_err(pe)?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(typeset(&self.x_label))
                .y_desc(typeset(&self.y_label))
                .x_label_formatter(&fmt)
                .y_label_formatter(&fmt)
                .label_style(("sans-serif", 13))
                .draw()
                .map_err(pe)?;
            chart
                .draw_series(panel.z.iter().enumerate().map(|(k, &z)| {
                    let (i, j) = (k / ny, k % ny);
                    Rectangle::new(
                        [(ex[i], ey[j]), (ex[i + 1], ey[j + 1])],
                        viridis((z - lo) / span).filled(),
                    )
                }))
                .map_err(pe)?;
            // Colour bar with its scale on the right.
            let mut cb = ChartBuilder::on(&bar)
                .margin_top(32)
                .margin_bottom(48)
                .margin_left(4)
                .right_y_label_area_size(55)
                .build_cartesian_2d(0.0..1.0, lo..lo + span)
                .map_err(pe)?;
            cb.configure_mesh()
                .disable_mesh()
                .disable_x_axis()
                .label_style(("sans-serif", 12))
                .y_label_formatter(&|v: &f64| format!("{v:.1}"))
                .draw()
                .map_err(pe)?;
            let steps = 64;
            cb.draw_series((0..steps).map(|s| {
                let (a, b) = (s as f64 / steps as f64, (s + 1) as f64 / steps as f64);
                Rectangle::new(
                    [(0.0, lo + a * span), (1.0, lo + b * span)],
                    viridis(0.5 * (a + b)).filled(),
                )
            }))
            .map_err(pe)?;
        }
        Ok(())
    }
}
