//! One trial contact radius of the holed two-plate model ([`super::holed`]; the search for R_o
//! over them is module `holed_search`): the crack field's Fredholm equation with a bottom load,
//! its traction on the hole at Chebyshev heights, the hole correction's fit, the iteration
//! l ← s₀ + σ_z^Z (derivation in [`super::holed`], Anderson-accelerated, module `anderson`) and
//! the contact pressure, with the quadrature helpers they share; with a prescribed lift of the
//! contact zone instead of the load ([`Setup::crack`], module `prescribed`) the finite
//! rim's correction S₂ ([`super::rim_holed`]).
//!
//! # Accuracy
//!
//! Measured through the holed route ([`super::holed`]): `tests/hankel/two_plate_hole.rs`
//! (`bilateral_limit_is_the_slab`, and against the FE `agrees_with_the_fe_on_table1_first_row`,
//! ignored, about 25 s).
//!
//! # Cost
//!
//! Most of the holed route's cost: per contact radius the cosine and J₀ tables of
//! [`super::grid`] and the H_l weights, rebuilt for every radius (rows in parallel; 50–60 ms of
//! 60–100 ms on (1, 1.3) at 1e-6, one thread, before the wider Nyström panels and the shorter
//! graded cap), then 5–7 Anderson-accelerated iterations (warm-started from a nearby radius's
//! correction); timed by example 19 (breakdown and sizes in [`super::holed`]'s Cost).

use super::anderson::{pack, unpack, Anderson};
use super::contact::RecedingError;
use super::endpoint::Endpoint;
use super::grid::{dot, PanelGrid, PanelInterp};
use super::holed_params::HoledParams;
use super::holed_setup::{Crack, Setup};
use super::layer::Stack;
use super::prescribed::Prescribed;
use super::system::{cos_m1, panels, Nystrom, XiRule};
use crate::hankel::hole::eigen::Mode;
use crate::hankel::hole::fit::{fit, Boundary, Fit, HoleData};
use crate::hankel::transform::LoadTransform;
use crate::load::FaceLoad;
use rayon::prelude::*;
use std::f64::consts::{FRAC_2_PI, PI};

/// (cos x, cos x − 1) from one `sin_cos`: cos x − 1 = −sin²x/(1 + cos x) without cancellation
/// where cos x > 0, and directly where cos x ≤ 0 (then |cos x − 1| ≥ 1).
fn cos_and_m1(x: f64) -> (f64, f64) {
    let (s, c) = x.sin_cos();
    (c, if c > 0.0 { -s * s / (1.0 + c) } else { c - 1.0 })
}

/// J₀(x) − 1 without cancellation at small x.
fn j0_m1(x: f64) -> f64 {
    if x < 0.1 {
        let y = 0.25 * x * x;
        // −y + y²/4 − y³/36 + y⁴/576: the next term is < 1e-17 at x < 0.1
        -y * (1.0 - y / 4.0 * (1.0 - y / 9.0 * (1.0 - y / 16.0)))
    } else {
        libm::j0(x) - 1.0
    }
}

impl Setup {
    /// Solves the crack field and its hole correction for contact radius `c` with `n` Nyström
    /// points, iterating l ← s₀ + σ_z^Z from the correction `start` (a nearby radius's, or
    /// none); and the contact pressure at `radii` (A ≤ r). With `lift`, the unloaded plate (no
    /// bilateral part) whose bottom is lifted by `lift` on the contact zone: the rim's S₂
    /// ([`super::rim_holed`]).
    pub(super) fn crack(
        &self,
        c: f64,
        n: usize,
        params: &HoledParams,
        radii: &[f64],
        start: Option<&Fit>,
        lift: Option<&Prescribed>,
    ) -> Result<Crack, RecedingError> {
        let d = self.d;
        let zero = LoadTransform::new(&FaceLoad::uniform(0.0, c, 0.0)?);
        // the Nyström ξ-rule: panels up to 2/D wide where the cosines (ω = 3c) allow (the layer
        // kernels' poles off ξ = 0, zeros of sinh x ± x at x = ξD, lie ≥ 4.2/D off the real
        // axis: Bernstein ρ ≥ 8.5 on a panel of 2/D, ρ⁻⁴⁰ < 1e-37), its tail cut at 1e-3 of
        // the iteration tolerance (1e-15 … 1e-8)
        let tail_tol = (1e-3 * params.iteration_tol).clamp(1e-15, 1e-8);
        let rule = XiRule::capped(&Stack::single(d), &zero, 3.0 * c, tail_tol, 2.0);
        let (xi_r, a_r, b_r) = rule.nodes();
        let (xi_r, a_r, b_r) = (xi_r.to_vec(), a_r.to_vec(), b_r.to_vec());
        // l on Gauss panels of [c, c + tail] resolving J₀(ξs) up to ξ_l (2.25 periods per panel)
        let lint = PanelInterp::new(c, c + self.tail, (4.5 * PI / self.xi_l).min(0.5 * d));
        let s_grid = lint.grid();
        let s_rule: Vec<(f64, f64)> = s_grid
            .nodes()
            .iter()
            .copied()
            .zip(s_grid.weights().iter().copied())
            .collect();
        let mode_mid: Vec<Vec<num_complex::Complex64>> = s_rule
            .iter()
            .map(|&(s, _)| {
                // a mode below 1e-20 here (times an amplitude of order P) adds nothing
                let value = |m: &Mode| match m.midplane_bound(s) < 1e-20 {
                    true => num_complex::Complex64::ZERO,
                    false => m.midplane_sigma_z(s),
                };
                self.modes.iter().map(value).collect()
            })
            .collect();
        let corner_mid: Vec<Vec<f64>> = match &self.corner {
            None => vec![Vec::new(); s_rule.len()],
            Some(cl) => s_rule
                .iter()
                .map(|&(s, _)| {
                    self.corner_table
                        .as_ref()
                        .and_then(|t| t.0.rows_at(&t.1, s))
                        .unwrap_or_else(|| cl.midplane_basis(s, self.r_max))
                })
                .collect(),
        };
        // s₀ = slab + modes + corner: the bilateral plate's corner fields are the crack
        // correction's (same A, D, ν, exponents), so their basis rows serve both
        let weights = self.bilateral.corner_weights();
        let s0: Vec<f64> = s_rule
            .iter()
            .zip(&corner_mid)
            .map(|(&(s, _), basis)| {
                let corner = match (weights.is_empty(), weights.len() == basis.len()) {
                    (true, _) => 0.0,
                    (false, true) => weights.iter().zip(basis).map(|(w, b)| w * b).sum(),
                    (false, false) => return self.s0(s),
                };
                self.slab_sigma_z(s) + self.bilateral.modes_midplane(s) + corner
            })
            .collect();
        // the lifted plate carries no load: no bilateral part, and the lift's Abel function F
        // joins φ as a known part (module `prescribed`)
        let s0 = if lift.is_some() {
            vec![0.0; s0.len()]
        } else {
            s0
        };
        let f_rule = lift.map(|f| f.transforms(&xi_r, c));
        let (f_total, f_edge) = lift.map_or((0.0, 0.0), |f| (f.integral(c), f.value(c)));
        // t-grid on [0, c]: panels resolving cos ξt up to the hole rule's end, and on the last
        // δ = min(c/2, D/2) t = c − u² (H_l ~ √(c − t) becomes smooth)
        let hole = self.hole_rule(c);
        let f_hole =
            lift.map(|f| f.transforms(&hole.xi.iter().map(|h| h.0).collect::<Vec<_>>(), c));
        let xi_h = hole.xi.last().map_or(0.0, |x| x.0);
        // the uniform panels (of h = 4.5π/ξ_h) stop δ = min(c/2, D/2, h) short of c: H_l's
        // branch point at c lies a panel or more beyond their end (Bernstein ρ ≥ 3 + √8,
        // ρ⁻⁴⁰ < 1e-30), and the graded cap is as short as that allows (its nodes cost two
        // table entries per row of every table)
        let t_width = 4.5 * PI / xi_h;
        let delta = (0.5 * c).min(0.5 * d).min(t_width);
        let su = delta.sqrt();
        let t_grid = PanelGrid::new(0.0, c - delta, t_width);
        let graded: Vec<(f64, f64)> =
            panels(0.0, su, (4.5 * PI / (2.0 * xi_h * su)).min(0.25 * su))
                .into_iter()
                .map(|(u, w)| (c - u * u, 2.0 * u * w))
                .collect();
        let nf = t_grid.len();
        let t_rule: Vec<(f64, f64)> = t_grid
            .nodes()
            .iter()
            .copied()
            .zip(t_grid.weights().iter().copied())
            .chain(graded.iter().copied())
            .collect();
        let nt = t_rule.len();
        // the tables, one row per ξ (contiguous in t or s): cos ξt, cos ξt − 1 on the rule's
        // ξ, cos ξt − 1 on the hole's
        // (rows in parallel: they are independent)
        let (cos_t, cosm1_t): (Vec<Vec<f64>>, Vec<Vec<f64>>) = xi_r
            .par_iter()
            .map(|&x| {
                let (mut cos, mut cosm1) = (vec![0.0; nt], vec![0.0; nt]);
                t_grid.cos_rows(x, &mut cos[..nf], &mut cosm1[..nf]);
                for (i, &(t, _)) in graded.iter().enumerate() {
                    (cos[nf + i], cosm1[nf + i]) = cos_and_m1(x * t);
                }
                (cos, cosm1)
            })
            .unzip();
        let hole_cosm1: Vec<Vec<f64>> = hole
            .xi
            .par_iter()
            .map(|h| {
                let mut row = vec![0.0; nt];
                t_grid.cos_m1_row(h.0, &mut row[..nf]);
                for (i, &(t, _)) in graded.iter().enumerate() {
                    row[nf + i] = cos_m1(h.0 * t);
                }
                row
            })
            .collect();
        // s-weights w·s·J₀(ξs) and w·s·(J₀ − 1) for the rule and the hole's low ξ
        let js = |xi: f64| -> (Vec<f64>, Vec<f64>) {
            let mut j = vec![0.0; s_rule.len()];
            s_grid.j0_row(xi, &mut j);
            s_rule
                .iter()
                .zip(&j)
                .map(|(&(s, w), &j)| {
                    let x = xi * s;
                    let m1 = if x < 0.1 { j0_m1(x) } else { j - 1.0 };
                    (w * s * j, w * s * m1)
                })
                .unzip()
        };
        // beyond ξ_l l̄ is its endpoint expansion on the rule too (its weights there are
        // below 30e^(−28) of their peak), with J₀(ξc), J₁(ξc) once per radius
        let rule_low = xi_r.partition_point(|&x| x <= self.xi_l);
        let rule_j: Vec<(Vec<f64>, Vec<f64>)> =
            xi_r[..rule_low].par_iter().map(|&x| js(x)).collect();
        let hole_low = hole.xi.partition_point(|h| h.0 <= self.xi_l);
        let bessel_c = |xi: &[f64]| -> Vec<(f64, f64)> {
            xi.par_iter()
                .map(|&x| (libm::j0(x * c), libm::j1(x * c)))
                .collect()
        };
        let rule_jc = bessel_c(&xi_r[rule_low..]);
        let hole_hi: Vec<f64> = hole.xi[hole_low..].iter().map(|h| h.0).collect();
        let hole_jc = bessel_c(&hole_hi);
        let hole_j: Vec<Vec<f64>> = hole.xi[..hole_low].par_iter().map(|h| js(h.0).1).collect();
        // H_l(t) = −(2/π)∫_c^{c+tail} l(s) s ds/√(s² − t²) = −(2/π)∫ l(√(t² + v²)) dv (v from
        // √(c² − t²); only where t is within a quarter s-panel of c, the rest on the s-rule):
        // linear in l's node values, so one row of weights per t, reused by every iteration
        let ns = s_rule.len();
        let h_row = |t: f64| -> Vec<f64> {
            if c - t >= 0.25 * lint.width {
                // s² − t² vanishes a quarter panel or more before the first panel: the s-rule
                // itself converges (Bernstein ellipse ρ ≥ 2.6, ρ⁻⁴⁰ < 2e-17)
                return s_rule
                    .iter()
                    .map(|&(s, w)| -FRAC_2_PI * w * s / ((s - t) * (s + t)).sqrt())
                    .collect();
            }
            let v0 = ((c - t) * (c + t)).max(0.0).sqrt();
            let end = c + self.tail;
            let v1 = ((end - t) * (end + t)).sqrt();
            let mut row = vec![0.0; ns];
            for (v, w) in panels(v0, v1, d) {
                if let Some((k, bw)) = lint.weights_at((t * t + v * v).sqrt()) {
                    for (r, b) in row[20 * k..20 * (k + 1)].iter_mut().zip(&bw) {
                        *r -= FRAC_2_PI * w * b;
                    }
                }
            }
            row
        };
        let h_rows: Vec<Vec<f64>> = t_rule.par_iter().map(|&(t, _)| h_row(t)).collect();
        let h_edge = h_row(c);
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
            let tail = Endpoint::new(&lint, &l, c);
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
            let sys =
                Nystrom::solve_general(rule.clone(), c, n, -l0 - hl_total - f_total, &alpha, &beta)
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
            let edge = sys.phi(c) + dot(&h_edge, &l) + f_edge;
            out.edge = edge / scale;
            out.iterations = it;
            // the crack field's bottom load b = q + l, b̃(ξ) = b̄(ξ) − b̄(0), on the hole rule
            let btil: Vec<f64> = hole
                .xi
                .par_iter()
                .enumerate()
                .map(|(k, &(xi, ..))| {
                    let q = dot(&wphi, &hole_cosm1[k]);
                    let lt = match hole_j.get(k) {
                        Some(j) => dot(j, &l),
                        None => {
                            let (j0, j1) = hole_jc[k - hole_low];
                            tail.transform(xi, j0, j1) - l0
                        }
                    };
                    q + lt + f_hole.as_ref().map_or(0.0, |f| f[k].1)
                })
                .collect();
            let nz = self.z_cheb.len();
            let (mut sr, mut tau) = (vec![0.0; nz], vec![0.0; nz]);
            for (k, &(_, w, j0, j1x, j1)) in hole.xi.iter().enumerate() {
                let wb = w * btil[k];
                for j in 0..nz {
                    let kk = hole.kernels[k][j];
                    sr[j] += wb * (kk[0] * j0 - kk[1] * j1x);
                    tau[j] += wb * kk[2] * j1;
                }
            }
            let data: Vec<HoleData> = self
                .z_fit
                .iter()
                .enumerate()
                .map(|(i, &z)| HoleData {
                    z,
                    sigma_r: dot(&self.interp_even[i], &sr),
                    tau_rz: dot(&self.interp_odd[i], &tau),
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
                .map(|&r| self.pressure_at(r, &sys, &l, &lint, used.as_ref(), lift))
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
