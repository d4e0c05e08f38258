//! The midplane of a solved single-plate mesh ([`MidplaneNodes`]: σ_z recovered from the roller
//! reactions, compression negative) and its first upward zero beyond the load, the discrete R_o
//! of one refinement level of [`super::single`] (report Ch. II.A: contact ends where the
//! midplane stress of Fernlund's substitute plate turns tensile).
//!
//! **Method.** σ_z = −t_z from the reactions ([`super::recover::line_traction`]); the crossing
//! is located inside the element edge where the nodal values change sign, by linear (Q4, Cst4)
//! or quadratic (Q9) interpolation of the nodal values, the quadratic's smaller root in the edge
//! taken in its numerically stable form.
//!
//! # Accuracy
//!
//! The interpolation is exact for a quadratic σ_z (unit test below, to 1e-14); the recovered
//! traction balances the applied force (`tests/fem/single.rs`).
//!
//! # Cost
//!
//! Linear in the midplane nodes, nothing beside the solve (`cargo bench --bench fem`).
//!
//! ```
//! use boltzone::fem::midplane_crossing::MidplaneNodes;
//! // σ_z = (r − 0.7)(r + 1) on quadratic edges: the crossing is found exactly
//! let r: Vec<f64> = (0..=10).map(|i| 0.1 * i as f64).collect();
//! let sigma_z = r.iter().map(|r| (r - 0.7) * (r + 1.0)).collect();
//! let m = MidplaneNodes { r, sigma_z, order: 2, nodes: 11, dofs: 22 };
//! assert!((m.first_tensile_crossing(0.2).unwrap() - 0.7).abs() < 1e-14);
//! ```

use super::error::FemError;
use super::recover::{line_traction, reactions};
use super::single::HalfPlate;
use crate::joint::SinglePlate;

/// The midplane of one solved single-plate mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct MidplaneNodes {
    /// Radii of the midplane nodes.
    pub r: Vec<f64>,
    /// σ_z at those nodes (compression negative).
    pub sigma_z: Vec<f64>,
    /// Edge order (1 or 2) for interpolation.
    pub order: usize,
    /// Number of nodes of the mesh.
    pub nodes: usize,
    /// Number of equations.
    pub dofs: usize,
}

/// The midplane σ_z of a solved half plate, recovered from the roller reactions.
pub fn midplane_of(_plate: &SinglePlate, h: &HalfPlate) -> Result<MidplaneNodes, FemError> {
    let kind = h.mesh.kind();
    let mid = h.mesh.bottom(0);
    let reac = reactions(&h.mesh, &h.materials, &h.u, &h.loads)?;
    let rz: Vec<f64> = mid.iter().map(|&n| reac[n][1]).collect();
    let t = line_traction(&h.mesh, &mid, &rz)?;
    Ok(MidplaneNodes {
        r: mid.iter().map(|&n| h.mesh.nodes()[n][0]).collect(),
        sigma_z: t.iter().map(|t| -t).collect(),
        order: kind.order(),
        nodes: h.mesh.n_nodes(),
        dofs: h.dofs.n_equations(),
    })
}

impl MidplaneNodes {
    /// The first radius ≥ `from` where σ_z goes from ≤ 0 to > 0, interpolated within the element
    /// edge (linear or quadratic); None if σ_z never turns tensile.
    pub fn first_tensile_crossing(&self, from: f64) -> Option<f64> {
        let o = self.order;
        let start = self
            .r
            .partition_point(|&r| r < from - 1e-12 * (1.0 + from.abs()));
        let mut i = start - start % o; // the edge that contains `from`
        if self.sigma_z.get(i).is_some_and(|&s| s > 0.0) {
            return Some(self.r[i]); // already tensile where the search starts
        }
        while i + o < self.r.len() {
            let (s0, s1) = (self.sigma_z[i], self.sigma_z[i + o]);
            let mid = self.sigma_z[i + o / 2];
            if s1 > 0.0 || mid > 0.0 {
                return Some(if o == 1 {
                    self.r[i] + (self.r[i + 1] - self.r[i]) * (-s0) / (s1 - s0)
                } else {
                    quadratic_root(self.r[i], self.r[i + 2], s0, mid, s1)
                });
            }
            i += o;
        }
        None
    }
}

/// The smallest root in [x0, x2] of the quadratic through (x0, f0), (mid, fm), (x2, f2), f0 ≤ 0.
fn quadratic_root(x0: f64, x2: f64, f0: f64, fm: f64, f2: f64) -> f64 {
    // in s ∈ [0, 1]: f = f0 + b s + a s², with f(1/2) = fm, f(1) = f2
    let a = 2.0 * (f2 - 2.0 * fm + f0);
    let b = f2 - f0 - a;
    let s = if a.abs() < 1e-14 * (f0.abs() + fm.abs() + f2.abs()) {
        -f0 / b
    } else {
        let disc = (b * b - 4.0 * a * f0).max(0.0).sqrt();
        // numerically stable roots; pick the smallest one in [0, 1]
        let q = -0.5 * (b + b.signum() * disc);
        let mut roots = [q / a, f0 / q];
        roots.sort_by(f64::total_cmp);
        roots
            .into_iter()
            .find(|s| (-1e-12..=1.0 + 1e-12).contains(s))
            .unwrap_or(0.5)
    };
    x0 + s.clamp(0.0, 1.0) * (x2 - x0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mid(r: Vec<f64>, s: Vec<f64>, order: usize) -> MidplaneNodes {
        MidplaneNodes {
            r,
            sigma_z: s,
            order,
            nodes: 0,
            dofs: 0,
        }
    }

    #[test]
    fn crossing_is_interpolated_inside_the_edge() {
        // σ = (r − 0.7)(r + 1): quadratic interpolation is exact, linear gives the chord's root
        let r: Vec<f64> = (0..=10).map(|i| i as f64 * 0.1).collect();
        let s: Vec<f64> = r.iter().map(|r| (r - 0.7) * (r + 1.0)).collect();
        let q = mid(r.clone(), s.clone(), 2)
            .first_tensile_crossing(0.2)
            .unwrap();
        assert!((q - 0.7).abs() < 1e-14, "{q}");
        let l = mid(r, s, 1).first_tensile_crossing(0.2).unwrap();
        assert!((l - 0.7).abs() < 1e-12, "{l}"); // 0.7 is a node: linear is exact there too
                                                 // a crossing below `from` is ignored; never tensile: None
        let r: Vec<f64> = (0..=4).map(|i| i as f64).collect();
        let m = mid(r.clone(), vec![1.0, -1.0, -2.0, 1.0, 2.0], 1);
        assert!((m.first_tensile_crossing(1.0).unwrap() - (2.0 + 2.0 / 3.0)).abs() < 1e-14);
        assert_eq!(mid(r, vec![-1.0; 5], 1).first_tensile_crossing(0.0), None);
    }
}
