//! Axisymmetric face loads p(r) on an annulus A ≤ r ≤ B: the bolt head's or nut's bearing pressure.
//!
//! Sign convention: p > 0 presses on the face (compression), so the face traction is σ_z = −p.
//! Every profile is stored as a piecewise-linear function on knots A = r₀ < r₁ < … < rₙ = B and is
//! zero outside [A, B] (jumps at A and B are allowed). The profiles of the report are:
//!
//! - uniform: p(r) = P on [A, B] (Figs. 12–17, Table 1);
//! - triangular with the peak at A or at B and the same total force as the uniform load of mean
//!   pressure P (Figs. 19–20): peak at A, p(r) = p̂ (B − r)/(B − A) with p̂ = 3P(A + B)/(B + 2A);
//!   peak at B, p(r) = p̂ (r − A)/(B − A) with p̂ = 3P(A + B)/(2B + A);
//! - tabulated: pressures at given radii, linear in between.
//!
//! The total force is F = 2π ∫ p(r) r dr; the mean pressure is F / (π(B² − A²)).
//!
//! # Accuracy
//!
//! Exact: totals and moments are closed-form integrals of the piecewise-linear profile, checked
//! by the FE loads' total force (`fem::loads`' example) and `tests/hankel/slab.rs`
//! (`total_force_is_carried_by_the_midplane`).
//!
//! # Cost
//!
//! Linear in the knots.
//!
//! ```
//! use boltzone::{FaceLoad, Peak};
//! let u = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let t = FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA)?;
//! assert!((u.total_force() - t.total_force()).abs() < 1e-14);
//! assert_eq!(t.pressure_at(0.31), 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{finite, non_negative, InputError};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Where a triangular load has its peak.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Peak {
    /// Peak at the inner radius A (the hole edge), zero at B (report Fig. 20(a)).
    AtA,
    /// Peak at the outer radius B, zero at A (report Fig. 20(b)).
    AtB,
}

/// The shape a load was built from; solvers use it to pick closed forms.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Profile {
    /// Constant pressure P on [A, B].
    Uniform,
    /// Linear, zero at one end, same total force as the uniform load of the same mean pressure.
    Triangular(Peak),
    /// Piecewise linear through given points.
    Tabulated,
}

/// One linear piece of a load: p goes from `p0` at `r0` to `p1` at `r1`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    /// Inner radius of the piece.
    pub r0: f64,
    /// Outer radius of the piece.
    pub r1: f64,
    /// Pressure at `r0`.
    pub p0: f64,
    /// Pressure at `r1`.
    pub p1: f64,
}

impl Segment {
    /// Pressure at `r` by linear interpolation (no range check).
    pub fn at(&self, r: f64) -> f64 {
        let t = (r - self.r0) / (self.r1 - self.r0);
        self.p0 + t * (self.p1 - self.p0)
    }

    /// ∫ p(r) r dr over the piece (exact for the linear p).
    pub fn moment(&self) -> f64 {
        let (a, b) = (self.r0, self.r1);
        // p = p0 + s (r − a), s = (p1 − p0)/(b − a): ∫ p r dr = p0 (b² − a²)/2 + s (b − a)²(2b + a)/6.
        let s = (self.p1 - self.p0) / (b - a);
        self.p0 * (b * b - a * a) / 2.0 + s * (b - a) * (b - a) * (2.0 * b + a) / 6.0
    }
}

/// An axisymmetric face pressure on A ≤ r ≤ B.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FaceLoad {
    profile: Profile,
    knots: Vec<f64>,
    values: Vec<f64>,
}

impl FaceLoad {
    /// Uniform pressure `p` on `a ≤ r ≤ b` (`a` may be 0: a disk load).
    pub fn uniform(a: f64, b: f64, p: f64) -> Result<Self, InputError> {
        check_radii(a, b)?;
        finite("pressure P", p)?;
        Ok(Self {
            profile: Profile::Uniform,
            knots: vec![a, b],
            values: vec![p, p],
        })
    }

    /// Triangular pressure on `a ≤ r ≤ b` with its peak at `peak` and the same total force as a
    /// uniform pressure `mean_p` (report Figs. 19–20).
    pub fn triangular(a: f64, b: f64, mean_p: f64, peak: Peak) -> Result<Self, InputError> {
        check_radii(a, b)?;
        finite("pressure P", mean_p)?;
        let values = match peak {
            Peak::AtA => vec![3.0 * mean_p * (a + b) / (b + 2.0 * a), 0.0],
            Peak::AtB => vec![0.0, 3.0 * mean_p * (a + b) / (2.0 * b + a)],
        };
        Ok(Self {
            profile: Profile::Triangular(peak),
            knots: vec![a, b],
            values,
        })
    }

    /// A piecewise-linear pressure through `(radii[i], pressures[i])`, zero outside
    /// `[radii[0], radii[n−1]]`. Radii must be non-negative and strictly increasing; at least two
    /// points; the total force must not vanish.
    pub fn tabulated(radii: &[f64], pressures: &[f64]) -> Result<Self, InputError> {
        if radii.len() != pressures.len() {
            return Err(InputError::Table {
                reason: format!("{} radii but {} pressures", radii.len(), pressures.len()),
            });
        }
        if radii.len() < 2 {
            return Err(InputError::Table {
                reason: format!("needs at least 2 points, got {}", radii.len()),
            });
        }
        for (i, (&r, &p)) in radii.iter().zip(pressures).enumerate() {
            if !r.is_finite() || r < 0.0 {
                return Err(InputError::Table {
                    reason: format!("radius[{i}] = {r} must be finite and not negative"),
                });
            }
            if !p.is_finite() {
                return Err(InputError::Table {
                    reason: format!("pressure[{i}] = {p} is not a finite number"),
                });
            }
            if i > 0 && r <= radii[i - 1] {
                return Err(InputError::Table {
                    reason: format!(
                        "radius[{i}] = {r} does not exceed radius[{}] = {}",
                        i - 1,
                        radii[i - 1]
                    ),
                });
            }
        }
        let load = Self {
            profile: Profile::Tabulated,
            knots: radii.to_vec(),
            values: pressures.to_vec(),
        };
        if load.total_force() == 0.0 {
            return Err(InputError::Table {
                reason: "the total force is zero".into(),
            });
        }
        Ok(load)
    }

    /// The profile this load was built from.
    pub fn profile(&self) -> Profile {
        self.profile
    }

    /// Inner radius of the loaded annulus (A for a load at the hole edge).
    pub fn inner(&self) -> f64 {
        self.knots[0]
    }

    /// Outer radius of the loaded annulus, B.
    pub fn outer(&self) -> f64 {
        *self.knots.last().expect("at least two knots")
    }

    /// Knot radii of the piecewise-linear representation.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// Pressures at the knots.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The linear pieces, from A outward.
    pub fn segments(&self) -> impl Iterator<Item = Segment> + '_ {
        self.knots
            .windows(2)
            .zip(self.values.windows(2))
            .map(|(r, p)| Segment {
                r0: r[0],
                r1: r[1],
                p0: p[0],
                p1: p[1],
            })
    }

    /// p(r); zero outside [A, B]. At a knot the piece to the right is used, at B the value at B.
    pub fn pressure_at(&self, r: f64) -> f64 {
        if r < self.inner() || r > self.outer() || r.is_nan() {
            return 0.0;
        }
        let i = self
            .knots
            .partition_point(|&k| k <= r)
            .min(self.knots.len() - 1);
        let i = i.max(1);
        Segment {
            r0: self.knots[i - 1],
            r1: self.knots[i],
            p0: self.values[i - 1],
            p1: self.values[i],
        }
        .at(r)
    }

    /// Total force F = 2π ∫ p(r) r dr (one face).
    pub fn total_force(&self) -> f64 {
        2.0 * PI * self.segments().map(|s| s.moment()).sum::<f64>()
    }

    /// Mean pressure F / (π(B² − A²)): equals P for the uniform and triangular loads.
    pub fn mean_pressure(&self) -> f64 {
        let (a, b) = (self.inner(), self.outer());
        self.total_force() / (PI * (b * b - a * a))
    }

    /// The same load in units where `length` and `pressure` are 1: every radius divided by
    /// `length`, every pressure by `pressure` (both finite and positive). Division, not
    /// multiplication by a reciprocal, so that each number is its ratio correctly rounded: a
    /// joint written in other units (whose ratios are the same) scales to the same bits.
    pub fn nondimensional(&self, length: f64, pressure: f64) -> Result<Self, InputError> {
        crate::error::positive("load length scale", length)?;
        crate::error::positive("load pressure scale", pressure)?;
        Ok(Self {
            profile: self.profile,
            knots: self.knots.iter().map(|r| r / length).collect(),
            values: self.values.iter().map(|v| v / pressure).collect(),
        })
    }

    /// The same load with every pressure multiplied by `factor`.
    pub fn scaled(&self, factor: f64) -> Result<Self, InputError> {
        finite("load scale factor", factor)?;
        Ok(Self {
            profile: self.profile,
            knots: self.knots.clone(),
            values: self.values.iter().map(|v| v * factor).collect(),
        })
    }
}

fn check_radii(a: f64, b: f64) -> Result<(), InputError> {
    non_negative("load inner radius A", a)?;
    finite("load outer radius B", b)?;
    if b <= a {
        return Err(InputError::LoadRadii { a, b });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∫ p r dr by a fine midpoint rule: an independent check of the closed-form moments.
    fn midpoint_force(load: &FaceLoad) -> f64 {
        let (a, b) = (load.inner(), load.outer());
        let n = 200_000;
        let h = (b - a) / n as f64;
        2.0 * PI
            * (0..n)
                .map(|i| {
                    let r = a + (i as f64 + 0.5) * h;
                    load.pressure_at(r) * r * h
                })
                .sum::<f64>()
    }

    #[test]
    fn triangular_loads_carry_the_uniform_force() {
        for (a, b) in [(0.1, 0.31), (0.0, 1.0), (0.1285, 0.211)] {
            let u = FaceLoad::uniform(a, b, 2.0).unwrap();
            let f = PI * (b * b - a * a) * 2.0;
            assert!((u.total_force() - f).abs() < 1e-14 * f);
            for peak in [Peak::AtA, Peak::AtB] {
                let t = FaceLoad::triangular(a, b, 2.0, peak).unwrap();
                assert!((t.total_force() - f).abs() < 1e-13 * f);
                // midpoint rule error is O(h²) ~ 1e-11 relative here
                assert!((midpoint_force(&t) - f).abs() < 1e-9 * f);
                assert!((t.mean_pressure() - 2.0).abs() < 1e-13);
            }
        }
    }

    #[test]
    fn tabulated_load_interpolates_and_validates() {
        let t = FaceLoad::tabulated(&[0.1, 0.2, 0.3], &[3.0, 1.0, 0.0]).unwrap();
        assert_eq!(t.pressure_at(0.15), 2.0);
        assert_eq!(t.pressure_at(0.05), 0.0);
        assert_eq!(t.pressure_at(0.3), 0.0);
        assert!((midpoint_force(&t) - t.total_force()).abs() < 1e-9 * t.total_force());
        assert!(FaceLoad::tabulated(&[0.1, 0.1], &[1.0, 1.0]).is_err());
        assert!(FaceLoad::tabulated(&[0.1], &[1.0]).is_err());
        assert!(FaceLoad::tabulated(&[0.1, 0.2], &[1.0]).is_err());
        assert!(FaceLoad::tabulated(&[0.1, 0.2], &[1.0, f64::NAN]).is_err());
        assert!(FaceLoad::tabulated(&[0.1, 0.2], &[0.0, 0.0]).is_err());
    }

    #[test]
    fn bad_radii_are_named() {
        let e = FaceLoad::uniform(0.3, 0.3, 1.0).unwrap_err();
        assert_eq!(e, InputError::LoadRadii { a: 0.3, b: 0.3 });
        let e = FaceLoad::uniform(f64::NAN, 0.3, 1.0).unwrap_err();
        assert!(e.to_string().contains("load inner radius A"));
        let e = FaceLoad::uniform(0.1, 0.3, f64::INFINITY).unwrap_err();
        assert!(e.to_string().contains("pressure P"));
    }
}
