//! The endpoint expansion of the crack load's transform in the holed two-plate route (module
//! `crack`): for ξ beyond ξ_l, where the panels of l would have to resolve J₀(ξs),
//!
//! ∫_c^∞ l(s) J₀(ξs) s ds = −l(c)cJ₁(ξc)/ξ − l′(c)cJ₀(ξc)/ξ² + (l′ + c l″)(c)J₁(ξc)/ξ³ + O(ξ^(−4.5)),
//!
//! by parts (l smooth and decaying beyond c; lengths in the units of D, l in those of the load).
//! l′ and l″ at c are one-sided differences of the panel interpolant of l.
//!
//! # Accuracy
//!
//! The three-term error falls at rate ≈ 6 in ξ_l (`tests/hankel/two_plate_hole_fast.rs`,
//! `the_endpoint_expansion_converges_fast_in_its_cutoff`; derivation and figures in
//! [`super`]).
//!
//! # Cost
//!
//! Three interpolations of l per difference and a few flops per ξ, given J₀(ξc) and J₁(ξc)
//! (computed once per radius by module `crack`); example 19.
//!
//! ```
//! // Internal to the route; reached through its entry point:
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let _ = (two_plate_hole, HoledParams::default());
//! ```

use crate::numerics::panel_grid::PanelInterp;

/// l's values at the contact edge for the endpoint expansion of its transform (module docs
/// of [`super`]): l(c), l′(c) and f = (s l′)′ = l′ + s l″ at c.
pub(super) struct Endpoint {
    c: f64,
    lc: f64,
    dl: f64,
    fc: f64,
}

impl Endpoint {
    /// From `l`'s values on `lint`'s nodes: l′ by the one-sided three-point difference, l″ by
    /// the one-sided four-point one.
    pub(super) fn new(lint: &PanelInterp, l: &[f64], c: f64) -> Self {
        let lc = lint.eval(l, c);
        let hstep = 1e-3 * lint.width;
        let dl = (-3.0 * lc + 4.0 * lint.eval(l, c + hstep) - lint.eval(l, c + 2.0 * hstep))
            / (2.0 * hstep);
        let h2 = 0.02 * lint.width;
        let at = |j: f64| lint.eval(l, c + j * h2);
        let d2l = (2.0 * lc - 5.0 * at(1.0) + 4.0 * at(2.0) - at(3.0)) / (h2 * h2);
        Self {
            c,
            lc,
            dl,
            fc: dl + c * d2l,
        }
    }

    /// ∫_c^∞ l(s) J₀(ξs) s ds ≈ −l(c)cJ₁(ξc)/ξ − l′(c)cJ₀(ξc)/ξ² + f J₁(ξc)/ξ³, given
    /// J₀(ξc) and J₁(ξc).
    pub(super) fn transform(&self, xi: f64, j0: f64, j1: f64) -> f64 {
        let c = self.c;
        -self.lc * c * j1 / xi - self.dl * c * j0 / (xi * xi) + self.fc * j1 / (xi * xi * xi)
    }
}
