//! A bracketed root of a smooth function that stops on the size of its next step, not of its
//! bracket: for expensive functions (one evaluation of the holed two-plate route's edge
//! coefficient solves a contact problem), where Brent's method ([`super::root::brent`]) spends
//! its last evaluations shrinking the bracket around a root it already has to far below the
//! tolerance.
//!
//! **Method.** Inverse quadratic interpolation through the last three points evaluated (a
//! secant through the last two when two of their values coincide), guarded like Brent's: a
//! candidate outside the bracket [a, b] (f(a)·f(b) ≤ 0) is replaced by the secant through the
//! bracket's ends, and by the midpoint when that too falls outside or when the bracket has not
//! halved over the last three evaluations. It stops when the next candidate lies within `tol`
//! of the last point evaluated, and returns that point: for a simple root of a smooth f the
//! interpolation converges superlinearly (order ≈ 1.84), so the candidate is far nearer the
//! root than the step, and the step bounds the returned point's error.
//!
//! # Accuracy
//!
//! `tests/numerics/secant.rs`: roots of closed-form functions within `tol`, in fewer
//! evaluations than Brent's method asked for the same half-width, and on a function with a
//! kink (where interpolation is poor) the guard still converges.
//!
//! # Cost
//!
//! One evaluation per step; on the holed route's edge coefficient 3 steps after the scan
//! instead of Brent's 6 (example 19).
//!
//! ```
//! use boltzone::numerics::secant::refine;
//! let mut f = |x: f64| Ok::<f64, std::convert::Infallible>(x * x - 2.0);
//! let r = refine(&mut f, &[(1.0, -1.0), (2.0, 2.0)], 1e-12, 50)?;
//! assert!((r.x - 2f64.sqrt()).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::root::Root;

/// The root of `f` from the points already evaluated, `known` (x, f(x)) in the order they were
/// evaluated, the last two bracketing the root (opposite signs or a zero): to within `tol`
/// (the last step), or after `max_iter` further evaluations (the half-width is then the
/// bracket's). Returns the last point evaluated, so that its evaluation can be reused.
/// `f` may fail: its first error is returned.
pub fn refine<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    known: &[(f64, f64)],
    tol: f64,
    max_iter: usize,
) -> Result<Root, E> {
    let n = known.len();
    let mut pts: Vec<(f64, f64)> = known[n.saturating_sub(3)..].to_vec();
    let (Some(&last), Some(&before)) = (known.last(), known.iter().rev().nth(1)) else {
        return Ok(Root {
            x: known.last().map_or(f64::NAN, |p| p.0),
            half_width: f64::INFINITY,
        });
    };
    let (mut a, mut b) = (before, last);
    let mut widths = vec![(b.0 - a.0).abs()];
    for evaluations in 0..=max_iter {
        let cur = pts[pts.len() - 1];
        let (lo, hi) = (a.0.min(b.0), a.0.max(b.0));
        if cur.1 == 0.0 || evaluations == max_iter {
            let half_width = if cur.1 == 0.0 { 0.0 } else { hi - lo };
            return Ok(Root {
                x: cur.0,
                half_width,
            });
        }
        let inside = |x: f64| x.is_finite() && x > lo && x < hi;
        let mut x = interpolate(&pts);
        if !inside(x) {
            x = secant(a, b);
        }
        let k = widths.len();
        let stalled = k > 3 && widths[k - 1] > 0.5 * widths[k - 4];
        let bisect = !inside(x) || stalled;
        if bisect {
            x = 0.5 * (lo + hi);
        }
        // an interpolated step bounds cur's error; a bisection only its bracket's half-width
        let error = if bisect { hi - lo } else { (x - cur.0).abs() };
        if error <= tol {
            return Ok(Root {
                x: cur.0,
                half_width: error,
            });
        }
        let fx = f(x)?;
        // the new bracket: x and whichever end has the other sign
        if (fx > 0.0) == (a.1 > 0.0) {
            a = (x, fx);
        } else {
            b = (x, fx);
        }
        widths.push((b.0 - a.0).abs());
        pts.push((x, fx));
        if pts.len() > 3 {
            pts.remove(0);
        }
    }
    Ok(Root {
        x: pts[pts.len() - 1].0,
        half_width: (b.0 - a.0).abs(),
    })
}

/// Where the secant through `p` and `q` crosses zero (NaN when their values coincide).
fn secant(p: (f64, f64), q: (f64, f64)) -> f64 {
    if p.1 == q.1 {
        return f64::NAN;
    }
    q.0 - q.1 * (q.0 - p.0) / (q.1 - p.1)
}

/// Inverse quadratic interpolation through the (up to) three points at f = 0, falling back to
/// the secant through the last two when two values coincide.
fn interpolate(pts: &[(f64, f64)]) -> f64 {
    let n = pts.len();
    if n < 2 {
        return f64::NAN;
    }
    let (p, q) = (pts[n - 2], pts[n - 1]);
    if n == 3 {
        let o = pts[0];
        let (f0, f1, f2) = (o.1, p.1, q.1);
        if f0 != f1 && f0 != f2 && f1 != f2 {
            return o.0 * f1 * f2 / ((f0 - f1) * (f0 - f2))
                + p.0 * f0 * f2 / ((f1 - f0) * (f1 - f2))
                + q.0 * f0 * f1 / ((f2 - f0) * (f2 - f1));
        }
    }
    secant(p, q)
}
