//! The far region: R_o of a holed joint whose hole is far from the contact edge, from a table of
//! the no-hole separation radius, R_o = B + D·g(B/D), with an error bar.
//!
//! **Method.** Far from the hole the holed R_o tends to the no-hole R_o of the disk load 0..B
//! (DESIGN.md, "Why the hole is felt only near it"), which depends on B/D alone (not on ν nor
//! on the load's magnitude): one curve g per model, uniform pressure. Each g is a Chebyshev
//! interpolant in t = D/B on [t_lo, t_hi] ⊂ [0, 1/2] at the Chebyshev points of the first kind,
//! built by example 25 from the no-hole routes (two plates: the receding contact
//! [`crate::hankel::receding::Layer::receding_contact`], whose dense Nyström system caps it at
//! B/D ≈ 60, so t_lo = 1/48; single plate: the slab's [`crate::hankel::Slab::separation_radius`],
//! t_lo = 0 reached at B/D up to 10⁴) and shipped in `src/table/data/far.json` with its
//! provenance. The error bar of R_o (in D) is the sum of
//! 1. the interpolation bound: the coefficients' envelope |c_k| ≤ Cρ^(−k) (ρ by least squares
//!    on the last half of the coefficients, C the smallest constant over them) summed over
//!    the missing terms, 2C Σ_{k≥N} (ρ₀/ρ)^k, ρ₀ = 1 inside [t_lo, t_hi] and ρ₀ = |s| + √(s² − 1)
//!    for the mapped s < −1 beyond (B/D > 1/t_lo: extrapolation; infinite when ρ₀ ≥ ρ);
//! 2. the build error (the samples' largest estimate) times the interpolant's Lebesgue
//!    function at t (barycentric weights of the first-kind points);
//! 3. the hole's handover bound K·e^(−4.212392 x), x = (R_o − A)/D: the round trip of the
//!    first Papkovich–Fadle mode ([`super::decay`]), with K [`HANDOVER_K_TWO`] /
//!    [`HANDOVER_K_SINGLE`] measured (example 24) over A/D 0.25–4, x ≥ 2, uniform load.
//!
//! Outside the measured range of the handover bound (A/D > [`MAX_A_OVER_D`], x <
//! [`MIN_HANDOVER_X`]) and B/D below the table the answer is a typed [`InputError`] naming the
//! ratio: the caller takes a solver there.
//!
//! # Accuracy
//!
//! `tests/table/far.rs`: the tables against fresh no-hole solves at points not used to build
//! them (|table − solve| ≤ bar), the single plate's extrapolated bar against its own table to
//! B/D = ∞, and the holed routes within the bar where the hole is far. Example 25's `check`.
//!
//! # Cost
//!
//! One Clenshaw sum and one barycentric sum over N ≈ 20 coefficients: well under a
//! microsecond (`benches/table.rs`); the data are parsed once per process.
//!
//! ```
//! use boltzone::table::{far::separation_radius, Model};
//! // two plates 0.1 in thick, hole 0.1 in, head 1.2 in: the hole is 11 D from the edge
//! let r = separation_radius(Model::TwoPlates, 0.1, 1.2, 0.1, 1e-8)?;
//! assert!(r.converged && (r.value - 1.2) > 0.03 && (r.value - 1.2) < 0.05);
//! # Ok::<(), boltzone::InputError>(())
//! ```

use super::decay::HANDOVER_RATE;
use super::Model;
use crate::error::{non_negative, positive, InputError};
use crate::value::Value;
use serde::Deserialize;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The handover prefactor K for two plates: |Δ| ≤ K·D·e^(−4.212392 x) held over the survey of
/// example 24 (A/D 0.25–4, (B − A)/D 0.5–8, ν 0, 0.3, 0.45, x ≥ 2) with its largest ratio
/// doubled (docs/tables.md quotes the survey).
pub const HANDOVER_K_TWO: f64 = 50.0;
/// The same prefactor for the single plate 2D thick (example 24, ν = 0.3).
pub const HANDOVER_K_SINGLE: f64 = 300.0;
/// Largest A/D over which the handover prefactor was measured.
pub const MAX_A_OVER_D: f64 = 4.0;
/// Smallest x = (R_o − A)/D from which the handover prefactor was measured.
pub const MIN_HANDOVER_X: f64 = 2.0;

/// One model's table of g(B/D), as shipped.
#[derive(Debug, Clone, Deserialize)]
pub struct FarTable {
    /// Smallest t = D/B of the interpolation interval (0: B/D = ∞ included).
    pub t_lo: f64,
    /// Largest t = D/B (the table's smallest B/D is 1/t_hi).
    pub t_hi: f64,
    /// The samples' largest error estimate, in D.
    pub build_error: f64,
    /// Chebyshev coefficients c₀…c_{N−1} on [t_lo, t_hi].
    pub coefficients: Vec<f64>,
    /// The coefficients' envelope (C, ρ), computed at load.
    #[serde(skip)]
    envelope: (f64, f64),
}

impl FarTable {
    /// The table through `values` of g at the first-kind points of [t_lo, t_hi]
    /// (t_j = t_lo + (s_j + 1)(t_hi − t_lo)/2, s_j = cos(π(j + ½)/N)), each within
    /// `build_error` (in D): what example 25 ships.
    pub fn from_samples(t_lo: f64, t_hi: f64, values: &[f64], build_error: f64) -> Self {
        let coefficients = crate::numerics::chebyshev::first_kind_coefficients(values);
        Self {
            t_lo,
            t_hi,
            build_error,
            envelope: envelope(&coefficients),
            coefficients,
        }
    }

    /// The sample abscissae t_j = D/B of a table of `n` points on [t_lo, t_hi].
    pub fn nodes(t_lo: f64, t_hi: f64, n: usize) -> Vec<f64> {
        crate::numerics::chebyshev::first_kind_points(n)
            .iter()
            .map(|s| t_lo + 0.5 * (s + 1.0) * (t_hi - t_lo))
            .collect()
    }
}

#[derive(Deserialize)]
struct FarFile {
    two_plates: FarTable,
    single_plate: FarTable,
}

fn tables() -> &'static FarFile {
    static TABLES: OnceLock<FarFile> = OnceLock::new();
    TABLES.get_or_init(|| {
        let mut f: FarFile = serde_json::from_str(include_str!("data/far.json"))
            .expect("src/table/data/far.json is written by example 25");
        for t in [&mut f.two_plates, &mut f.single_plate] {
            t.envelope = envelope(&t.coefficients);
        }
        f
    })
}

/// (C, ρ) with |c_k| ≤ Cρ^(−k) over the last half of the coefficients, ρ by least squares of
/// log|c_k| against k there (a zero coefficient is skipped).
pub fn envelope(c: &[f64]) -> (f64, f64) {
    let n = c.len();
    let pts: Vec<(f64, f64)> = (n / 2..n)
        .filter(|&k| c[k] != 0.0)
        .map(|k| (k as f64, c[k].abs().ln()))
        .collect();
    let m = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / m, sy / m);
    let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(a, b), p| {
        (a + (p.0 - mx) * (p.1 - my), b + (p.0 - mx) * (p.0 - mx))
    });
    // a flat or rising tail (the build's noise floor) bounds nothing: ρ = 1
    let rho = (-sxy / sxx).exp().max(1.0);
    let big_c = (n / 2..n)
        .map(|k| c[k].abs() * rho.powi(k as i32))
        .fold(0.0f64, f64::max);
    (big_c, rho)
}

impl FarTable {
    /// The table of `model`.
    pub fn of(model: Model) -> &'static FarTable {
        let f = tables();
        match model {
            Model::TwoPlates => &f.two_plates,
            Model::SinglePlate => &f.single_plate,
        }
    }

    /// g(B/D) and its bar (interpolation bound + build error × Lebesgue function), in D, for
    /// t = D/B in [0, t_hi]; the bar is infinite where the extrapolation bounds nothing.
    pub fn g(&self, t: f64) -> (f64, f64) {
        let s = (2.0 * t - self.t_lo - self.t_hi) / (self.t_hi - self.t_lo);
        let value = crate::numerics::chebyshev::clenshaw(&self.coefficients, s);
        let n = self.coefficients.len();
        let (big_c, rho) = self.envelope;
        let rho0 = if s < -1.0 {
            -s + (s * s - 1.0).sqrt()
        } else {
            1.0
        };
        let q = rho0 / rho;
        let tail = if q < 1.0 {
            2.0 * big_c * q.powi(n as i32) / (1.0 - q)
        } else {
            f64::INFINITY
        };
        (value, tail + self.build_error * lebesgue(n, s))
    }
}

/// Σ_j |ℓ_j(s)| of the interpolant at the N first-kind points s_j = cos(π(j + ½)/N)
/// (barycentric weights (−1)^j sin(π(j + ½)/N)); 1 at a node.
pub fn lebesgue(n: usize, s: f64) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for j in 0..n {
        let theta = PI * (j as f64 + 0.5) / n as f64;
        let d = s - theta.cos();
        if d == 0.0 {
            return 1.0;
        }
        let w = if j % 2 == 0 { 1.0 } else { -1.0 } * theta.sin() / d;
        num += w.abs();
        den += w;
    }
    num / den.abs()
}

/// R_o of a joint with hole A, load outer radius B (uniform pressure on A..B), plate thickness
/// D (one plate; the single plate is 2D thick), C = ∞, any ν, from the far table: a
/// [`Value`] in the units of the lengths, converged when its bar is within `tol`·R_o. A = 0 is
/// the no-hole disk load itself (no handover term). Errors: bad lengths, B/D below the table,
/// A/D above [`MAX_A_OVER_D`], or the hole nearer than [`MIN_HANDOVER_X`]·D to the contact
/// edge (the near region: a solver's).
pub fn separation_radius(
    model: Model,
    a: f64,
    b: f64,
    d: f64,
    tol: f64,
) -> Result<Value, InputError> {
    non_negative("hole radius A", a)?;
    positive("load outer radius B", b)?;
    positive("plate thickness D", d)?;
    positive("tolerance", tol)?;
    if b <= a {
        return Err(InputError::LoadRadii { a, b });
    }
    let table = FarTable::of(model);
    let t = d / b;
    if t > table.t_hi {
        return Err(InputError::Parameter {
            field: "B/D (far table)",
            value: b / d,
            reason: "at least 2 for the far table",
        });
    }
    if a / d > MAX_A_OVER_D {
        return Err(InputError::Parameter {
            field: "A/D (far table)",
            value: a / d,
            reason: "at most 4 for the far table (its handover bound is measured to there)",
        });
    }
    let (g, bar) = table.g(t);
    let r_o = b + d * g;
    let x = (r_o - a) / d;
    let handover = if a == 0.0 {
        0.0
    } else {
        if x < MIN_HANDOVER_X {
            return Err(InputError::Parameter {
                field: "(R_o − A)/D (far table)",
                value: x,
                reason: "at least 2 for the far table (its handover bound is measured from there)",
            });
        }
        let k = match model {
            Model::TwoPlates => HANDOVER_K_TWO,
            Model::SinglePlate => HANDOVER_K_SINGLE,
        };
        k * (-HANDOVER_RATE * x).exp()
    };
    Ok(Value::with_tolerance(r_o, d * (bar + handover), tol))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lebesgue_function_is_one_at_nodes_and_above_one_between() {
        let s = (PI * 2.5 / 9.0).cos();
        assert_eq!(lebesgue(9, s), 1.0);
        // Σ ℓ_j = 1, so Σ |ℓ_j| ≥ 1; between first-kind nodes it stays below (2/π) ln N + 1
        let mid = 0.5 * ((PI * 2.5 / 9.0).cos() + (PI * 3.5 / 9.0).cos());
        let l = lebesgue(9, mid);
        assert!(l >= 1.0 && l <= 2.0 / PI * 9f64.ln() + 1.0, "{l}");
    }

    #[test]
    fn the_envelope_of_geometric_coefficients_is_their_ratio() {
        let c: Vec<f64> = (0..16).map(|k| 0.7 * 3f64.powi(-k)).collect();
        let (big_c, rho) = envelope(&c);
        // exact geometric data: limited by round-off in the logarithms
        assert!(
            (rho - 3.0).abs() < 1e-12 && (big_c - 0.7).abs() < 1e-11,
            "{big_c} {rho}"
        );
    }
}
