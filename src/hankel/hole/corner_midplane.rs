//! The corner enrichment fields' midplane stress σ_z(r, 0) ([`super::corner`]: the slab loaded
//! inside the hole by the Williams-exponent pressure and shear), as the real basis values the
//! hole route's separation search and the two-plate route's midplane sums use: one node set in ξ
//! per largest radius ([`CornerMidplaneRule`]), on which one J₀(ξr) per node serves every
//! exponent's four values at a radius.
//!
//! **Method.** σ_z(r, 0) = ∫₀^∞ [−ξ q̄(ξ) K(ξD) or ξ s̄(ξ) L_z(ξD, 0)] J₀(ξr) dξ with the
//! midplane kernels of [`crate::hankel::kernel`] and [`crate::hankel::kernel_shear`]: 20-point
//! Gauss–Legendre panels of at most five half-periods of r_max + A and 1.5/D, to ξ = 45/D where
//! the kernels, ≤ 2.5(1 + t)e^(−t), are below 1e-17 of the load's size.
//!
//! # Accuracy
//!
//! `tests/hankel/hole_corner.rs` (the fields against brute-force quadrature) and, through the
//! hole route's R_o, `tests/hankel/hole_fast.rs`.
//!
//! # Cost
//!
//! One rule per hole and largest radius, then a dot product per radius (`cargo bench --bench
//! hole`, example 14).
//!
//! ```
//! use boltzone::hankel::hole::corner::CornerLoads;
//! let loads = CornerLoads::new(0.1, 0.1, 0.3, 1.0, 1);
//! let rule = loads.midplane_rule(0.5);
//! loads.midplane_basis(0.3, 0.5); // keeps the rule for r_max = 0.5
//! let direct = loads.midplane_basis(0.3, 0.9); // another r_max: the direct integral
//! // the rule and the direct integral give the same basis values inside r_max
//! let scale = direct.iter().fold(0.0f64, |m, x| m.max(x.abs()));
//! let on_rule = rule.basis(0.3).unwrap();
//! assert!(on_rule.iter().zip(&direct).all(|(x, y)| (x - y).abs() <= 1e-11 * scale));
//! assert!(rule.basis(0.6).is_none()); // beyond r_max
//! ```

use super::corner::{CornerLoads, FieldComponent};
use crate::hankel::kernel_shear::ShearKernels;
use crate::numerics::quadrature::gauss_legendre;
use num_complex::Complex64;
use std::f64::consts::PI;

impl CornerLoads {
    /// The enrichment fields' midplane σ_z(r, 0) as real basis values (see
    /// [`CornerMidplaneRule::basis`]): radii up to `r_max` on the node set of the first
    /// `r_max` asked for (built then, kept), beyond or for another `r_max` the direct integral.
    pub fn midplane_basis(&self, r: f64, r_max: f64) -> Vec<f64> {
        let rule = self
            .midplane_nodes
            .get_or_init(|| self.midplane_rule(r_max));
        match rule.basis(r) {
            Some(b) if rule.r_max == r_max => b,
            _ => self.fields(r, &[0.0], &[FieldComponent::SigmaZ])[0]
                .iter()
                .flat_map(|f| [f[0][0].re, f[0][0].im, f[0][1].re, f[0][1].im])
                .collect(),
        }
    }

    /// [`Self::midplane_basis`] at many radii r_i ≤ `r_max` at once, `count` of them:
    /// `j0_row(ξ, row)` fills row_i = J₀(ξ r_i) (a tabulation of the caller's, faster than one
    /// Bessel call per entry). Row i holds the basis at r_i.
    pub fn midplane_basis_rows(
        &self,
        r_max: f64,
        count: usize,
        j0_row: impl FnMut(f64, &mut [f64]),
    ) -> Vec<Vec<f64>> {
        let rule = self
            .midplane_nodes
            .get_or_init(|| self.midplane_rule(r_max));
        if rule.r_max != r_max {
            return Vec::new();
        }
        rule.basis_rows(count, j0_row)
    }

    /// The midplane rule for radii up to r_max: nodes ξ_i and, per exponent, the weighted
    /// (−w_i ξ_i q̄ K(ξ_i D), w_i ξ_i s̄ L_z(ξ_i D, 0)) (panels of at most five half-periods of
    /// (r_max + A) and 1.5/D, 20 points each, to ξ = 45/D where K, L_z ≤ 2.5(1 + t)e^(−t) are
    /// below 1e-17 of the load's size). A smaller r_max has fewer nodes.
    pub fn midplane_rule(&self, r_max: f64) -> CornerMidplaneRule {
        let nodes = self
            .midplane_nodes(self.a + r_max)
            .into_iter()
            .map(|(xi, _, parts)| (xi, parts))
            .collect();
        CornerMidplaneRule { r_max, nodes }
    }

    /// The nodes of [`Self::midplane_rule`] with panels of at most five half-periods of the
    /// frequency `span` (and 1.5/D): (ξ_i, w_i ξ_i, the weighted parts of every exponent).
    #[allow(clippy::type_complexity)]
    pub fn midplane_nodes(&self, span: f64) -> Vec<(f64, f64, Vec<(Complex64, Complex64)>)> {
        let d = self.d;
        let x_end = 45.0 / d;
        let h = (5.0 * PI / span).min(1.5 / d);
        let panels = (x_end / h).ceil() as usize;
        let rule = gauss_legendre(20);
        let mut nodes = Vec::with_capacity(panels * rule.len());
        for p in 0..panels {
            let c0 = (p as f64 + 0.5) * h;
            for &(x, w) in rule.iter() {
                let xi = c0 + 0.5 * h * x;
                let t = xi * d;
                let wt = 0.5 * h * w * xi;
                let (kp, ks) = (
                    crate::hankel::kernel::midplane(t),
                    ShearKernels::midplane(t),
                );
                let parts = self
                    .transforms_all(xi)
                    .into_iter()
                    .map(|(qn, qs)| (-wt * kp * qn, wt * ks * qs))
                    .collect();
                nodes.push((xi, wt, parts));
            }
        }
        nodes
    }
}

/// The corner enrichment fields' midplane σ_z(r, 0) for radii up to r_max on one node set
/// ([`CornerLoads::midplane_rule`]): one J₀ per node serves all 4·count values at a radius.
#[derive(Debug, Clone)]
pub struct CornerMidplaneRule {
    r_max: f64,
    #[allow(clippy::type_complexity)]
    nodes: Vec<(f64, Vec<(Complex64, Complex64)>)>,
}

impl CornerMidplaneRule {
    /// The largest radius served.
    pub fn r_max(&self) -> f64 {
        self.r_max
    }

    /// [`Self::basis`] at `count` radii whose J₀(ξ r_i) `j0_row(ξ, row)` fills.
    pub fn basis_rows(
        &self,
        count: usize,
        mut j0_row: impl FnMut(f64, &mut [f64]),
    ) -> Vec<Vec<f64>> {
        let zero = Complex64::new(0.0, 0.0);
        let terms = self.nodes.first().map_or(0, |n| n.1.len());
        let mut sums = vec![vec![(zero, zero); terms]; count];
        let mut row = vec![0.0; count];
        for (xi, parts) in &self.nodes {
            j0_row(*xi, &mut row);
            for (sum, &j) in sums.iter_mut().zip(&row) {
                for (s, (p, q)) in sum.iter_mut().zip(parts) {
                    s.0 += j * p;
                    s.1 += j * q;
                }
            }
        }
        sums.iter()
            .map(|sum| {
                sum.iter()
                    .flat_map(|(p, q)| [p.re, p.im, q.re, q.im])
                    .collect()
            })
            .collect()
    }

    /// For exponent k, [Re, Im] of the pressure field's σ_z(r, 0), then [Re, Im] of the shear
    /// field's (so that amplitudes c = (x₀ − ix₁, x₂ − ix₃) give Σ_j x_j·basis_j =
    /// Re(c_p F_p + c_s F_s), the fit's convention); None beyond r_max.
    pub fn basis(&self, r: f64) -> Option<Vec<f64>> {
        if r > self.r_max {
            return None;
        }
        let zero = Complex64::new(0.0, 0.0);
        let count = self.nodes.first().map_or(0, |n| n.1.len());
        let mut sums = vec![(zero, zero); count];
        for (xi, parts) in &self.nodes {
            let j = libm::j0(xi * r);
            for (s, (p, q)) in sums.iter_mut().zip(parts) {
                s.0 += j * p;
                s.1 += j * q;
            }
        }
        Some(
            sums.iter()
                .flat_map(|(p, q)| [p.re, p.im, q.re, q.im])
                .collect(),
        )
    }
}
