//! Thermal strains in one element: the equivalent nodal forces f = ∫ Bᵀ D ε_th dV and the
//! stresses σ = D (B u − ε_th), for every [`ElementKind`].
//!
//! An isotropic thermal strain ε_th = e (1, 1, 1, 0) with e = α(T)(T − T_ref) (report Appendix C;
//! axisymmetric: ε_r = ε_z = ε_θ = e, γ_rz = 0), so D ε_th = 3K e (1, 1, 1, 0) with
//! 3K = 3λ + 2μ = E/(1 − 2ν). Tension positive; units: e dimensionless, forces whole-ring.
//!
//! Where the temperature is taken:
//! - [`ElementKind::Cst4`]: as the 1970 listing, one temperature per element, the mean of its
//!   four listed nodes, and one strain e for the whole element ([`super::cst4::thermal_load`]);
//! - Q4, Q9: at every Gauss point, T interpolated from the nodes by the shape functions, so a
//!   temperature linear in (r, z) gives a thermal strain linear in (r, z);
//! - Q4 B-bar: the volume mean of the Gauss points' e, as the element's mean dilatation replaces
//!   the volumetric strain (ε_th is purely volumetric).
//!
//! Because the same quadrature forms K u and f, a displacement that makes B u = ε_th at every
//! point is the discrete solution to round-off: a free body under a uniform temperature on every
//! element, and under a temperature linear in z on Q9 (w has an r² term; Q4 and Cst4 converge
//! to it).
//!
//! # Accuracy
//!
//! `tests/fem/thermal.rs`: `free_body_at_uniform_temperature_expands_without_stress` (every
//! element, to round-off) and `free_plate_under_a_gradient_bends_to_alpha_dt_over_d_exactly_on_q9`.
//!
//! # Cost
//!
//! One element's quadrature, as its stiffness; the two-plate model with a temperature is timed
//! by example 20.
//!
//! ```
//! use boltzone::fem::element::{thermal::ElementThermal, ElementKind};
//! use boltzone::Material;
//! let x = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]];
//! let th = ElementThermal { temperature: &[10.0; 4], reference: 0.0, alpha: &|_| 1e-5 };
//! let f = ElementKind::Q4.thermal_forces(&x, &Material::unit(0.3)?, &th);
//! assert!((f[1] + f[3] + f[5] + f[7]).abs() < 1e-18); // no net axial force
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::iso::{bbar, gauss, map, mean_dilatation, Parent};
use super::{cst4, elasticity, q4, q9, ElementKind, ElementPoint, Stress};
use crate::material::Material;
use std::f64::consts::PI;

/// An element's nodal temperatures, the stress-free temperature and α(T).
#[derive(Clone, Copy)]
pub struct ElementThermal<'a> {
    /// Temperature at each node, in the element's node order.
    pub temperature: &'a [f64],
    /// The stress-free temperature T_ref.
    pub reference: f64,
    /// The expansion coefficient α(T) at a temperature T.
    pub alpha: &'a dyn Fn(f64) -> f64,
}

impl ElementThermal<'_> {
    /// Mean of the nodal temperatures (the 1970 listing's element temperature).
    pub fn mean(&self) -> f64 {
        self.temperature.iter().sum::<f64>() / self.temperature.len().max(1) as f64
    }

    /// The listing's element strain α(T̄)(T̄ − T_ref), T̄ the mean of the nodes.
    pub fn mean_strain(&self) -> f64 {
        let t = self.mean();
        (self.alpha)(t) * (t - self.reference)
    }

    /// α(T)(T − T_ref) at a point with shape-function values `n`; T − T_ref is interpolated
    /// from the nodes' differences, so that T = T_ref everywhere gives exactly zero.
    fn at_shape(&self, n: &[f64]) -> f64 {
        let (t, dt) = n
            .iter()
            .zip(self.temperature)
            .fold((0.0, 0.0), |(t, dt), (a, b)| {
                (t + a * b, dt + a * (b - self.reference))
            });
        (self.alpha)(t) * dt
    }
}

/// 3K = E/(1 − 2ν): D (1, 1, 1, 0) = 3K (1, 1, 1, 0).
fn bulk3(m: &Material) -> f64 {
    let d = elasticity(m);
    d[0][0] + 2.0 * d[0][1]
}

fn parent(kind: ElementKind) -> &'static dyn Parent {
    match kind {
        ElementKind::Q9 => &q9::Q9,
        _ => &q4::Q4,
    }
}

/// Thermal strain at each Gauss point (in [`gauss`] order); B-bar: their volume mean.
fn gauss_strains(kind: ElementKind, x: &[[f64; 2]], th: &ElementThermal) -> Vec<f64> {
    let el = parent(kind);
    let (mut e, mut ev, mut vol) = (Vec::new(), 0.0, 0.0);
    for (p, w) in gauss(el) {
        let m = map(el, x, p);
        let dv = w * 2.0 * PI * m.r * m.det;
        let ep = th.at_shape(&m.n);
        ev += ep * dv;
        vol += dv;
        e.push(ep);
    }
    if kind == ElementKind::Q4Bbar {
        e.iter_mut().for_each(|v| *v = ev / vol);
    }
    e
}

/// σ − D ε_th on the normal components.
fn less_thermal(s: Stress, k3e: f64) -> Stress {
    Stress {
        r: s.r - k3e,
        z: s.z - k3e,
        theta: s.theta - k3e,
        rz: s.rz,
    }
}

impl ElementKind {
    /// Equivalent nodal forces ∫ Bᵀ D ε_th dV of the element's thermal strain (2n, whole-ring,
    /// dofs u₀, w₀, …; Cst4 condensed as its stiffness). Add them to the load vector.
    pub fn thermal_forces(self, x: &[[f64; 2]], m: &Material, th: &ElementThermal) -> Vec<f64> {
        if self == Self::Cst4 {
            return cst4::thermal_load(x, m, th.mean_strain());
        }
        let el = parent(self);
        let k3 = bulk3(m);
        let mean = if self == Self::Q4Bbar {
            mean_dilatation(el, x)
        } else {
            Vec::new()
        };
        let mut f = vec![0.0; 2 * x.len()];
        for ((p, w), e) in gauss(el).zip(gauss_strains(self, x, th)) {
            let mut mp = map(el, x, p);
            if self == Self::Q4Bbar {
                bbar(&mut mp.b, &mean);
            }
            let s = k3 * e * w * 2.0 * PI * mp.r * mp.det;
            for (fa, b) in f.iter_mut().zip(&mp.b) {
                *fa += s * (b[0] + b[1] + b[2]);
            }
        }
        f
    }

    /// [`ElementKind::quadrature_points`] with σ = D (B u − ε_th).
    pub fn thermal_quadrature_points(
        self,
        x: &[[f64; 2]],
        m: &Material,
        u: &[f64],
        th: &ElementThermal,
    ) -> Vec<ElementPoint> {
        if self == Self::Cst4 {
            return cst4::points(x, &elasticity(m), u, th.mean_strain());
        }
        let k3 = bulk3(m);
        let mut pts = self.quadrature_points(x, m, u);
        for (p, e) in pts.iter_mut().zip(gauss_strains(self, x, th)) {
            p.stress = less_thermal(p.stress, k3 * e);
        }
        pts
    }

    /// [`ElementKind::centre_stress`] with σ = D (B u − ε_th) (T at the parent centre).
    pub fn thermal_centre_stress(
        self,
        x: &[[f64; 2]],
        m: &Material,
        u: &[f64],
        th: &ElementThermal,
    ) -> ElementPoint {
        if self == Self::Cst4 {
            return cst4::centre(x, &elasticity(m), u, th.mean_strain());
        }
        let mut p = self.centre_stress(x, m, u);
        let e = self.parent_strain(x, th, [0.0, 0.0]);
        p.stress = less_thermal(p.stress, bulk3(m) * e);
        p
    }

    /// [`ElementKind::nodal_stresses`] with σ = D (B u − ε_th) (each node's own temperature).
    pub fn thermal_nodal_stresses(
        self,
        x: &[[f64; 2]],
        m: &Material,
        u: &[f64],
        th: &ElementThermal,
    ) -> Vec<Stress> {
        if self == Self::Cst4 {
            return cst4::corner_stresses(x, &elasticity(m), u, th.mean_strain());
        }
        let k3 = bulk3(m);
        let nodes: &[[f64; 2]] = if self == Self::Q9 {
            &q9::NODES
        } else {
            &q4::CORNERS
        };
        self.nodal_stresses(x, m, u)
            .into_iter()
            .zip(nodes)
            .map(|(s, &p)| less_thermal(s, k3 * self.parent_strain(x, th, p)))
            .collect()
    }

    /// The thermal strain at parent point `p` (B-bar: the element mean).
    fn parent_strain(self, x: &[[f64; 2]], th: &ElementThermal, p: [f64; 2]) -> f64 {
        if self == Self::Q4Bbar {
            return gauss_strains(self, x, th)[0];
        }
        th.at_shape(&map(parent(self), x, p).n)
    }
}
