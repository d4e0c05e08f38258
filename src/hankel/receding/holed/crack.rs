//! One trial contact radius of the holed two-plate model ([`super`]; the search for R_o
//! over them is module `search`): the crack field's Fredholm equation with a bottom load,
//! its traction on the hole at Chebyshev heights, the hole correction's fit, the iteration
//! l ← s₀ + σ_z^Z (derivation in [`super`], Anderson-accelerated, module `anderson`) and
//! the contact pressure, with the quadrature helpers they share; with a prescribed lift of the
//! contact zone instead of the load ([`Setup::crack`], module `prescribed`) the finite
//! rim's correction S₂ ([`super::rim`]).
//!
//! # Accuracy
//!
//! Measured through the holed route ([`super`]): `tests/hankel/two_plate_hole.rs`
//! (`bilateral_limit_is_the_slab`, and against the FE `agrees_with_the_fe_on_table1_first_row`,
//! ignored, about 25 s).
//!
//! # Cost
//!
//! Per contact radius the tables of module `crack_tables` (a setup keeps the last radius's),
//! then a few Anderson-accelerated iterations (32 over the 8 radii of (1, 1.3) at 1e-6;
//! warm-started from a nearby radius's
//! correction), each a Nyström solve of n + 1 unknowns with the matrix built and LU-factored
//! once per radius (module `system`'s `NystromMatrix`: only α, β and the total change between
//! iterations; the same arithmetic, R_o bit for bit), the cosine tables' sums and the hole's
//! part through module `hole_tables` (2nz sums over the t- and s-rule instead of sums over the
//! hole rule); timed by example 19 (breakdown in [`super`]'s Cost).

use super::anderson::{pack, unpack, Anderson};
use super::endpoint::Endpoint;
use super::params::HoledParams;
use super::setup::{Crack, Setup};
use crate::hankel::hole::fit::{fit, Boundary, Fit, HoleData};
use crate::hankel::receding::contact::RecedingError;
use crate::hankel::receding::prescribed::Prescribed;
use crate::hankel::receding::system::{panels, Nystrom, NystromMatrix};
use crate::numerics::panel_grid::{dot, PanelInterp};
use std::f64::consts::FRAC_2_PI;

impl Setup {
    /// Solves the crack field and its hole correction for contact radius `c` with `n` Nyström
    /// points, iterating l ← s₀ + σ_z^Z from the correction `start` (a nearby radius's, or
    /// none); and the contact pressure at `radii` (A ≤ r). With `lift`, the unloaded plate (no
    /// bilateral part) whose bottom is lifted by `lift` on the contact zone: the rim's S₂
    /// ([`super::rim`]).
    pub(super) fn crack(
        &self,
        c: f64,
        n: usize,
        params: &HoledParams,
        radii: &[f64],
        start: Option<&Fit>,
        lift: Option<&Prescribed>,
    ) -> Result<Crack, RecedingError> {
        let tb = self.radius_tables(c, params)?;
        let (xi_r, a_r, b_r, lint, s_rule) = (&tb.xi_r, &tb.a_r, &tb.b_r, &tb.lint, &tb.s_rule);
        let (mode_mid, corner_mid, hole, t_rule) =
            (&tb.mode_mid, &tb.corner_mid, &tb.hole, &tb.t_rule);
        let (cos_t, cosm1_t) = (&tb.cos_t, &tb.cosm1_t);
        let (rule_low, rule_j, rule_jc) = (tb.rule_low, &tb.rule_j, &tb.rule_jc);
        let nz = self.z_cheb.len();
        let (h_rows, h_edge) = (&tb.h_rows, &tb.h_edge);
        // the lifted plate carries no load: no bilateral part, and the lift's Abel function F
        // joins φ as a known part (module `prescribed`)
        let s0 = match lift {
            Some(_) => vec![0.0; tb.s0.len()],
            None => tb.s0.clone(),
        };
        let f_rule = lift.map(|f| f.transforms(xi_r, c));
        let (f_total, f_edge) = lift.map_or((0.0, 0.0), |f| (f.integral(c), f.value(c)));
        // the lift's part of the hole traction (σ_r's heights, then τ_rz's): fixed per radius
        let mut lift_hole = vec![0.0; 2 * nz];
        if let Some(f) = lift {
            for (wk, (_, f1)) in hole.wk.iter().zip(f.transforms(&hole.xi, c)) {
                axpy(&mut lift_hole, f1, wk);
            }
        }
        let mut fitted: Option<Fit> = start.filter(|f| f.modes.len() == self.modes.len()).cloned();
        let mut last = f64::NAN;
        let mut out = Crack {
            edge: f64::NAN,
            residual: f64::NAN,
            crack_traction: 0.0,
            iterations: 0,
            pressure: Vec::new(),
            fit: None,
        };
        let scale = self.p0 / c;
        // the last solve and the l and correction it was solved with (for the pressure)
        let mut state: Option<(Nystrom, Vec<f64>, Option<Fit>)> = None;
        let mut accel = (params.anderson > 0).then(|| Anderson::new(params.anderson));
        // the Nyström matrix depends on the radius only: factored once for every iteration
        let matrix = NystromMatrix::new(tb.rule.clone(), c, n);
        for it in 1..=params.max_iterations {
            let l: Vec<f64> = (0..s_rule.len())
                .map(|i| {
                    s0[i]
                        + fitted.as_ref().map_or(0.0, |f| {
                            let m: f64 = mode_mid[i]
                                .iter()
                                .zip(&f.modes)
                                .map(|(v, a)| (a * v).re)
                                .sum();
                            m + dot(&corner_mid[i], &f.extra)
                        })
                })
                .collect();
            let l0: f64 = s_rule.iter().zip(&l).map(|(&(s, w), v)| w * s * v).sum();
            let tail = Endpoint::new(lint, &l, c);
            let hl: Vec<f64> = h_rows.iter().map(|row| dot(row, &l)).collect();
            let whl: Vec<f64> = t_rule.iter().zip(&hl).map(|(&(_, w), h)| w * h).collect();
            let hl_total: f64 = whl.iter().sum();
            let m = xi_r.len();
            let mut alpha = vec![0.0; m];
            let mut beta = vec![0.0; m];
            for k in 0..m {
                let (hc, hv) = (dot(&whl, &cos_t[k]), dot(&whl, &cosm1_t[k]));
                let (lbar, ltil) = match rule_j.get(k) {
                    Some((j, jm1)) => (dot(j, &l), dot(jm1, &l)),
                    None => {
                        let (j0, j1) = rule_jc[k - rule_low];
                        let lbar = tail.transform(xi_r[k], j0, j1);
                        (lbar, lbar - l0)
                    }
                };
                alpha[k] = -a_r[k] * (lbar + hc);
                beta[k] = -b_r[k] * (ltil + hv);
                if let Some(f) = &f_rule {
                    alpha[k] -= a_r[k] * f[k].0;
                    beta[k] -= b_r[k] * f[k].1;
                }
            }
            let sys = matrix
                .solve(-l0 - hl_total - f_total, &alpha, &beta)
                .ok_or(RecedingError::Singular { c })?;
            let (c0, g, h) = sys.series();
            // φ = ψ + H_l, ψ(t) = C₀ + Σ_k [g_k (cos ξ_k t − 1) − h_k cos ξ_k t]
            let mut phi: Vec<f64> = hl.iter().map(|h| c0 + h).collect();
            for k in 0..m {
                for ((p, cm1), cs) in phi.iter_mut().zip(&cosm1_t[k]).zip(&cos_t[k]) {
                    *p += g[k] * cm1 - h[k] * cs;
                }
            }
            let wphi: Vec<f64> = t_rule.iter().zip(&phi).map(|(&(_, w), p)| w * p).collect();
            let edge = sys.phi(c) + dot(h_edge, &l) + f_edge;
            out.edge = edge / scale;
            out.iterations = it;
            // the crack field's traction on the hole from its bottom load b = q + l through the
            // hole's tables (module `hole_tables`): φ's part by G, l's up to ξ_l by H, beyond
            // ξ_l l̄'s endpoint expansion on the hole rule
            let mut st = lift_hole.clone();
            for (g, w) in tb.hole_t.iter().zip(&wphi) {
                axpy(&mut st, *w, g);
            }
            for (h, v) in tb.hole_s.iter().zip(&l) {
                axpy(&mut st, *v, h);
            }
            let high = hole.xi[hole.low..].iter().zip(&hole.wk[hole.low..]);
            for ((&xi, wk), &(j0, j1)) in high.zip(&tb.hole_jc) {
                axpy(&mut st, tail.transform(xi, j0, j1) - l0, wk);
            }
            let (sr, tau) = st.split_at(nz);
            let data: Vec<HoleData> = self
                .z_fit
                .iter()
                .enumerate()
                .map(|(i, &z)| HoleData {
                    z,
                    sigma_r: dot(&self.interp_even[i], sr),
                    tau_rz: dot(&self.interp_odd[i], tau),
                })
                .collect();
            if it == 1 {
                out.crack_traction = data
                    .iter()
                    .fold(0.0f64, |m, p| m.max(p.sigma_r.hypot(p.tau_rz)))
                    / self.p_ref;
            }
            let f = self.fit(&data);
            out.residual =
                f.residual(
                    &self.modes,
                    &Boundary {
                        r: self.a,
                        data: &data,
                        extra: &self.corner_cols,
                    },
                )
                .0 / self.p_ref;
            let f = match accel.as_mut() {
                Some(acc) => {
                    let x = fitted
                        .as_ref()
                        .map_or_else(|| vec![0.0; pack(&f).len()], pack);
                    let next = acc.next(&x, pack(&f));
                    unpack(f, &next)
                }
                None => f,
            };
            let used = fitted.replace(f);
            let done = (edge - last).abs() < params.iteration_tol * scale;
            state = Some((sys, l, used));
            if done {
                break;
            }
            last = edge;
        }
        out.fit = fitted;
        if let Some((sys, l, used)) = state.filter(|_| !radii.is_empty()) {
            out.pressure = radii
                .iter()
                .map(|&r| self.pressure_at(r, &sys, &l, lint, used.as_ref(), lift))
                .collect();
        }
        Ok(out)
    }

    /// The contact pressure q(r) ≥ 0 (compression positive) at A ≤ r of the solution with
    /// contact radius c = `sys`'s, solved with bottom load `l` (values on `lint`'s nodes) that the
    /// correction `fit` gave: q = q_ψ + q_H − l(r), where q_ψ is the smooth part ψ's pressure
    /// ([`Nystrom::pressure`]) and q_H that of H_l, in closed form (the Abel pressure of a ring
    /// load beyond c, integrated over l):
    /// q_H(r) = −(2/π)/√(c² − r²) ∫_c^∞ l(s) s √(s² − c²)/(s² − r²) ds, with s² = c² + v².
    /// Zero for r ≥ c.
    fn pressure_at(
        &self,
        r: f64,
        sys: &Nystrom,
        l: &[f64],
        lint: &PanelInterp,
        fit: Option<&Fit>,
        lift: Option<&Prescribed>,
    ) -> f64 {
        let c = sys.radius();
        if r >= c {
            return 0.0;
        }
        let k2 = (c - r) * (c + r);
        let kappa = k2.sqrt();
        let end = c + self.tail;
        let v_end = ((end - c) * (end + c)).sqrt();
        // the kernel v²/(κ² + v²) turns over at v ~ κ: panels of κ/2 up to 10κ, then of D/2
        let split = (10.0 * kappa).min(v_end);
        let mut rule = panels(0.0, split, 0.5 * kappa);
        rule.extend(panels(split, v_end, 0.5 * self.d));
        let integral: f64 = rule
            .iter()
            .map(|&(v, w)| w * lint.eval(l, (c * c + v * v).sqrt()) * v * v / (k2 + v * v))
            .sum();
        let q_h = -FRAC_2_PI * integral / kappa;
        // l inside c: the bilateral plate's midplane σ_z plus the correction's on the plane
        let corner = self
            .corner
            .as_ref()
            .map_or_else(Vec::new, |cl| cl.midplane_basis(r, self.r_max));
        let z = fit.map_or(0.0, |f| {
            let m: f64 = self
                .modes
                .iter()
                .zip(&f.modes)
                .map(|(mode, a)| (a * mode.midplane_sigma_z(r)).re)
                .sum();
            m + corner.iter().zip(&f.extra).map(|(b, x)| b * x).sum::<f64>()
        });
        match lift {
            Some(f) => sys.pressure(r, self.d) + q_h - z + f.pressure(r, c),
            None => sys.pressure(r, self.d) + q_h - (self.s0(r) + z),
        }
    }

    /// The correction cancelling `data` on the hole (collocation on every other height).
    fn fit(&self, data: &[HoleData]) -> Fit {
        let columns = 4 * self.corner.as_ref().map_or(0, |c| c.count());
        let colloc: Vec<HoleData> = data.iter().step_by(2).copied().collect();
        let extra: Vec<f64> = self
            .corner_cols
            .chunks(2 * columns.max(1))
            .step_by(2)
            .flatten()
            .copied()
            .collect();
        fit(
            &self.modes,
            self.a,
            false,
            columns,
            &[Boundary {
                r: self.a,
                data: &colloc,
                extra: &extra,
            }],
        )
    }
}

/// y ← y + a·x.
fn axpy(y: &mut [f64], a: f64, x: &[f64]) {
    for (y, x) in y.iter_mut().zip(x) {
        *y += a * x;
    }
}
