//! Bracketed root finding (Brent 1973, *Algorithms for Minimization without Derivatives*, ch. 4):
//! inverse quadratic interpolation guarded by bisection, so the bracket always shrinks; and the
//! scan that finds the bracket: the first upward crossing f(x_(k−1)) ≤ 0 < f(x_k) met by a scan
//! ([`first_upward_crossing`], [`first_upward_root`]). Shared by every separation-radius search
//! of the crate (slab, slab with a hole, receding layer).
//!
//! # Accuracy
//!
//! The root to the half-width asked; Brent's superlinear convergence is checked in
//! `tests/numerics/root.rs`.
//!
//! # Cost
//!
//! One evaluation per scan point and per iteration.
//!
//! ```
//! use boltzone::numerics::root::brent;
//! let mut f = |x: f64| Ok::<f64, std::convert::Infallible>(x * x - 2.0);
//! let r = brent(&mut f, 1.0, -1.0, 2.0, 2.0, 1e-14, 100)?;
//! assert!((r.x - 2f64.sqrt()).abs() < 1e-13);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

/// A root and the half-width of its final bracket.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// The root's estimate.
    pub x: f64,
    /// Half-width of the bracket around it when the iteration stopped.
    pub half_width: f64,
}

/// Brent's method on a bracket [a, b] with f(a)·f(b) ≤ 0, to half-width `tol` or `max_iter`
/// evaluations. `f` may fail: its first error is returned.
pub fn brent<E, F: FnMut(f64) -> Result<f64, E>>(
    f: &mut F,
    mut a: f64,
    mut fa: f64,
    mut b: f64,
    mut fb: f64,
    tol: f64,
    max_iter: usize,
) -> Result<Root, E> {
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..max_iter {
        if (fb > 0.0) == (fc > 0.0) {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa, b, fb, c, fc) = (b, fb, c, fc, b, fb);
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol1 || fb == 0.0 {
            return Ok(Root {
                x: b,
                half_width: m.abs().max(tol1),
            });
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            // inverse quadratic interpolation (secant when a = c)
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * m * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol1 { d } else { tol1.copysign(m) };
        fb = f(b)?;
    }
    Ok(Root {
        x: b,
        half_width: (c - b).abs(),
    })
}

/// Two neighbouring scan points, each (x, f(x)), with f(before) ≤ 0 < f(after).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// The last point with f ≤ 0.
    pub before: (f64, f64),
    /// The first point after it with f > 0.
    pub after: (f64, f64),
}

/// The first upward crossing among the samples `sample(0)`, `sample(1)`, …, `sample(last)`,
/// each (x_k, f(x_k)) in scan order (either direction): the first k ≥ 1 with
/// f(x_(k−1)) ≤ 0 < f(x_k). `Ok(None)` when there is none; the first error of `sample` is
/// returned.
pub fn first_upward_crossing<E>(
    mut sample: impl FnMut(usize) -> Result<(f64, f64), E>,
    last: usize,
) -> Result<Option<Crossing>, E> {
    let mut before = sample(0)?;
    for k in 1..=last {
        let after = sample(k)?;
        if before.1 <= 0.0 && after.1 > 0.0 {
            return Ok(Some(Crossing { before, after }));
        }
        before = after;
    }
    Ok(None)
}

/// The number of steps of `step` (either sign, non-zero) from `start` to reach `end`: the scan
/// points are x_k = start + k·step for k < that number, and `end` for the last.
pub fn scan_steps(start: f64, end: f64, step: f64) -> usize {
    let n = ((end - start) / step).ceil();
    if n.is_finite() && n > 0.0 {
        n as usize
    } else {
        0
    }
}

/// Scans x_k = start + k·step (the last point clamped to `end`) from `start` = (x₀, f(x₀)) for
/// the first upward crossing of f, then refines it by [`brent`] to half-width `tol`.
/// `Ok(None)` when f has no upward crossing on the scan.
pub fn first_upward_root<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    start: (f64, f64),
    step: f64,
    end: f64,
    tol: f64,
    max_iter: usize,
) -> Result<Option<Root>, E> {
    let last = scan_steps(start.0, end, step);
    let at = |k: usize| {
        let x = start.0 + k as f64 * step;
        if k == last || (step > 0.0 && x > end) || (step < 0.0 && x < end) {
            end
        } else {
            x
        }
    };
    let crossing = first_upward_crossing(
        |k| {
            if k == 0 {
                return Ok(start);
            }
            let x = at(k);
            Ok((x, f(x)?))
        },
        last,
    )?;
    let Some(Crossing { before, after }) = crossing else {
        return Ok(None);
    };
    brent(f, before.0, before.1, after.0, after.1, tol, max_iter).map(Some)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::convert::Infallible;

    #[test]
    fn first_upward_root_finds_the_first_upward_zero_in_either_direction() {
        let mut f = |x: f64| Ok::<f64, Infallible>(x.cos());
        // outward from 0: cos falls through π/2 (downward) and rises through 3π/2
        let Ok(r) = first_upward_root(&mut f, (0.0, 1.0), 0.7, 10.0, 1e-14, 100);
        let r = r.map(|r| r.x).unwrap_or(f64::NAN);
        assert!((r - 1.5 * std::f64::consts::PI).abs() < 1e-13, "{r}");
        // inward from 4 (cos 4 < 0): the first upward crossing met going down is π/2
        let Ok(r) = first_upward_root(&mut f, (4.0, 4f64.cos()), -0.7, 0.1, 1e-14, 100);
        let r = r.map(|r| r.x).unwrap_or(f64::NAN);
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-13, "{r}");
        // none on [0, 1]
        let Ok(r) = first_upward_root(&mut f, (0.0, 1.0), 0.3, 1.0, 1e-14, 100);
        assert!(r.is_none());
    }

    #[test]
    fn scan_steps_reaches_the_end() {
        assert_eq!(scan_steps(0.0, 1.0, 0.3), 4);
        assert_eq!(scan_steps(1.0, 0.0, -0.5), 2);
        assert_eq!(scan_steps(1.0, 1.0, 0.5), 0);
    }
}
