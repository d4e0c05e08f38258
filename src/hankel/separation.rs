//! The separation radius R_o of the single-plate substitution (Fernlund): the first radius
//! beyond the load's outer radius B where the midplane stress σ_z(r, 0) turns tensile.
//!
//! By symmetry the midplane of the slab 2D thick plays the joint's interface; where σ_z(r, 0)
//! would be tensile the two plates separate. R_o is found by an outward scan from r = B in
//! steps of D/2 for the first sign change of σ_z(r, 0) from compressive to tensile (beyond it
//! σ_z keeps oscillating with amplitude falling ≈ e⁻⁶ per half-wave of ≈ 2.8D: those later
//! crossings are not separations), then Brent's method (Brent 1973, *Algorithms for
//! Minimization without Derivatives*, ch. 4) on the bracket. Only midplane σ_z is evaluated,
//! by a [`Midplane`] evaluator shared by all evaluations (a ξ-rule, or the
//! real-space route for thin slabs). The zero is shallow (slope ≈ 0.01–0.1 P/A),
//! so the error estimate is the final bracket half-width plus the σ_z error divided by the
//! slope at the root.
//!
//! # Accuracy
//!
//! R_o is the first upward zero of directly integrated σ_z (`tests/hankel/separation.rs`,
//! `r_o_is_the_first_upward_zero_of_direct_midplane_stress`); the achieved error is below the
//! estimate for tolerances 1e-4 … 1e-12 (example 01).
//!
//! # Cost
//!
//! `cargo bench --bench hankel` (R_o to 1e-10); example 01 (time against error).
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{Slab, SeparationParams}};
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.1, 0.31, 1.0)?)?;
//! let s = slab.separation_radius(&SeparationParams::default())?;
//! let at = |r: f64| slab.sigma_z(r, 0.0, &Default::default()).value;
//! assert!(at(s.r_o - 1e-6) < 0.0 && at(s.r_o + 1e-6) > 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::field::Slab;
use super::midplane::Midplane;
use crate::error::{positive, InputError};
use crate::numerics::root::first_upward_root;
use std::time::Instant;

/// Knobs of the R_o search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeparationParams {
    /// Relative tolerance on R_o (default 1e-10).
    pub rel_tol: f64,
    /// Scan step as a fraction of D (default 0.5; the half-wavelength of the far-field
    /// oscillation is ≈ 2.8D, so no pair of crossings hides between two steps).
    pub step: f64,
    /// The scan stops at B + `reach`·D (default 12).
    pub reach: f64,
    /// Brent iterations allowed (default 100).
    pub max_iterations: usize,
}

impl Default for SeparationParams {
    fn default() -> Self {
        Self {
            rel_tol: 1e-10,
            step: 0.5,
            reach: 12.0,
            max_iterations: 100,
        }
    }
}

/// R_o with its error estimate and cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeparationInfo {
    /// The separation radius R_o.
    pub r_o: f64,
    /// Estimated absolute error of R_o.
    pub r_o_error: f64,
    /// Whether `error` met the relative tolerance asked (the slab's `rel_tol`, the hole
    /// route's `r_o_tolerance`).
    pub converged: bool,
    /// Midplane σ_z evaluations (scan + root finder).
    pub evaluations: usize,
    /// Slope dσ_z/dr at R_o (pressure per length; positive).
    pub slope: f64,
    /// ξ-nodes of the midplane rule (0: the real-space route was used).
    pub nodes: usize,
    /// Wall-clock time in seconds.
    pub seconds: f64,
}

/// Why no R_o was found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SeparationError {
    /// Bad parameters or a slab outside the solver's range.
    #[error(transparent)]
    Input(#[from] InputError),
    /// σ_z(B, 0) is already tensile: the midplane opens inside the loaded annulus.
    #[error("midplane sigma_z at the load's outer radius B is already tensile ({sigma_z}): no separation radius beyond the load")]
    TensileAtLoadEdge {
        /// σ_z(B, 0).
        sigma_z: f64,
    },
    /// σ_z(r, 0) stayed compressive up to `searched_to`.
    #[error("midplane sigma_z stays compressive from B to r = {searched_to}: no separation found")]
    NotFound {
        /// End of the scan.
        searched_to: f64,
    },
}

impl SeparationError {
    /// Whether the failure is bad input (the caller's to fix) rather than a solver failure.
    pub fn is_input(&self) -> bool {
        matches!(self, Self::Input(_))
    }
}

impl Slab {
    /// The separation radius R_o (see the module docs of [`super::separation`]).
    pub fn separation_radius(
        &self,
        params: &SeparationParams,
    ) -> Result<SeparationInfo, SeparationError> {
        let start = Instant::now();
        positive("R_o relative tolerance", params.rel_tol)?;
        positive("scan step", params.step)?;
        positive("scan reach", params.reach)?;
        let d = self.half_thickness();
        let b = self.transform().outer();
        let r_end = b + params.reach * d;
        // scale of the midplane σ_z: P under a wide load, F·g(0)/D² ≈ 2∫|p|ρdρ/D² under a
        // narrow one in a thick slab (then the zero lies ≈ 1.55D out with slope ≈ scale/D);
        // a slope of order 1e-3·scale/length turns the σ_z tolerance into rel_tol on R_o
        let p_max = self
            .load()
            .values()
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        let scale = p_max.min(2.0 * self.transform().abs_moment() / (d * d));
        let sigma_tol = (1e-3 * params.rel_tol * scale).max(1e-15 * scale);
        let rule = Midplane::new(self, r_end, sigma_tol)?;
        let sign = self.load().total_force().signum();
        let mut evaluations = 0;
        let mut f = |r: f64| {
            evaluations += 1;
            sign * rule.eval(r).value
        };
        let f_b = f(b);
        if f_b > 0.0 {
            // the contact would end inside the load: not the situation R_o describes
            return Err(SeparationError::TensileAtLoadEdge {
                sigma_z: sign * f_b,
            });
        }
        let mut g = |x: f64| Ok::<f64, std::convert::Infallible>(f(x));
        let tol = params.rel_tol * b * 0.25;
        let Ok(root) = first_upward_root(
            &mut g,
            (b, f_b),
            params.step * d,
            r_end,
            tol,
            params.max_iterations,
        );
        let root = root.ok_or(SeparationError::NotFound { searched_to: r_end })?;
        // slope by a central difference on the σ_z scale of the bracket
        let dr = (1e-4 * d).max(1e-6 * root.x);
        let slope = (f(root.x + dr) - f(root.x - dr)) / (2.0 * dr);
        let error = root.half_width + rule.eval(root.x).error / slope.abs();
        Ok(SeparationInfo {
            r_o: root.x,
            r_o_error: error,
            converged: crate::value::meets(root.x, error, params.rel_tol),
            evaluations,
            slope,
            nodes: rule.nodes(),
            seconds: start.elapsed().as_secs_f64(),
        })
    }
}
