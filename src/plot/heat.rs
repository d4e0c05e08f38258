//! Heat maps over a log–log grid ([`HeatMapFigure`]): each panel's values as coloured cells, its
//! contour lines at the colour bar's round values ([`super::contour`]), axes ticked at round
//! numbers (0.2, 0.5, 1, 2, 5 rather than 10^(log-spaced) values like 5.01). A panel whose values
//! take both signs (a signed error) is drawn on a diverging scale centred on 0 ([`diverging`]:
//! blue below, white at 0, red above, symmetric ±max|z|); others on viridis ([`viridis`]). Both
//! colour maps are readable with the common colour-vision deficiencies.
//!
//! # Accuracy
//!
//! `tests/io/figure_map.rs` parses the SVG of `boltzone map` for the tick labels, the contour lines
//! and the colour bar's symmetric range.
//!
//! # Cost
//!
//! A 40 × 40 map draws in well under a second (one rectangle per cell and one pass per contour
//! level; `boltzone map`).
//!
//! ```
//! use boltzone::plot::{svg_string, HeatMapFigure, HeatPanel};
//! let fig = HeatMapFigure {
//!     x: vec![1.0, 2.0, 4.0], y: vec![1.0, 3.0], x_label: "x".into(), y_label: "y".into(),
//!     panels: vec![HeatPanel { title: "signed".into(), z: vec![-3.0, -1.0, 0.5, 1.0, 2.0, 4.0] }],
//! };
//! let svg = svg_string(&fig, (600, 400))?;
//! assert!(svg.contains("signed")); // its caption (the bar spans ±4: tests/io/figure_map.rs)
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::contour::{contour_segments, log_ticks, nice_ticks, tick_label};
use super::{pe, typeset, Figure, PlotError};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

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

fn lerp_map(anchors: &[(f64, f64, f64)], t: f64) -> RGBColor {
    let n = anchors.len() - 1;
    let s = t.clamp(0.0, 1.0) * n as f64;
    let k = (s.floor() as usize).min(n - 1);
    let f = s - k as f64;
    let mix = |a: f64, b: f64| (a + f * (b - a)).round() as u8;
    let (a, b) = (anchors[k], anchors[k + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
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
    lerp_map(&C, t)
}

/// A diverging colour map at t ∈ [0, 1] (ColorBrewer's RdBu, 7 anchors, reversed): blue at 0,
/// white at ½, red at 1.
pub fn diverging(t: f64) -> RGBColor {
    const C: [(f64, f64, f64); 7] = [
        (33.0, 102.0, 172.0),
        (103.0, 169.0, 207.0),
        (209.0, 229.0, 240.0),
        (247.0, 247.0, 247.0),
        (253.0, 219.0, 199.0),
        (239.0, 138.0, 98.0),
        (178.0, 24.0, 43.0),
    ];
    lerp_map(&C, t)
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

/// The colour scale of a panel: its range and map (diverging and symmetric about 0 when the
/// values take both signs).
fn scale(z: &[f64]) -> (f64, f64, fn(f64) -> RGBColor) {
    let (lo, hi) = z
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if lo > hi {
        return (0.0, 1.0, viridis);
    }
    if lo < 0.0 && hi > 0.0 {
        let m = lo.abs().max(hi);
        return (-m, m, diverging);
    }
    if hi > lo {
        (lo, hi, viridis)
    } else {
        (lo - 0.5, hi + 0.5, viridis)
    }
}

impl Figure for HeatMapFigure {
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError> {
        root.fill(&WHITE).map_err(pe)?;
        let rows = self.panels.len().div_ceil(2);
        let areas = root.split_evenly((rows, 2));
        let (ex, ey) = (edges(&self.x), edges(&self.y));
        let (lx, ly): (Vec<f64>, Vec<f64>) = (
            self.x.iter().map(|v| v.log10()).collect(),
            self.y.iter().map(|v| v.log10()).collect(),
        );
        let ny = self.y.len();
        let (x_range, y_range) = (ex[0]..ex[ex.len() - 1], ey[0]..ey[ey.len() - 1]);
        let x_ticks = log_ticks(10f64.powf(x_range.start), 10f64.powf(x_range.end));
        let y_ticks = log_ticks(10f64.powf(y_range.start), 10f64.powf(y_range.end));
        let base = root.get_base_pixel();
        let label = ("sans-serif", 13).into_font();
        for (panel, area) in self.panels.iter().zip(&areas) {
            let (lo, hi, cmap) = scale(&panel.z);
            let span = hi - lo;
            let w = area.dim_in_pixel().0;
            let (main, bar) = area.split_horizontally(w.saturating_sub(90));
            let mut chart = ChartBuilder::on(&main)
                .caption(typeset(&panel.title), ("sans-serif", 16))
                .margin(8)
                .x_label_area_size(40)
                .y_label_area_size(50)
                .build_cartesian_2d(x_range.clone(), y_range.clone())
                .map_err(pe)?;
            // axis lines and titles from plotters; ticks at round numbers drawn below
            chart
                .configure_mesh()
                .disable_mesh()
                .x_labels(0)
                .y_labels(0)
                .x_desc(typeset(&self.x_label))
                .y_desc(typeset(&self.y_label))
                .label_style(("sans-serif", 13))
                .draw()
                .map_err(pe)?;
            chart
                .draw_series(panel.z.iter().enumerate().map(|(k, &z)| {
                    let (i, j) = (k / ny, k % ny);
                    Rectangle::new(
                        [(ex[i], ey[j]), (ex[i + 1], ey[j + 1])],
                        cmap((z - lo) / span).filled(),
                    )
                }))
                .map_err(pe)?;
            let levels = nice_ticks(lo, hi, 7);
            let step = levels
                .windows(2)
                .map(|w| w[1] - w[0])
                .next()
                .unwrap_or(span);
            for &c in &levels {
                let segs = contour_segments(&lx, &ly, &panel.z, c);
                chart
                    .draw_series(
                        segs.into_iter().map(|(a, b)| {
                            PathElement::new([a, b], BLACK.mix(0.75).stroke_width(1))
                        }),
                    )
                    .map_err(pe)?;
            }
            let abs = |x: f64, y: f64| {
                let p = chart.backend_coord(&(x, y));
                (p.0 - base.0, p.1 - base.1)
            };
            for &t in &x_ticks {
                let (px, py) = abs(t.log10(), y_range.start);
                let s = tick_label(t, t);
                root.draw(&PathElement::new([(px, py), (px, py + 5)], BLACK))
                    .map_err(pe)?;
                let style = label.color(&BLACK).pos(Pos::new(HPos::Center, VPos::Top));
                root.draw(&Text::new(s, (px, py + 7), style)).map_err(pe)?;
            }
            for &t in &y_ticks {
                let (px, py) = abs(x_range.start, t.log10());
                let s = tick_label(t, t);
                root.draw(&PathElement::new([(px - 5, py), (px, py)], BLACK))
                    .map_err(pe)?;
                let style = label.color(&BLACK).pos(Pos::new(HPos::Right, VPos::Center));
                root.draw(&Text::new(s, (px - 7, py), style)).map_err(pe)?;
            }
            // Colour bar with the contour levels as its ticks on the right.
            let mut cb = ChartBuilder::on(&bar)
                .margin_top(32)
                .margin_bottom(48)
                .margin_left(4)
                .right_y_label_area_size(55)
                .build_cartesian_2d(0.0..1.0, lo..hi)
                .map_err(pe)?;
            cb.configure_mesh()
                .disable_mesh()
                .disable_x_axis()
                .y_labels(0)
                .draw()
                .map_err(pe)?;
            let steps = 64;
            cb.draw_series((0..steps).map(|s| {
                let (a, b) = (s as f64 / steps as f64, (s + 1) as f64 / steps as f64);
                Rectangle::new(
                    [(0.0, lo + a * span), (1.0, lo + b * span)],
                    cmap(0.5 * (a + b)).filled(),
                )
            }))
            .map_err(pe)?;
            for &c in &levels {
                cb.draw_series([PathElement::new(
                    [(0.0, c), (1.0, c)],
                    BLACK.stroke_width(1),
                )])
                .map_err(pe)?;
                let p = cb.backend_coord(&(1.0, c));
                let (px, py) = (p.0 - base.0, p.1 - base.1);
                let style = label.color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
                root.draw(&Text::new(tick_label(c, step), (px + 7, py), style))
                    .map_err(pe)?;
            }
        }
        Ok(())
    }
}
