//! The Lamé thick-walled cylinder, a closed-form check of the axisymmetric elements.
//!
//! A long cylinder a ≤ r ≤ b under internal pressure p in plane strain (ε_z = 0, rollers on both
//! end faces): u = C₁ r + C₂ / r with
//! C₂ = p / (2μ (1/a² − 1/b²)), C₁ = μ C₂ / ((λ + μ) b²), so that
//! σ_r = 2(λ + μ) C₁ − 2μ C₂ / r² equals −p at r = a and 0 at r = b (compression negative).
//! [`lame_error`] meshes a slice of the wall with `n` elements through the thickness and returns
//! the relative L2 error of the displacement, ‖u_h − u‖ / ‖u‖ with ‖v‖² = ∫ |v|² 2πr dV,
//! evaluated at the elements' quadrature points.
//!
//! # Accuracy
//!
//! The observed orders are 2 (Cst4, Q4, Q4 B-bar) and 3 (Q9) at ν = 0.3, and B-bar and Q9 do not
//! lock at ν = 0.499 (`tests/fem/lame.rs`, example 02).
//!
//! # Cost
//!
//! One assembly and factorization per mesh (example 02 to 64 elements).
//!
//! ```
//! use boltzone::fem::lame::{lame_error, LameCase};
//! use boltzone::fem::ElementKind;
//! let case = LameCase { a: 1.0, b: 2.0, nu: 0.3 };
//! let e4 = lame_error(&case, ElementKind::Q9, 4)?;
//! let e8 = lame_error(&case, ElementKind::Q9, 8)?;
//! assert!(e8 < e4 / 6.0); // third order: 8 × per halving
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::assemble::{assemble, Pattern};
use super::dofs::{DofMap, Supports};
use super::element::ElementKind;
use super::error::FemError;
use super::loads::Loads;
use super::mesh::{Mesh, PlateSpec};
use super::recover::gauss_stresses;
use super::solve::{Factorization, SolveParams};
use super::spacing::Spacing;
use crate::material::Material;

/// A Lamé cylinder: radii a < b, Poisson's ratio ν (E = 1, p = 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LameCase {
    /// Inner radius.
    pub a: f64,
    /// Outer radius.
    pub b: f64,
    /// Poisson's ratio.
    pub nu: f64,
}

impl LameCase {
    /// Exact radial displacement u(r) for E = 1, p = 1.
    pub fn u(&self, r: f64) -> f64 {
        let (l, mu) = Material::unit(self.nu).expect("valid ν").lame();
        let c2 = 1.0 / (2.0 * mu * (1.0 / (self.a * self.a) - 1.0 / (self.b * self.b)));
        let c1 = mu * c2 / ((l + mu) * self.b * self.b);
        c1 * r + c2 / r
    }
}

/// Relative L2 displacement error of `kind` with `n` elements through the wall (and one element
/// of height (b − a)/n along z).
pub fn lame_error(case: &LameCase, kind: ElementKind, n: usize) -> Result<f64, FemError> {
    let mat = [Material::unit(case.nu)?];
    let r = Spacing::uniform(case.a, case.b, n)?;
    let z = Spacing::uniform(0.0, (case.b - case.a) / n as f64, 1)?;
    let mesh = Mesh::structured(kind, &r, &[PlateSpec { z, material: 0 }])?;
    let mut s = Supports::new(mesh.n_nodes());
    for n in [mesh.bottom(0), mesh.top(0)].concat() {
        s.roller_z(n);
    }
    let mut loads = Loads::new(mesh.n_nodes());
    loads.add_side_pressure(&mesh, &mesh.inner(0), -1.0, 1.0)?;
    let dofs = DofMap::new(&s);
    let k = assemble(&mesh, &mat, &dofs, &Pattern::new(&mesh, &dofs))?;
    let x =
        Factorization::new(&k.matrix, &SolveParams::default())?.solve(&dofs.gather(loads.forces()));
    let u = dofs.expand(&x);
    let (mut num, mut den) = (0.0, 0.0);
    for p in gauss_stresses(&mesh, &mat, &u)? {
        let ue = case.u(p.r);
        num += p.weight * ((p.displacement[0] - ue).powi(2) + p.displacement[1].powi(2));
        den += p.weight * ue * ue;
    }
    Ok((num / den).sqrt())
}
