//! The hole's part of the holed two-plate route's crack iteration (module `crack`) through
//! tables that do not depend on the trial contact radius c.
//!
//! **What is computed.** The crack field's σ_r and τ_rz on the hole r = A at the upper
//! Chebyshev heights z_j are linear in its bottom load b = q + l (compression negative, the
//! units of the load; lengths in those of D): with the hole ξ-rule (ξ_k, w_k) and the layer's
//! bottom kernels R₀, R₁, T of [`crate::hankel::receding::layer_field::bottom_kernels`],
//!
//! σ_r(A, z_j) = Σ_k w_k b̃(ξ_k) [R₀ J₀(ξ_kA) − R₁ J₁(ξ_kA)/(ξ_kA)],  τ_rz = Σ_k w_k b̃(ξ_k) T J₁(ξ_kA),
//!
//! b̃(ξ) = b̄(ξ) − b̄(0) = ∫₀^c φ(t)(cos ξt − 1) dt + ∫_c^∞ l(s)(J₀(ξs) − 1) s ds (φ the Abel
//! function of the contact pressure). Exchanging the sums, σ_r and τ_rz are
//! ∫₀^c φ(t) G_j(t) dt + ∫_c^∞ l(s) H_j(s) s ds with G_j(t) = Σ_k w_k K_kj (cos ξ_kt − 1) over
//! the whole rule and H_j(s) = Σ_{ξ_k ≤ ξ_l} w_k K_kj (J₀(ξ_ks) − 1), K_kj the bracket above
//! (beyond ξ_l, l̄ is its endpoint expansion at c as before, a sum over those nodes per
//! iteration). G_j and H_j depend on the geometry only; they are tabulated on 20-point
//! Gauss–Legendre panels of width 2.5π/ξ_max from 0 (ξ_max the rule's end for G, ξ_l for H),
//! each panel computed the first time a radius needs it, and interpolated (barycentric
//! formula, [`crate::numerics::panel_grid::PanelInterp`]) at each radius's t- and s-rule. The hole ξ-rule is
//! `Setup::hole_rule` (module `setup`) for a radius c_hi = c + 2D beyond the first radius asked (it resolves
//! every radius up to c_hi); a radius beyond c_hi starts a new table.
//!
//! **Interpolation error.** G_j and H_j are band-limited to ξ_max: on a panel of width h the
//! Chebyshev coefficients of cos(ξt) beyond degree 19 sum to at most 2(ξh/4)²⁰/20!, which at
//! ξh = 2.5π is 5.9e-13; with the Lebesgue constant of 20 Gauss–Legendre nodes (< 5) the
//! interpolant's error is below 3e-12 of Σ_k |w_k K_kj| (a bound; the measured error: Accuracy).
//!
//! # Accuracy
//!
//! The unit test of module `setup_tables` (`interpolated_tables_match_the_sums`) measures the interpolant against
//! the sums at 400 points per band on Table 1 row (1, 1.3) at the knobs for 1e-6: 2.5e-15 (G)
//! and 1.6e-15 (H) of Σ_k |w_k K_kj|, asserted below the bound (1e-11 with its Lebesgue
//! constant rounded up); through the route, R_o moved by at most 8.1e-12 R_o from the
//! per-radius tables it replaced on Table 1 (module [`super`]'s Cost).
//!
//! # Cost
//!
//! A panel of G costs 20 cosines per ξ-node (the addition theorem of [`crate::numerics::panel_grid`]), of H 20
//! J₀ values per node up to ξ_l; the first radius of a setup builds about twice the entries of
//! the per-radius tables it replaces, later radii a panel or two (module [`super`]'s
//! Cost; example 19).
//!
//! ```
//! // Internal to the route; reached through its entry point:
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let _ = (two_plate_hole, HoledParams::default());
//! ```

use crate::numerics::panel_grid::{j0_m1, PanelGrid, PanelInterp};
use nalgebra::DMatrix;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::{Arc, Mutex};

/// The tables' panels are `PANEL_PERIODS`·π/ξ_max wide (module docs: the interpolation error).
const PANEL_PERIODS: f64 = 2.5;

/// One function of a length tabulated on equal panels from 0, each panel's 20 rows (of 2nz
/// values: σ_r's heights, then τ_rz's) built on first use.
struct Band {
    interp: PanelInterp,
    width: f64,
    panels: Mutex<Vec<Option<Arc<Vec<f64>>>>>,
}

/// The hole's tables for radii up to `c_hi` (module docs).
pub(super) struct HoleTable {
    /// Radii up to which the hole rule resolves the loads.
    pub(super) c_hi: f64,
    /// Upper Chebyshev heights.
    pub(super) nz: usize,
    /// The hole ξ-rule's nodes, and per node w_k K_kj (σ_r's heights, then τ_rz's).
    pub(super) xi: Vec<f64>,
    pub(super) wk: Vec<Vec<f64>>,
    /// Nodes up to ξ_l (the rest take l's endpoint expansion).
    pub(super) low: usize,
    t_band: Band,
    s_band: Band,
}

impl Band {
    fn new(end: f64, width: f64) -> Self {
        let count = (end / width).ceil().max(1.0) as usize;
        Self {
            interp: PanelInterp::equal(0.0, width, count),
            width,
            panels: Mutex::new(vec![None; count]),
        }
    }
}

impl HoleTable {
    /// The table for radii up to `c_hi` from the hole rule `rule` (built for `c_hi`), with `nz`
    /// Chebyshev heights, l's transform taken up to `xi_l`, G tabulated on [0, `t_end`] and H on
    /// [0, `s_end`].
    pub(super) fn new(
        rule: &HoleRule,
        nz: usize,
        xi_l: f64,
        c_hi: f64,
        t_end: f64,
        s_end: f64,
    ) -> Self {
        let xi: Vec<f64> = rule.xi.iter().map(|h| h.0).collect();
        let wk: Vec<Vec<f64>> = rule
            .xi
            .iter()
            .zip(&rule.kernels)
            .map(|(&(_, w, j0, j1x, j1), kk)| {
                let sr = kk.iter().map(|k| w * (k[0] * j0 - k[1] * j1x));
                sr.chain(kk.iter().map(|k| w * k[2] * j1)).collect()
            })
            .collect();
        let low = xi.partition_point(|&x| x <= xi_l);
        let xi_max = xi.last().copied().unwrap_or(xi_l);
        Self {
            c_hi,
            nz,
            t_band: Band::new(t_end, PANEL_PERIODS * PI / xi_max),
            s_band: Band::new(s_end, PANEL_PERIODS * PI / xi_l),
            xi,
            wk,
            low,
        }
    }

    /// G's values (σ_r's heights, then τ_rz's) at each of `t` (0 ≤ t ≤ c_hi).
    pub(super) fn g(&self, t: &[f64]) -> Vec<Vec<f64>> {
        self.values(&self.t_band, t, false)
    }

    /// H's values at each of `s` (s ≤ c_hi + tail), each times `scale` of the same index.
    pub(super) fn h(&self, s: &[f64], scale: &[f64]) -> Vec<Vec<f64>> {
        let mut rows = self.values(&self.s_band, s, true);
        for (row, f) in rows.iter_mut().zip(scale) {
            row.iter_mut().for_each(|v| *v *= f);
        }
        rows
    }

    /// The panels `first..=last` of G (`bessel` false) or H, each 20 rows of 2nz values: the
    /// rows cos ξ_kt − 1 (or J₀(ξ_ks) − 1) over every node at once (the addition theorem of
    /// [`crate::numerics::panel_grid`] shares its sines and cosines across panels), times the matrix w_k K_kj.
    fn panels(&self, band: &Band, first: usize, last: usize, bessel: bool) -> Vec<Arc<Vec<f64>>> {
        let count = last + 1 - first;
        let grid = PanelGrid::equal(first as f64 * band.width, band.width, count);
        let nodes = grid.len();
        let used = if bessel { self.low } else { self.xi.len() };
        let mut rows = DMatrix::<f64>::zeros(nodes, used);
        rows.as_mut_slice()
            .par_chunks_mut(nodes)
            .zip(&self.xi[..used])
            .for_each(|(col, &x)| {
                if bessel {
                    grid.j0_row(x, col);
                    for (r, &s) in col.iter_mut().zip(grid.nodes()) {
                        *r = if x * s < 0.1 { j0_m1(x * s) } else { *r - 1.0 };
                    }
                } else {
                    grid.cos_m1_row(x, col);
                }
            });
        let m = 2 * self.nz;
        let weights = DMatrix::from_fn(used, m, |k, j| self.wk[k][j]);
        let out = rows * weights;
        (0..count)
            .map(|p| {
                let panel = (0..20).flat_map(|i| (0..m).map(move |j| (20 * p + i, j)));
                Arc::new(panel.map(|ij| out[ij]).collect())
            })
            .collect()
    }

    /// The band's interpolant at each of `at`, building the panels it needs first.
    fn values(&self, band: &Band, at: &[f64], bessel: bool) -> Vec<Vec<f64>> {
        let weights: Vec<Option<(usize, [f64; 20])>> =
            at.iter().map(|&x| band.interp.weights_at(x)).collect();
        let kept: Vec<Option<Arc<Vec<f64>>>> = band
            .panels
            .lock()
            .map(|p| p.clone())
            .unwrap_or_else(|e| e.into_inner().clone());
        let mut wanted: Vec<usize> = weights
            .iter()
            .flatten()
            .map(|w| w.0)
            .filter(|&p| kept[p].is_none())
            .collect();
        wanted.sort_unstable();
        wanted.dedup();
        // the panels from the first wanted to the last (at most a few kept ones again)
        let built: Vec<(usize, Arc<Vec<f64>>)> = match (wanted.first(), wanted.last()) {
            (Some(&first), Some(&last)) => (first..=last)
                .zip(self.panels(band, first, last, bessel))
                .collect(),
            _ => Vec::new(),
        };
        let mut panels = kept;
        if let Ok(mut shared) = band.panels.lock() {
            for (p, v) in &built {
                shared[*p] = Some(Arc::clone(v));
            }
        }
        for (p, v) in built {
            panels[p] = Some(v);
        }
        let m = 2 * self.nz;
        weights
            .iter()
            .map(|w| {
                let mut out = vec![0.0; m];
                if let Some((p, w)) = w {
                    if let Some(rows) = &panels[*p] {
                        for (i, wi) in w.iter().enumerate() {
                            for (o, v) in out.iter_mut().zip(&rows[i * m..(i + 1) * m]) {
                                *o += wi * v;
                            }
                        }
                    }
                }
                out
            })
            .collect()
    }
}

/// The hole's ξ-rule for one contact radius (`Setup::hole_rule`, module `setup`).
pub(super) struct HoleRule {
    /// (ξ, w, J₀(ξA), J₁(ξA)/(ξA), J₁(ξA)).
    pub(super) xi: Vec<(f64, f64, f64, f64, f64)>,
    /// The kernels (R₀, R₁, T) per node and Chebyshev height.
    pub(super) kernels: Vec<Vec<[f64; 3]>>,
}
