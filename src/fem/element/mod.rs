//! Axisymmetric solid elements in the (r, z) half-plane.
//!
//! Displacement (u, w) = (u_r, u_z); strains ε = (ε_r, ε_z, ε_θ, γ_rz) with
//! ε_r = ∂u/∂r, ε_z = ∂w/∂z, ε_θ = u/r, γ_rz = ∂u/∂z + ∂w/∂r (the hoop strain u/r is what makes the
//! problem axisymmetric). Stresses σ = (σ_r, σ_z, σ_θ, τ_rz) = D ε with the isotropic
//! D = [[λ+2μ, λ, λ, 0], [λ, λ+2μ, λ, 0], [λ, λ, λ+2μ, 0], [0, 0, 0, μ]] (report eqs. 2.3, A.5).
//! The stiffness k = ∫ Bᵀ D B dV with dV = 2πr dr dz (A.10): forces are whole-ring forces (the
//! 1970 program used one radian; divide by 2π to compare).
//!
//! Element kinds ([`ElementKind`]), one module each:
//! - [`cst4`]: the report's quadrilateral, four constant-strain triangles around a condensed
//!   centre node (Appendix A, eq. A.21);
//! - [`q4`]: the bilinear isoparametric quadrilateral, 2×2 Gauss, and its B-bar (mean
//!   dilatation) variant for nearly incompressible materials;
//! - [`q9`]: the biquadratic Lagrange quadrilateral, 3×3 Gauss.
//!
//! Quadrature points never lie on the axis r = 0, so u/r is always evaluated where r > 0. Nodes
//! may lie on the axis: there the hoop strain is taken as its limit ∂u/∂r (u = 0 on the axis).
//!
//! Sign convention: tension positive, compression negative.
//!
//! **Accuracy.** Symmetric stiffness with exactly one rigid-body mode and the patch tests
//! (displacement- and traction-driven, skew rollers) to round-off for every kind
//! (`tests/fem/elements.rs`); convergence orders on the Lamé cylinder (`tests/fem/lame.rs`).
//! **Cost.** Per element, 4–9 quadrature points; assembly in `cargo bench --bench fem`.
//!
//! ```
//! use boltzone::fem::element::ElementKind;
//! use boltzone::Material;
//! let x = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]];
//! let k = ElementKind::Q4.stiffness(&x, &Material::unit(0.3)?);
//! assert!((k[1] - k[8]).abs() < 1e-15 * k[0].abs()); // symmetric
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod cst4;
mod iso;
pub mod q4;
pub mod q9;
pub mod thermal;

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

/// Stresses (σ_r, σ_z, σ_θ, τ_rz), tension positive.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Stress {
    /// Radial normal stress σ_r.
    pub r: f64,
    /// Axial normal stress σ_z.
    pub z: f64,
    /// Hoop stress σ_θ.
    pub theta: f64,
    /// Shear stress τ_rz.
    pub rz: f64,
}

impl Stress {
    fn from_array(s: [f64; 4]) -> Self {
        Self {
            r: s[0],
            z: s[1],
            theta: s[2],
            rz: s[3],
        }
    }

    /// The components as (σ_r, σ_z, σ_θ, τ_rz).
    pub fn to_array(self) -> [f64; 4] {
        [self.r, self.z, self.theta, self.rz]
    }
}

/// A point of an element with its volume weight (2πr·det J·w) and what lives there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ElementPoint {
    /// Radius.
    pub r: f64,
    /// Axial coordinate.
    pub z: f64,
    /// Volume weight of the point in ∫ · dV (zero where only a value is reported).
    pub weight: f64,
    /// Displacement (u_r, u_z) at the point.
    pub displacement: [f64; 2],
    /// Stress at the point.
    pub stress: Stress,
}

/// The isotropic elasticity matrix D for (ε_r, ε_z, ε_θ, γ_rz).
pub fn elasticity(m: &Material) -> [[f64; 4]; 4] {
    let (l, mu) = m.lame();
    let c = l + 2.0 * mu;
    [
        [c, l, l, 0.0],
        [l, c, l, 0.0],
        [l, l, c, 0.0],
        [0.0, 0.0, 0.0, mu],
    ]
}

/// σ = D ε.
pub(crate) fn apply_d(d: &[[f64; 4]; 4], e: &[f64; 4]) -> [f64; 4] {
    let mut s = [0.0; 4];
    for (i, si) in s.iter_mut().enumerate() {
        *si = (0..4).map(|j| d[i][j] * e[j]).sum();
    }
    s
}

/// Adds w·Bᵀ D B to the upper triangle (i ≤ j) of the (nd × nd, row-major) matrix `k`, B given
/// by columns (4 strains per dof); call [`mirror_upper`] once after the last point.
pub(crate) fn add_btdb(k: &mut [f64], b: &[[f64; 4]], d: &[[f64; 4]; 4], w: f64) {
    let nd = b.len();
    for j in 0..nd {
        let db = apply_d(d, &b[j]);
        for i in 0..=j {
            let bi = &b[i];
            k[i * nd + j] += w * (bi[0] * db[0] + bi[1] * db[1] + bi[2] * db[2] + bi[3] * db[3]);
        }
    }
}

/// Copies the upper triangle of the (nd × nd, row-major) `k` into the lower one.
pub(crate) fn mirror_upper(k: &mut [f64], nd: usize) {
    for i in 0..nd {
        for j in 0..i {
            k[i * nd + j] = k[j * nd + i];
        }
    }
}

/// Strain B·u from columns of B.
pub(crate) fn strain(b: &[[f64; 4]], u: &[f64]) -> [f64; 4] {
    let mut e = [0.0; 4];
    for (bj, uj) in b.iter().zip(u) {
        for c in 0..4 {
            e[c] += bj[c] * uj;
        }
    }
    e
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

/// Gauss–Legendre abscissae and weights on [−1, 1].
pub(crate) const GAUSS2: [(f64, f64); 2] = [
    (-0.577_350_269_189_625_8, 1.0),
    (0.577_350_269_189_625_8, 1.0),
];
/// Three-point Gauss–Legendre rule (exact to degree 5).
pub(crate) const GAUSS3: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];
