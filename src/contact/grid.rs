//! Graded one-dimensional grids: the radial and axial node lines of a structured plate mesh.
//!
//! A grid runs from `start` to `end` through given key points (hole A, load edge B, an estimate
//! of R_o, …), each with a wanted spacing there. The local spacing is the size function
//! h(x) = min(h_max, min_k (h_k + (q − 1)|x − x_k|)), which grows geometrically at most by the
//! factor q away from each key point. Between consecutive key points the grid marches with that
//! spacing and then stretches its steps uniformly so that it lands exactly on the next key point.
//! Units: those of the inputs.
//!
//! (A stand-in for the FE module's mesh grading, written here while `fem` is being built; the FE
//! module may absorb it.)
//!
//! ```
//! use boltzone::contact::grid::{graded, KeyPoint};
//! let x = graded(0.1, 1.54, &[KeyPoint { x: 0.1, h: 0.01 }, KeyPoint { x: 0.31, h: 0.002 }], 1.2, 0.1);
//! assert_eq!(x[0], 0.1);
//! assert_eq!(*x.last().unwrap(), 1.54);
//! assert!(x.iter().any(|&v| v == 0.31));
//! assert!(x.windows(2).all(|w| w[1] > w[0] && w[1] - w[0] <= 0.1 + 1e-12));
//! ```

/// A point the grid must contain, with the spacing wanted there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeyPoint {
    /// Position.
    pub x: f64,
    /// Wanted spacing at the point (> 0).
    pub h: f64,
}

/// Nodes from `start` to `end` (both included) through every key point inside, graded by the
/// size function of the module docs with growth factor `q` (> 1) and cap `h_max`.
pub fn graded(start: f64, end: f64, keys: &[KeyPoint], q: f64, h_max: f64) -> Vec<f64> {
    let size = |x: f64| {
        keys.iter()
            .map(|k| k.h + (q - 1.0) * (x - k.x).abs())
            .fold(h_max, f64::min)
    };
    let mut stops: Vec<f64> = keys
        .iter()
        .map(|k| k.x)
        .filter(|&x| x > start && x < end)
        .collect();
    stops.push(end);
    stops.sort_by(f64::total_cmp);
    stops.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * end.abs().max(1.0));
    let mut nodes = vec![start];
    let mut a = start;
    for &b in &stops {
        // March with the local size (evaluated at the step's far end as well, so a step never
        // outgrows the size function), then stretch to land on b.
        let mut xs = vec![a];
        let mut x = a;
        while x < b {
            let h = size(x).min(size((x + size(x)).min(b)));
            x += h;
            xs.push(x);
        }
        let n = xs.len() - 1;
        let n = if n > 1 && (xs[n] - b) > 0.5 * (xs[n] - xs[n - 1]) {
            n - 1
        } else {
            n
        }
        .max(1);
        // Keep the relative step sizes of the march, scaled to fill [a, b].
        let steps: Vec<f64> = (0..n).map(|i| xs[i + 1] - xs[i]).collect();
        let total: f64 = steps.iter().sum();
        let mut acc = a;
        for (i, s) in steps.iter().enumerate() {
            acc += s * (b - a) / total;
            nodes.push(if i + 1 == n { b } else { acc });
        }
        a = b;
    }
    nodes
}
