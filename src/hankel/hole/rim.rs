//! A rim too far from R_o to move it at the tolerance asked: when the single plate's R_o may
//! be taken from the infinite plate, and the bound on the difference that joins its estimate.
//!
//! **What is bounded.** Freeing the rim r = C adds a field whose traction on r = C cancels
//! the traction the infinite plate leaves there. Its z-mean part (the uniform in-plane state
//! σ_r = σ_θ and the Lamé field c/r, [`super::eigen`]) has no σ_z at all; the rest is
//! self-equilibrated through the thickness and decays into the plate like the slowest
//! symmetric Papkovich–Fadle mode, |I₀(λ₁r)/I₀(λ₁C)| ≈ √(C/r)·e^(−Re λ₁ (C − r)), with
//! λ₁D = 2.1062 + 1.1254i the first root of sin 2x + 2x = 0 ([`super::eigen::symmetric_roots`];
//! Saint-Venant decay in the layer, Fadle 1941). The bound on R_o's shift taken here is
//!
//! δR_o ≤ P·√(C/R_o)·e^(−Re(λ₁D)·(C − R_o)/D) / |∂σ_z/∂r(R_o)|,
//!
//! i.e. a rim traction no larger than the mean pressure P, carried to R_o by the slowest mode
//! at unit amplitude, divided by the slope of the midplane σ_z at its zero (the same
//! linearisation as every other share of R_o's estimate). Lengths in any unit; P in the load's
//! pressure units (the bound is a length).
//!
//! **Use.** [`super::single_plate_separation`] first solves the plate without its rim when that
//! is likely to pass ([`worth_trying`]), to 1 − [`RIM_SHARE`] of the tolerance asked; when the
//! bound is at most [`RIM_SHARE`]·tolerance·R_o that result stands, with the bound added to its
//! estimate (and reported as [`super::HoleInfo::rim_bound`]); else the rim is fitted. Fitting a
//! rim costs 3–5× the rest of the hole route on Table 1 (C = 1.54 in = 12–15 D beyond R_o),
//! where its effect on R_o is ~1e-10 of R_o.
//!
//! # Accuracy
//!
//! The bound holds with a wide margin: the actual shift (R_o with the rim fitted against R_o
//! without, both to 1e-8) was at most 0.042 of the bound on 150 geometries (A/D 0.3–5, B/A
//! 1.1–6, ν 0–0.45, C − R_o from 0.25D to 4D), falling faster than the bound with distance
//! (the slab's own traction at C decays too): `tests/hankel/hole_fast.rs`,
//! `rim_bound_holds_against_the_fitted_rim`.
//!
//! # Cost
//!
//! A few floating-point operations; what it saves is timed by example 17.
//!
//! ```
//! use boltzone::hankel::hole::rim::rim_bound;
//! // Table 1 row 1: C = 1.54 in, R_o ≈ 0.403 in, D = 0.1 in, slope ≈ 0.5 P/in
//! let b = rim_bound(1.54, 0.403, 0.1, 0.5, 1.0);
//! assert!(b > 0.0 && b < 1e-9);
//! // a rim half a thickness beyond R_o bounds nothing useful
//! assert!(rim_bound(0.453, 0.403, 0.1, 0.5, 1.0) > 0.1);
//! ```

use super::eigen::symmetric_roots;

/// Share of R_o's tolerance a neglected rim may take.
pub const RIM_SHARE: f64 = 0.1;

/// Whether the plate without its rim is worth trying at relative tolerance `tol`: the bound
/// predicted at R_o = B + D with a slope of 0.1 P/D (R_o − B is 0.3–2 D and the slopes are
/// 0.03–0.16 P/D on Table 1 and the tests' geometries) meets [`RIM_SHARE`] of the tolerance.
/// Only the cost depends on it: a rim not tried is fitted, and a trial whose actual bound
/// misses is followed by the fit (Table 1's A/D = 0.5 rows at 5e-4 were such trials, 8–13 %
/// of their time wasted, before this prediction).
pub fn worth_trying(c: f64, b: f64, d: f64, tol: f64) -> bool {
    let r = b + d;
    rim_bound(c, r, d, 0.1 / d, 1.0) <= RIM_SHARE * tol * r
}

/// The bound of the module docs on |R_o(rim fitted) − R_o(infinite plate)|: rim radius `c`,
/// the infinite plate's `r_o`, half-thickness `d`, slope |∂σ_z/∂r| at R_o (pressure per
/// length) and mean pressure `p`. Infinite when C ≤ R_o or the slope is zero.
pub fn rim_bound(c: f64, r_o: f64, d: f64, slope: f64, p: f64) -> f64 {
    let decay = symmetric_roots(1)[0].re;
    if c <= r_o || slope == 0.0 || !slope.is_finite() {
        return f64::INFINITY;
    }
    p.abs() * (c / r_o).sqrt() * (-decay * (c - r_o) / d).exp() / slope.abs()
}
