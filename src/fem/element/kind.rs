//! The element families ([`ElementKind`]) and what each computes: stiffness (report eq. A.10),
//! quadrature-point, centre and nodal stresses, dispatched to the kinds' modules. Equations,
//! sign convention and units as in the [folder's docs](super).
//!
//! # Accuracy
//!
//! `tests/fem/elements.rs` (symmetry, one rigid-body mode, patch tests to round-off for every
//! kind) and `tests/fem/lame.rs` (convergence orders on the Lamé cylinder).
//!
//! # Cost
//!
//! Per element, 4–9 quadrature points; assembly in `cargo bench --bench fem`.
//!
//! ```
//! use boltzone::fem::element::ElementKind;
//! assert_eq!((ElementKind::Q9.nodes(), ElementKind::Q9.order()), (9, 2));
//! ```

use super::{cst4, elasticity, iso, q4, q9, ElementPoint, Stress};
use crate::material::Material;
use serde::{Deserialize, Serialize};

/// The element families.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum ElementKind {
    /// The report's quadrilateral: four constant-strain triangles, centre node condensed.
    Cst4,
    /// Bilinear quadrilateral, 2×2 Gauss (locks when ν → 1/2).
    Q4,
    /// Bilinear quadrilateral with the B-bar mean-dilatation volumetric strain (does not lock).
    Q4Bbar,
    /// Biquadratic 9-node Lagrange quadrilateral, 3×3 Gauss.
    Q9,
}

impl ElementKind {
    /// Nodes per element (the condensed centre of [`ElementKind::Cst4`] is not a mesh node).
    pub fn nodes(self) -> usize {
        match self {
            Self::Cst4 | Self::Q4 | Self::Q4Bbar => 4,
            Self::Q9 => 9,
        }
    }

    /// Polynomial order of the element edges (1 linear, 2 quadratic).
    pub fn order(self) -> usize {
        match self {
            Self::Q9 => 2,
            _ => 1,
        }
    }

    /// Element stiffness (2n × 2n, row-major, dofs ordered u₀, w₀, u₁, w₁, …) for node
    /// coordinates `x` (counterclockwise in (r, z); Q9: corners, mid-sides bottom, right, top,
    /// left, centre).
    pub fn stiffness(self, x: &[[f64; 2]], m: &Material) -> Vec<f64> {
        let d = elasticity(m);
        match self {
            Self::Cst4 => cst4::stiffness(x, &d),
            Self::Q4 => iso::stiffness(&q4::Q4, x, &d, false),
            Self::Q4Bbar => iso::stiffness(&q4::Q4, x, &d, true),
            Self::Q9 => iso::stiffness(&q9::Q9, x, &d, false),
        }
    }

    /// Displacement and stress at the quadrature points (Gauss points; for Cst4 the centroids of
    /// the four triangles), with their volume weights: ∑ weight·f ≈ ∫ f dV.
    pub fn quadrature_points(self, x: &[[f64; 2]], m: &Material, u: &[f64]) -> Vec<ElementPoint> {
        let d = elasticity(m);
        match self {
            Self::Cst4 => cst4::points(x, &d, u, 0.0),
            Self::Q4 => iso::gauss_points(&q4::Q4, x, &d, u, false),
            Self::Q4Bbar => iso::gauss_points(&q4::Q4, x, &d, u, true),
            Self::Q9 => iso::gauss_points(&q9::Q9, x, &d, u, false),
        }
    }

    /// Stress at the element centre (parent point (0, 0); for Cst4 the area-weighted mean of the
    /// four triangles, the report's printed "stresses at the center of each element").
    pub fn centre_stress(self, x: &[[f64; 2]], m: &Material, u: &[f64]) -> ElementPoint {
        let d = elasticity(m);
        match self {
            Self::Cst4 => cst4::centre(x, &d, u, 0.0),
            Self::Q4 => iso::at_parent(&q4::Q4, x, &d, u, [0.0, 0.0], false),
            Self::Q4Bbar => iso::at_parent(&q4::Q4, x, &d, u, [0.0, 0.0], true),
            Self::Q9 => iso::at_parent(&q9::Q9, x, &d, u, [0.0, 0.0], false),
        }
    }

    /// Stress evaluated at each node of the element (for nodal averaging). Cst4 gives each corner
    /// the stress of the two triangles that touch it, averaged.
    pub fn nodal_stresses(self, x: &[[f64; 2]], m: &Material, u: &[f64]) -> Vec<Stress> {
        let d = elasticity(m);
        match self {
            Self::Cst4 => cst4::corner_stresses(x, &d, u, 0.0),
            Self::Q4 | Self::Q4Bbar => q4::CORNERS
                .iter()
                .map(|&p| iso::at_parent(&q4::Q4, x, &d, u, p, self == Self::Q4Bbar).stress)
                .collect(),
            Self::Q9 => q9::NODES
                .iter()
                .map(|&p| iso::at_parent(&q9::Q9, x, &d, u, p, false).stress)
                .collect(),
        }
    }
}
