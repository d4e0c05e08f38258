//! Bracketed root finding (Brent 1973, *Algorithms for Minimization without Derivatives*, ch. 4):
//! inverse quadratic interpolation guarded by bisection, so the bracket always shrinks. Shared by
//! every separation-radius search of the crate (slab, slab with a hole, receding layer).
//!
//! ```
//! use boltzone::hankel::root::brent;
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
