//! The near region: R_o of a table [`Model`] with a hole — two equal infinite plates with a
//! frictionless interface, or the single plate 2D thick — uniform pressure on A ≤ r ≤ B, where
//! the hole is near the contact edge (the far table's handover bound is too large there), from
//! a tensor Chebyshev interpolant built offline by the model's holed route at 1e-8, with an
//! error bar.
//!
//! **What.** y = (R_o − B)/D as a function of a = A/D ∈ [0.25, 4], w = (B − A)/D ∈
//! [[`W_MIN`], [`W_MAX`]] and ν ∈ [0, 0.5] (R_o/D depends on these three ratios alone: the
//! report's two-plate model, Ch. II.B, and its single plate, Ch. II.A, at C = ∞; D one plate's
//! thickness).
//!
//! **Method.** The domain is cut in w into panels; on each, y is interpolated at the tensor
//! grid of Chebyshev points of the first kind in (ln a, v, ν), v = ln w on the panels below
//! w = 1.2 (the load narrows onto the hole's corner as w → 0: the log map keeps that end's
//! non-analyticity away from the interval) and v = w on the others (short: the hole's faster
//! Papkovich–Fadle modes still vary there). The samples are
//! [`crate::hankel::receding::holed::two_plate_hole_to`] (two plates) or
//! [`crate::hankel::hole::single_plate_separation`] (single plate) at 1e-8 (example 27 builds
//! them and writes `src/table/data/near.json` or `near_single.json` with its provenance: route,
//! tolerance, commit, date); the
//! coefficients c_ijk come from the discrete cosine transform of type II along each axis. The
//! error bar of R_o (in D) is the sum of
//! 1. the interpolation bound, per axis: the axis's coefficient magnitudes m_i = Σ_jk |c_ijk|
//!    (each bounds that axis's 1D coefficient at every point of the other two) with their
//!    envelope |m_i| ≤ Cρ^(−i) ([`super::far::envelope`]: ρ fitted on the last half) summed
//!    over the missing terms, 2C Σ_{i≥N} ρ^(−i) (infinite when ρ = 1: no decay, no bound);
//! 2. the build error: the samples' estimates e_ijk (the route's own, within 1e-8 R_o but
//!    where the route could not reach it: narrow loads on wide holes) through the cardinal
//!    functions, Σ |ℓ_i(s_a) ℓ_j(s_v) ℓ_k(s_ν)| e_ijk (at most the largest e times the tensor
//!    Lebesgue function).
//!
//! `converged` is bar ≤ tol·R_o. Outside the domain the answer is a typed [`InputError`] naming
//! the ratio (the caller takes the far table or a solver).
//!
//! # Accuracy
//!
//! `tests/table/near.rs`: random points (seed fixed) against fresh 1e-8 solves not used to
//! build the table, |table − route| ≤ bar + the route's estimate, and the same on the held-out
//! solves kept in `reference/tables/` (two plates: 10⁴ points by the route at 1e-5, 1,600 at
//! 1e-8; the single plate: 10⁴ at 1e-8; example 27 `validate` draws them and `check` prints
//! their distribution: `docs/tables.md`).
//!
//! # Cost
//!
//! Three Chebyshev recurrences and one tensor sum over the panel's N_a·N_v·N_ν coefficients,
//! and three Lebesgue sums: about a microsecond (`benches/table.rs`); the data are parsed once
//! per process.
//!
//! ```
//! use boltzone::table::{near::separation_radius, Model};
//! // two plates 0.1 in thick, hole 0.1 in, bearing face to 0.22 in (Table 1, A/D = 1, B/A = 2.2)
//! let r = separation_radius(Model::TwoPlates, 0.1, 0.22, 0.1, 0.3, 1e-2)?;
//! // the 1e-8 route: R_o/A = 2.6235234 (`docs/tables.md`)
//! assert!(r.converged && (r.value - 0.26235234).abs() <= r.error);
//! # Ok::<(), boltzone::InputError>(())
//! ```

use super::far::envelope;
use super::Model;
use crate::error::{positive, InputError};
use crate::value::Value;
use serde::Deserialize;
use std::sync::OnceLock;

/// Smallest A/D of the near table.
pub const A_MIN: f64 = 0.25;
/// Largest A/D of the near table.
pub const A_MAX: f64 = 4.0;
/// Smallest (B − A)/D of the near table.
pub const W_MIN: f64 = 0.15;
/// Largest (B − A)/D of the near table: beyond it the far table's handover bound is below
/// 1e-8 of R_o (`super::far`).
pub const W_MAX: f64 = 5.0;
/// Largest Poisson's ratio of the near table (the smallest is 0).
pub const NU_MAX: f64 = 0.5;

/// One panel of the near table, as shipped.
#[derive(Debug, Clone, Deserialize)]
pub struct Panel {
    /// Smallest w = (B − A)/D of the panel.
    pub w_lo: f64,
    /// Largest w of the panel.
    pub w_hi: f64,
    /// Whether the w axis is mapped by ln w (else linearly).
    pub log_w: bool,
    /// Points per axis (a, w, ν).
    pub n: [usize; 3],
    /// Each sample's error estimate (the route's), in D, in the order of the samples.
    pub errors: Vec<f64>,
    /// c_ijk, index (i·N_w + j)·N_ν + k: i along ln a, j along w, k along ν.
    pub coefficients: Vec<f64>,
    /// The interpolation bound per axis (in D), computed at load.
    #[serde(skip)]
    tails: [f64; 3],
}

/// The shipped near table.
#[derive(Debug, Clone, Deserialize)]
pub struct NearTable {
    /// How and when it was built (route, tolerance, commit, date, run time).
    pub provenance: String,
    /// The panels, in increasing w.
    pub panels: Vec<Panel>,
}

/// The three axis coordinates s ∈ [−1, 1] of (a, w, ν) on `panel`.
fn coordinates(panel: &Panel, a: f64, w: f64, nu: f64) -> [f64; 3] {
    let map = |x: f64, lo: f64, hi: f64| (2.0 * x - lo - hi) / (hi - lo);
    let s_w = if panel.log_w {
        map(w.ln(), panel.w_lo.ln(), panel.w_hi.ln())
    } else {
        map(w, panel.w_lo, panel.w_hi)
    };
    [
        map(a.ln(), A_MIN.ln(), A_MAX.ln()).clamp(-1.0, 1.0),
        s_w.clamp(-1.0, 1.0),
        map(nu, 0.0, NU_MAX).clamp(-1.0, 1.0),
    ]
}

/// T_0(s)…T_{n−1}(s) into `t`.
fn chebyshev_row(s: f64, t: &mut [f64]) {
    for k in 0..t.len() {
        t[k] = match k {
            0 => 1.0,
            1 => s,
            _ => 2.0 * s * t[k - 1] - t[k - 2],
        };
    }
}

impl Panel {
    /// The panel through `values` of y at its tensor grid (index (i·N_w + j)·N_ν + k, the
    /// axes' first-kind points s = cos(π(i + ½)/N) from +1 down), each within `build_error`
    /// (in D): what example 27 ships.
    pub fn from_samples(
        w_lo: f64,
        w_hi: f64,
        log_w: bool,
        n: [usize; 3],
        values: &[f64],
        errors: &[f64],
    ) -> Self {
        let mut c = values.to_vec();
        // the type-II transform along each axis in turn
        for axis in 0..3 {
            let stride: usize = n[axis + 1..].iter().product();
            let len = n[axis];
            let outer: usize = n[..axis].iter().product();
            for o in 0..outer {
                for inner in 0..stride {
                    let at = |m: usize| (o * len + m) * stride + inner;
                    let line: Vec<f64> = (0..len).map(|m| c[at(m)]).collect();
                    let coef = crate::numerics::chebyshev::first_kind_coefficients(&line);
                    for (m, v) in coef.into_iter().enumerate() {
                        c[at(m)] = v;
                    }
                }
            }
        }
        let mut panel = Self {
            w_lo,
            w_hi,
            log_w,
            n,
            errors: errors.to_vec(),
            coefficients: c,
            tails: [0.0; 3],
        };
        panel.tails = panel.axis_tails();
        panel
    }

    /// The sample points (a, w, ν) of a panel, in the order of [`Panel::from_samples`].
    pub fn nodes(w_lo: f64, w_hi: f64, log_w: bool, n: [usize; 3]) -> Vec<[f64; 3]> {
        let pts = |m: usize| crate::numerics::chebyshev::first_kind_points(m);
        let unmap = |s: f64, lo: f64, hi: f64| lo + 0.5 * (s + 1.0) * (hi - lo);
        let mut out = Vec::with_capacity(n.iter().product());
        for sa in pts(n[0]) {
            for sw in pts(n[1]) {
                for sn in pts(n[2]) {
                    let w = if log_w {
                        unmap(sw, w_lo.ln(), w_hi.ln()).exp()
                    } else {
                        unmap(sw, w_lo, w_hi)
                    };
                    let a = unmap(sa, A_MIN.ln(), A_MAX.ln()).exp();
                    out.push([a, w, unmap(sn, 0.0, NU_MAX)]);
                }
            }
        }
        out
    }

    /// The coefficient magnitudes m_i = Σ over the other two indices of |c|, along `axis`.
    pub fn axis_magnitudes(&self, axis: usize) -> Vec<f64> {
        let [na, nw, nn] = self.n;
        let mut m = vec![0.0; self.n[axis]];
        for i in 0..na {
            for j in 0..nw {
                for k in 0..nn {
                    let c = self.coefficients[(i * nw + j) * nn + k].abs();
                    m[[i, j, k][axis]] += c;
                }
            }
        }
        m
    }

    /// This panel as parsed, with its interpolation bounds computed (they are not shipped).
    pub(super) fn with_tails(mut self) -> Self {
        self.tails = self.axis_tails();
        self
    }

    /// The interpolation bound of each axis (module docs, item 1), in D.
    pub fn tails(&self) -> [f64; 3] {
        self.tails
    }

    fn axis_tails(&self) -> [f64; 3] {
        std::array::from_fn(|axis| {
            let m = self.axis_magnitudes(axis);
            let (big_c, rho) = envelope(&m);
            let q = 1.0 / rho;
            if q < 1.0 {
                2.0 * big_c * q.powi(m.len() as i32) / (1.0 - q)
            } else {
                f64::INFINITY
            }
        })
    }

    /// y = (R_o − B)/D and its bar (in D) at (a, w, ν) within the panel.
    pub fn y(&self, a: f64, w: f64, nu: f64) -> (f64, f64) {
        let s = coordinates(self, a, w, nu);
        let [na, nw, nn] = self.n;
        let mut ta = [0.0; 64];
        let mut tw = [0.0; 64];
        let mut tn = [0.0; 64];
        chebyshev_row(s[0], &mut ta[..na]);
        chebyshev_row(s[1], &mut tw[..nw]);
        chebyshev_row(s[2], &mut tn[..nn]);
        let y = tensor_sum(&self.coefficients, self.n, &ta[..na], &tw[..nw], &tn[..nn]);
        // the samples' errors through the cardinal functions: Σ |ℓ_i ℓ_j ℓ_k| e_ijk
        let (mut la, mut lw, mut ln) = ([0.0; 64], [0.0; 64], [0.0; 64]);
        cardinal(s[0], &mut la[..na]);
        cardinal(s[1], &mut lw[..nw]);
        cardinal(s[2], &mut ln[..nn]);
        let build = tensor_sum(&self.errors, self.n, &la[..na], &lw[..nw], &ln[..nn]);
        (y, self.tails.iter().sum::<f64>() + build)
    }
}

/// Σ_ijk d_ijk·x_i·y_j·z_k over `data` indexed (i·N_w + j)·N_ν + k.
fn tensor_sum(data: &[f64], n: [usize; 3], x: &[f64], y: &[f64], z: &[f64]) -> f64 {
    data.chunks(n[1] * n[2])
        .zip(x)
        .map(|(plane, xi)| {
            let p: f64 = plane
                .chunks(n[2])
                .zip(y)
                .map(|(row, yj)| yj * row.iter().zip(z).map(|(d, zk)| d * zk).sum::<f64>())
                .sum();
            xi * p
        })
        .sum()
}

/// |ℓ_j(s)| of the interpolant at the first-kind points s_j = cos(π(j + ½)/N), N = ℓ.len()
/// (barycentric weights (−1)^j sin(π(j + ½)/N)); at a node 1 there and 0 elsewhere.
fn cardinal(s: f64, l: &mut [f64]) {
    let n = l.len();
    let mut den = 0.0;
    for j in 0..n {
        let theta = std::f64::consts::PI * (j as f64 + 0.5) / n as f64;
        let d = s - theta.cos();
        if d == 0.0 {
            l.fill(0.0);
            l[j] = 1.0;
            return;
        }
        l[j] = if j % 2 == 0 { 1.0 } else { -1.0 } * theta.sin() / d;
        den += l[j];
    }
    for v in l.iter_mut() {
        *v = (*v / den).abs();
    }
}

/// `model`'s shipped table (parsed once).
pub fn table(model: Model) -> &'static NearTable {
    static TWO: OnceLock<NearTable> = OnceLock::new();
    static SINGLE: OnceLock<NearTable> = OnceLock::new();
    let parse = |json: &str| {
        let t: NearTable =
            serde_json::from_str(json).expect("src/table/data/near*.json is written by example 27");
        NearTable {
            panels: t.panels.into_iter().map(Panel::with_tails).collect(),
            ..t
        }
    };
    match model {
        Model::TwoPlates => TWO.get_or_init(|| parse(include_str!("data/near.json"))),
        Model::SinglePlate => SINGLE.get_or_init(|| parse(include_str!("data/near_single.json"))),
    }
}

/// Checks that (A/D, (B − A)/D, ν) lie in the near table's domain (a typed error naming the
/// ratio otherwise).
pub fn check_domain(a: f64, w: f64, nu: f64) -> Result<(), InputError> {
    if !(A_MIN..=A_MAX).contains(&a) {
        return Err(InputError::Parameter {
            field: "A/D (near table)",
            value: a,
            reason: "within 0.25..4 for the near table",
        });
    }
    if !(W_MIN..=W_MAX).contains(&w) {
        return Err(InputError::Parameter {
            field: "(B − A)/D (near table)",
            value: w,
            reason: "within 0.15..5 for the near table",
        });
    }
    if !(0.0..=NU_MAX).contains(&nu) {
        return Err(InputError::Parameter {
            field: "Poisson's ratio (near table)",
            value: nu,
            reason: "within 0..0.5 for the near table",
        });
    }
    Ok(())
}

/// R_o of `model` (two equal infinite plates D thick, frictionless interface, or the single
/// plate 2D thick) with hole A, uniform pressure on A..B, Poisson's ratio ν, from its near
/// table: a [`Value`] in the units of the lengths, converged when its bar is within `tol`·R_o.
/// Errors: bad lengths, or a ratio outside the table ([`check_domain`]).
pub fn separation_radius(
    model: Model,
    a: f64,
    b: f64,
    d: f64,
    nu: f64,
    tol: f64,
) -> Result<Value, InputError> {
    positive("hole radius A", a)?;
    positive("plate thickness D", d)?;
    positive("tolerance", tol)?;
    if b <= a {
        return Err(InputError::LoadRadii { a, b });
    }
    let (ad, w) = (a / d, (b - a) / d);
    check_domain(ad, w, nu)?;
    let t = table(model);
    let Some(panel) = t.panels.iter().find(|p| w <= p.w_hi).or(t.panels.last()) else {
        return Err(InputError::Parameter {
            field: "near table",
            value: 0.0,
            reason: "not built (example 27 writes src/table/data/near*.json)",
        });
    };
    let (y, bar) = panel.y(ad, w, nu);
    Ok(Value::with_tolerance(b + d * y, d * bar, tol))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tensor_polynomial_is_reproduced_from_its_samples() {
        // y = T₂(s_a)·T₁(s_w) + 0.5·T₃(s_ν) on a 4 × 3 × 5 grid: degree within the grid, exact
        let n = [4, 3, 5];
        let pts = Panel::nodes(0.5, 2.0, false, n);
        let s = |p: &[f64; 3]| {
            let t = Panel {
                w_lo: 0.5,
                w_hi: 2.0,
                log_w: false,
                n,
                errors: vec![],
                coefficients: vec![],
                tails: [0.0; 3],
            };
            coordinates(&t, p[0], p[1], p[2])
        };
        let f = |p: &[f64; 3]| {
            let [x, y, z] = s(p);
            (2.0 * x * x - 1.0) * y + 0.5 * (4.0 * z * z * z - 3.0 * z)
        };
        let values: Vec<f64> = pts.iter().map(f).collect();
        let panel = Panel::from_samples(0.5, 2.0, false, n, &values, &vec![0.0; values.len()]);
        let p = [1.3, 0.77, 0.21];
        let (y, _) = panel.y(p[0], p[1], p[2]);
        assert!((y - f(&p)).abs() < 1e-14, "{y} {}", f(&p));
    }
}
