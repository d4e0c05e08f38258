//! A design map: R_o/A of the single-plate substitution and of the two-plate model, and each
//! rule of thumb's error against the two-plate answer, over a grid of A/D × B/A (default
//! A/D ∈ [0.2, 5] × B/A ∈ [1.1, 5], 40 × 40, logarithmically spaced), at fixed C/A (default
//! Table 1's 15.4) and ν (0.3). Each point is one [`super::compare`], run in parallel with
//! rayon; each model's R_o meets the relative tolerance `tolerance` (default 1e-3 = 0.1 %) by its
//! own error estimate, which the CSV carries beside each value with the method that produced it
//! and whether it converged. [`MapParams::method`] picks the method ([`super::route`]): the finite
//! elements (default), the Hankel routes (refused, before any point is computed, when a point
//! is beyond the two-plate route's reach: [`check_reach`]), the tables (infinite plates,
//! `c_over_a` = ∞; refused the same way outside them) or `auto` (the route layer's choice per
//! point and model: the tables where their bar meets the tolerance, the single plate's Hankel
//! route, the two plates' only below a tolerance of 3e-5, [`super::two_takes_hankel`]).
//!
//! # Accuracy
//!
//! Each point's R_o to the tolerance by its own estimate (example 13 checks the estimates against
//! references 50 times tighter); the map is smooth and monotone and equals Table 1 at its points
//! (`tests/compare/map.rs`, `tests/compare/tables.rs`). By the Hankel routes the values agree with
//! the FE's within the sum of both estimates (`tests/compare/map_method.rs`; example 13's `map`
//! mode: at most 0.58 (single) and 0.55 (two plates) of it on a 10 × 10 map at 1e-3).
//!
//! # Cost
//!
//! About 20 ms of CPU per point at 1e-3 by the FE, both models (the default 40 × 40 map: 31.6 s of
//! CPU, 15.9 s of wall time on the two cores; 42.0 s and 21.1 s before the FE's assembly and
//! factorization work, measured by turns at load 0.6–1.5, means of two rounds);
//! example 13 times both models point by point against the error they achieve. By `hankel` the
//! two-plate route with the rim dominates: 1.1–3.2 s of CPU per point at 1e-3, growing with B/D
//! (10 × 10 map, every two-plate point by that route where it reaches: 143 s of CPU against the
//! FE's 3.7 s, so about 2,400 s for 40 × 40; example 13, `map` mode, and [`super::route`] for
//! where the time goes); that is why `auto` takes it only below 3e-5, where the FE cannot claim
//! the tolerance.
//!
//! ```
//! use boltzone::compare::map::{compute, log_spaced, MapParams};
//! let p = MapParams { a_over_d: vec![1.0], b_over_a: log_spaced(1.3, 3.1, 2), tolerance: 2e-3,
//!                     ..MapParams::default() };
//! let m = compute(&p, &|| ())?;
//! assert!(m.at(0, 1).two.value > m.at(0, 0).two.value); // wider load, wider contact
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{compare_all, CompareError, CompareParams, Comparison, Geometry, Method};
use crate::error::{positive, InputError};
use std::time::Instant;

/// Knobs of [`compute`].
#[derive(Debug, Clone, PartialEq)]
pub struct MapParams {
    /// A/D values (rows).
    pub a_over_d: Vec<f64>,
    /// B/A values (columns).
    pub b_over_a: Vec<f64>,
    /// Hole radius A (any unit; R_o/A depends only on the ratios).
    pub a: f64,
    /// C/A (default 15.4, Table 1's plates; `f64::INFINITY`: infinite plates, which the
    /// tables answer under `auto`).
    pub c_over_a: f64,
    /// Poisson's ratio (default 0.3).
    pub nu: f64,
    /// Relative tolerance of each R_o (default 1e-3).
    pub tolerance: f64,
    /// How each model's R_o is computed (default [`Method::Fem`]; [`super::route`]).
    pub method: Method,
}

impl Default for MapParams {
    fn default() -> Self {
        Self {
            a_over_d: log_spaced(0.2, 5.0, 40),
            b_over_a: log_spaced(1.1, 5.0, 40),
            a: 0.1,
            c_over_a: 15.4,
            nu: 0.3,
            tolerance: 1e-3,
            method: Method::Fem,
        }
    }
}

/// `n` values from `lo` to `hi` with constant ratio (n = 1: `lo`).
pub fn log_spaced(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![lo];
    }
    (0..n)
        .map(|i| {
            if i + 1 == n {
                hi
            } else {
                lo * (hi / lo).powf(i as f64 / (n - 1) as f64)
            }
        })
        .collect()
}

/// The computed map.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignMap {
    /// A/D values (rows).
    pub a_over_d: Vec<f64>,
    /// B/A values (columns).
    pub b_over_a: Vec<f64>,
    /// Comparisons, row-major: point (i, j) at i·len(b_over_a) + j.
    pub points: Vec<Comparison>,
    /// Wall-clock seconds.
    pub seconds: f64,
}

impl DesignMap {
    /// The point at A/D index `i`, B/A index `j`.
    pub fn at(&self, i: usize, j: usize) -> &Comparison {
        &self.points[i * self.b_over_a.len() + j]
    }

    /// Largest relative error estimate of the single- and two-plate R_o over the map.
    pub fn max_relative_error(&self) -> (f64, f64) {
        self.points.iter().fold((0.0, 0.0), |(s, t), p| {
            (
                f64::max(s, p.single.error / p.single.value),
                f64::max(t, p.two.error / p.two.value),
            )
        })
    }

    /// The points whose models ran by `route`: (single plate, two plates).
    pub fn count(&self, route: super::Route) -> (usize, usize) {
        self.points.iter().fold((0, 0), |(s, t), p| {
            (
                s + usize::from(p.single_method == route),
                t + usize::from(p.two_method == route),
            )
        })
    }

    /// The map as CSV, one line per point: the columns of [`super::table1::COLUMNS`] (each
    /// named with its unit, `a_over_d [1]`), then each model's method (`fem` or `hankel`) and whether its R_o met the
    /// tolerance (`single_method,single_converged,two_method,two_converged`).
    pub fn csv(&self) -> String {
        let header = super::table1::header(&super::table1::COLUMNS);
        let mut s = format!("{header},{METHOD_COLUMNS}\n");
        for p in &self.points {
            s += &format!(
                "{},{},{},{},{}\n",
                super::table1::csv_fields(p),
                p.single_method.as_str(),
                p.single.converged,
                p.two_method.as_str(),
                p.two.converged
            );
        }
        s
    }
}

/// The map CSV's last columns (text, no unit): which method produced each model's R_o, and
/// whether it met the tolerance.
pub const METHOD_COLUMNS: &str = "single_method,single_converged,two_method,two_converged";

/// With [`Method::Hankel`], the first point of the map beyond the two-plate Hankel route's
/// reach ([`super::two_hankel_reach`]), with [`Method::Table`] the first outside either
/// model's tables ([`super::table_reach`]), as [`CompareError::OutOfReach`] naming the point
/// and the model; [`compute`] checks it before computing any point. Ok for the other methods
/// and when every point is in reach (the single plate's Hankel route has no reach limit).
pub fn check_reach(params: &MapParams) -> Result<(), CompareError> {
    let geometries = geometries(params)?;
    for g in geometries {
        let blocked = match params.method {
            Method::Hankel => super::two_hankel_reach(&g).map_err(|r| ("two-plate", r)),
            Method::Table => super::table_reach(&g, params.tolerance),
            _ => Ok(()),
        };
        if let Err((model, reason)) = blocked {
            return Err(CompareError::OutOfReach {
                geometry: g.label(),
                model,
                reason,
            });
        }
    }
    Ok(())
}

/// The map's geometries, row-major (checked).
fn geometries(params: &MapParams) -> Result<Vec<Geometry>, CompareError> {
    positive("hole radius A", params.a)?;
    if params.c_over_a.is_nan() || params.c_over_a <= 0.0 {
        return Err(InputError::Parameter {
            field: "C/A",
            value: params.c_over_a,
            reason: "must be positive (infinite: plates without a rim)",
        }
        .into());
    }
    if params.a_over_d.is_empty() || params.b_over_a.is_empty() {
        return Err(InputError::Parameter {
            field: "map size",
            value: 0.0,
            reason: "both axes need at least one value",
        }
        .into());
    }
    let mut geometries = Vec::new();
    for &ad in &params.a_over_d {
        for &ba in &params.b_over_a {
            geometries.push(Geometry::from_ratios(
                params.a,
                ad,
                ba,
                params.a * params.c_over_a,
                params.nu,
            )?);
        }
    }
    Ok(geometries)
}

/// Computes the map (module docs); `tick` is called once per finished point.
pub fn compute(params: &MapParams, tick: &(dyn Fn() + Sync)) -> Result<DesignMap, CompareError> {
    let start = Instant::now();
    check_reach(params)?;
    let geometries = geometries(params)?;
    let cp = CompareParams {
        tolerance: params.tolerance,
        method: params.method,
        ..CompareParams::default()
    };
    let points = compare_all(&geometries, &cp, tick)
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?;
    Ok(DesignMap {
        a_over_d: params.a_over_d.clone(),
        b_over_a: params.b_over_a.clone(),
        points,
        seconds: start.elapsed().as_secs_f64(),
    })
}
