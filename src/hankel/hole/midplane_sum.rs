//! The slab's midplane σ_z(r, 0) and the corner enrichment's midplane fields at once, on one
//! node set: what the R_o search of the single plate with a hole evaluates at every scan
//! radius and interpolation point.
//!
//! **What is computed.** σ_z(r, 0) = −∫₀^∞ ξ p̄(ξ) K(ξD) J₀(ξr) dξ for the slab (extended load,
//! [`crate::hankel::midplane`]; K the midplane kernel of [`crate::hankel::kernel::midplane`])
//! and the 4 real basis values per corner exponent of
//! [`CornerMidplaneRule::basis`](super::corner::CornerMidplaneRule::basis), all for r ≤ r_max.
//! Compression negative; the load's pressure units.
//!
//! **Method.** The corner fields' node set ([`CornerLoads::midplane_nodes`]: 20-point
//! Gauss–Legendre panels to ξ = 45/D) with panels no wider than five half-periods of
//! max(A, B) + r_max, which is the slab rule's own panel width
//! ([`crate::hankel::midplane::MidplaneRule`]: five half-periods of r_max + B, and 1.5/D);
//! the slab's weights w_i ξ_i p̄(ξ_i) K(ξ_i D) join the corner fields' as one more column, so
//! one J₀(ξ_i r) per node serves them all — half the Bessel calls of the two rules apart. The
//! slab column reaches 45/D, beyond the slab rule's truncation whenever its σ tolerance is
//! at least ~1e-17 P·(B/D)² (the search asks ≥ 1e-15 P): the slab rule's estimate bounds it.
//!
//! # Accuracy
//!
//! Against the two rules it merges (the slab's [`crate::hankel::midplane::MidplaneRule`] and
//! [`CornerLoads::midplane_rule`], built on other nodes): the slab within 1.2e-15 P, the corner
//! basis within 4.5e-14 of its largest value (rounding of sums with cancellation) on three
//! Table 1 geometries, `tests/hankel/hole_fast.rs`, `midplane_sum_matches_the_two_rules`.
//!
//! # Cost
//!
//! 600–1000 J₀ calls per radius on Table 1 (the two rules apart: twice that); the R_o search
//! evaluates it at ~10 radii (example 17).
//!
//! ```
//! use boltzone::{FaceLoad, Material};
//! use boltzone::hankel::Slab;
//! use boltzone::hankel::hole::corner::CornerLoads;
//! use boltzone::hankel::hole::midplane_sum::MidplaneSum;
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.0, 0.31, 1.0)?)?;
//! let corner = CornerLoads::new(0.1, 0.1, 0.3, 1.0, 3);
//! let sum = MidplaneSum::new(&slab, &corner, 0.71);
//! let v = sum.eval(0.4).expect("r ≤ r_max");
//! assert_eq!(v.len(), 1 + 4 * 3);
//! // the slab's σ_z near Table 1 row 1's R_o is a small fraction of P
//! assert!(v[0].abs() < 0.1 && sum.eval(0.72).is_none());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::corner::CornerLoads;
use crate::hankel::field::Slab;

/// The slab's midplane σ_z and the corner fields' basis on one node set (module docs).
#[derive(Debug, Clone)]
pub struct MidplaneSum {
    r_max: f64,
    xi: Vec<f64>,
    /// Per node: the slab's weight, then 4 per corner exponent (row-major).
    coef: Vec<f64>,
    width: usize,
}

impl MidplaneSum {
    /// The node set for radii up to `r_max` of `slab` and the enrichment `corner` (the same
    /// plate's).
    pub fn new(slab: &Slab, corner: &CornerLoads, r_max: f64) -> Self {
        let tr = slab.transform();
        let d = slab.half_thickness();
        let nodes = corner.midplane_nodes(tr.outer().max(corner.radius()) + r_max);
        let width = 1 + 4 * corner.count();
        let mut xi = Vec::with_capacity(nodes.len());
        let mut coef = Vec::with_capacity(nodes.len() * width);
        for (x, wt, parts) in nodes {
            xi.push(x);
            coef.push(-wt * tr.eval(x) * crate::hankel::kernel::midplane(x * d));
            for (p, q) in parts {
                coef.extend([p.re, p.im, q.re, q.im]);
            }
        }
        Self {
            r_max,
            xi,
            coef,
            width,
        }
    }

    /// [σ_z(r, 0) of the slab, the corner basis…] at r, or None beyond r_max.
    pub fn eval(&self, r: f64) -> Option<Vec<f64>> {
        if r > self.r_max {
            return None;
        }
        let mut out = vec![0.0; self.width];
        for (x, row) in self.xi.iter().zip(self.coef.chunks_exact(self.width)) {
            let j = libm::j0(x * r);
            for (o, c) in out.iter_mut().zip(row) {
                *o += j * c;
            }
        }
        Some(out)
    }

    /// The largest radius served.
    pub fn r_max(&self) -> f64 {
        self.r_max
    }

    /// ξ-nodes.
    pub fn nodes(&self) -> usize {
        self.xi.len()
    }
}
