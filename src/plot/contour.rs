//! Axis ticks at round numbers and contour lines of gridded data, for the heat maps.
//!
//! - [`nice_ticks`]: the multiples of a step 1, 2 or 5 × 10ᵏ inside a range, the step chosen as
//!   the smallest giving at most the wanted count (the "nice numbers" rule of Heckbert, Graphics
//!   Gems I, 1990).
//! - [`log_ticks`]: on a logarithmic axis, the numbers m × 10ᵏ with m ∈ {1, 2, 5} inside the
//!   range, or every m ∈ {1, …, 9} when that gives fewer than three.
//! - [`contour_segments`]: the level set z = c of values on a rectilinear grid by marching
//!   squares (linear interpolation along each cell edge; a saddle cell is resolved by the mean of
//!   its four corners), as straight segments.
//!
//! # Accuracy
//!
//! Marching squares is exact for data linear in x and y — `tests/io/figure_map.rs` checks every
//! segment end of z = x + 2y on a non-uniform grid against the line x + 2y = c, and the ticks
//! against hand-listed round numbers.
//!
//! # Cost
//!
//! One pass over the grid per level.
//!
//! ```
//! use boltzone::plot::contour::{log_ticks, nice_ticks};
//! assert_eq!(nice_ticks(-3.2, 11.7, 8), vec![-2.0, 0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
//! assert_eq!(log_ticks(0.2, 5.0), vec![0.2, 0.5, 1.0, 2.0, 5.0]);
//! ```

/// The multiples of the smallest step 1, 2 or 5 × 10ᵏ that gives at most `max_count` of them in
/// [`lo`, `hi`] (empty for an empty or non-finite range).
pub fn nice_ticks(lo: f64, hi: f64, max_count: usize) -> Vec<f64> {
    let span = hi - lo;
    if !span.is_finite() || span <= 0.0 || max_count == 0 {
        return Vec::new();
    }
    let mut k = (span / max_count as f64).log10().floor() as i32 - 1;
    loop {
        for m in [1.0, 2.0, 5.0] {
            let step = m * 10f64.powi(k);
            let (first, last) = ((lo / step).ceil() as i64, (hi / step).floor() as i64);
            if last - first < max_count as i64 {
                // multiples computed as i·step, rounded to the step's decimals (no 0.30000000000000004)
                return (first..=last)
                    .map(|i| round_to(i as f64 * step, step))
                    .collect();
            }
        }
        k += 1;
    }
}

/// The round numbers m × 10ᵏ (m ∈ {1, 2, 5}, or 1..9 when that gives fewer than three) in
/// [`lo`, `hi`], both positive.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Vec::new();
    }
    let pick = |mantissas: &[f64]| -> Vec<f64> {
        let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
        let mut v = Vec::new();
        for k in k0..=k1 {
            for &m in mantissas {
                let t = round_to(m * 10f64.powi(k), 10f64.powi(k));
                if t >= lo * (1.0 - 1e-12) && t <= hi * (1.0 + 1e-12) {
                    v.push(t);
                }
            }
        }
        v
    };
    let v = pick(&[1.0, 2.0, 5.0]);
    if v.len() >= 3 {
        v
    } else {
        pick(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
    }
}

/// `x` rounded to the decimals of `step` (a power of ten times 1, 2 or 5).
fn round_to(x: f64, step: f64) -> f64 {
    let d = decimals(step) as i32;
    let s = 10f64.powi(d);
    (x * s).round() / s
}

/// Decimals that show `step` (1, 2 or 5 × 10ᵏ) exactly: max(0, −k).
pub fn decimals(step: f64) -> usize {
    (-(step.abs().log10().floor())).max(0.0) as usize
}

/// A tick label: `v` with the decimals of `step` ("-0" shown as "0").
pub fn tick_label(v: f64, step: f64) -> String {
    let s = format!("{:.*}", decimals(step), v);
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// A straight piece of a contour line: two (x, y) points.
pub type Segment = ((f64, f64), (f64, f64));

/// The level set z = `level` of `z` over the grid `x` × `y` (z\[i·len(y) + j\] at (x\[i\], y\[j\]))
/// by marching squares (module docs). Cells with a non-finite corner are skipped.
pub fn contour_segments(x: &[f64], y: &[f64], z: &[f64], level: f64) -> Vec<Segment> {
    let ny = y.len();
    let mut out = Vec::new();
    if x.len() < 2 || ny < 2 || z.len() != x.len() * ny {
        return out;
    }
    let at = |i: usize, j: usize| z[i * ny + j];
    // the crossing on the edge from p (value a) to q (value b), if the level separates them
    let cross = |p: (f64, f64), a: f64, q: (f64, f64), b: f64| {
        ((a >= level) != (b >= level)).then(|| {
            let t = (level - a) / (b - a);
            (p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1))
        })
    };
    for i in 0..x.len() - 1 {
        for j in 0..ny - 1 {
            let (v00, v10, v11, v01) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if ![v00, v10, v11, v01].iter().all(|v| v.is_finite()) {
                continue;
            }
            let (p00, p10, p11, p01) = (
                (x[i], y[j]),
                (x[i + 1], y[j]),
                (x[i + 1], y[j + 1]),
                (x[i], y[j + 1]),
            );
            // edges in order bottom, right, top, left
            let e = [
                cross(p00, v00, p10, v10),
                cross(p10, v10, p11, v11),
                cross(p01, v01, p11, v11),
                cross(p00, v00, p01, v01),
            ];
            let hits: Vec<(usize, (f64, f64))> = e
                .iter()
                .enumerate()
                .filter_map(|(k, c)| c.map(|c| (k, c)))
                .collect();
            match hits.len() {
                2 => out.push((hits[0].1, hits[1].1)),
                4 => {
                    let centre = 0.25 * (v00 + v10 + v11 + v01) >= level;
                    let [b, r, t, l] = [hits[0].1, hits[1].1, hits[2].1, hits[3].1];
                    if centre == (v00 >= level) {
                        // the centre joins corners 00 and 11: cut off corners 10 and 01
                        out.extend([(b, r), (t, l)]);
                    } else {
                        out.extend([(b, l), (r, t)]);
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// A linear axis's tick label for `v` on an axis spanning `span`: the fewest decimals that show
/// `v` to 10⁻⁹ of the span (so 0.25 and 1.5, not 0.2500000001 or a rounded 2), in exponent form
/// (2.5e-8) when the span is below 10⁻³ or above 10⁶, and "0" for a zero that rounding made
/// negative.
pub fn axis_label(v: f64, span: f64) -> String {
    let tol = 1e-9 * span.abs();
    if v.abs() <= tol {
        return "0".into();
    }
    let exponent = span.abs() < 1e-3 || span.abs() > 1e6;
    let scale = if exponent {
        10f64.powf(v.abs().log10().floor())
    } else {
        1.0
    };
    let m = v / scale;
    let digits = (0..=12usize)
        .find(|&d| {
            let p = 10f64.powi(d as i32);
            ((m * p).round() / p - m).abs() * scale <= tol
        })
        .unwrap_or(12);
    if exponent {
        format!("{:.*e}", digits, v)
    } else {
        format!("{:.*}", digits, v)
    }
}
