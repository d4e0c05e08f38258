//! One trial contact radius of the holed two-plate model ([`super::holed`]): the crack field's
//! Fredholm equation with a bottom load, its traction on the hole at Chebyshev heights, the hole
//! correction's fit, and the iteration l ← s₀ + σ_z^Z (derivation in [`super::holed`]), with the
//! quadrature helpers they share.
//!
//! # Accuracy
//!
//! Measured through the holed route ([`super::holed`]): `tests/hankel/two_plate_hole.rs`
//! (`bilateral_limit_is_the_slab`, and against the FE `agrees_with_the_fe_on_table1_first_row`,
//! ignored, about 25 s).
//!
//! # Cost
//!
//! Most of the holed route's cost (the brute-force transforms of l and of the hole's traction);
//! timed by the ignored study `table1_rows_record` in the same file.

use super::contact::RecedingError;
use super::holed::{Crack, HoledParams, Setup};
use super::system::{cos_m1, panels, Nystrom, XiRule};
use crate::hankel::hole::fit::{fit, Boundary, Fit, HoleData};
use crate::hankel::transform::LoadTransform;
use crate::load::FaceLoad;
use crate::numerics::quadrature::gauss_legendre;
use std::f64::consts::{FRAC_2_PI, PI};

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

/// Barycentric interpolation on Gauss–Legendre panels of equal width from `start`.
struct PanelInterp {
    start: f64,
    width: f64,
    panels: usize,
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl PanelInterp {
    fn new(start: f64, end: f64, width: f64) -> Self {
        let panels = ((end - start) / width).ceil().max(1.0) as usize;
        let nodes: Vec<f64> = gauss_legendre(20).iter().map(|&(x, _)| x).collect();
        let weights = (0..nodes.len())
            .map(|j| {
                1.0 / (0..nodes.len())
                    .filter(|&k| k != j)
                    .map(|k| nodes[j] - nodes[k])
                    .product::<f64>()
            })
            .collect();
        Self {
            start,
            width: (end - start) / panels as f64,
            panels,
            nodes,
            weights,
        }
    }

    /// The nodes (x, w) of every panel, in order.
    fn rule(&self) -> Vec<(f64, f64)> {
        panels(
            self.start,
            self.start + self.width * self.panels as f64,
            self.width,
        )
    }

    /// The interpolant of `values` (one per node of [`Self::rule`]) at `s` (0 beyond the end).
    fn eval(&self, values: &[f64], s: f64) -> f64 {
        let u = (s - self.start) / self.width;
        if !(0.0..=self.panels as f64).contains(&u) {
            return 0.0;
        }
        let k = (u.floor() as usize).min(self.panels - 1);
        let x = 2.0 * (u - k as f64) - 1.0;
        let v = &values[20 * k..20 * (k + 1)];
        let (mut num, mut den) = (0.0, 0.0);
        for ((xj, wj), vj) in self.nodes.iter().zip(&self.weights).zip(v) {
            let dx = x - xj;
            if dx == 0.0 {
                return *vj;
            }
            let t = wj / dx;
            num += t * vj;
            den += t;
        }
        num / den
    }
}

impl Setup {
    /// Solves the crack field and its hole correction for contact radius `c` with `n` Nyström
    /// points, iterating l ← s₀ + σ_z^Z.
    pub(super) fn crack(
        &self,
        c: f64,
        n: usize,
        params: &HoledParams,
    ) -> Result<Crack, RecedingError> {
        let d = self.d;
        let zero = LoadTransform::new(&FaceLoad::uniform(0.0, c, 0.0)?);
        let rule = XiRule::new(d, &zero, 3.0 * c, 1e-15);
        let (xi_r, a_r, b_r) = rule.nodes();
        let (xi_r, a_r, b_r) = (xi_r.to_vec(), a_r.to_vec(), b_r.to_vec());
        // l on Gauss panels of [c, c + tail] resolving J₀(ξs) up to ξ_l (2.25 periods per panel)
        let lint = PanelInterp::new(c, c + self.tail, (4.5 * PI / self.xi_l).min(0.5 * d));
        let s_rule = lint.rule();
        let s0: Vec<f64> = s_rule.iter().map(|&(s, _)| self.s0(s)).collect();
        let mode_mid: Vec<Vec<num_complex::Complex64>> = s_rule
            .iter()
            .map(|&(s, _)| self.modes.iter().map(|m| m.midplane_sigma_z(s)).collect())
            .collect();
        let corner_mid: Vec<Vec<f64>> = s_rule
            .iter()
            .map(|&(s, _)| {
                self.corner
                    .as_ref()
                    .map_or_else(Vec::new, |cl| cl.midplane_basis(s, self.r_max))
            })
            .collect();
        // t-grid on [0, c]: panels resolving cos ξt up to the hole rule's end, and on the last
        // δ = min(c/2, D/2) t = c − u² (H_l ~ √(c − t) becomes smooth)
        let xi_h = self.hole_xi.last().map_or(0.0, |x| x.0);
        let delta = (0.5 * c).min(0.5 * d);
        let su = delta.sqrt();
        let mut t_rule = panels(0.0, c - delta, 4.5 * PI / xi_h);
        t_rule.extend(
            panels(0.0, su, (4.5 * PI / (2.0 * xi_h * su)).min(0.25 * su))
                .into_iter()
                .map(|(u, w)| (c - u * u, 2.0 * u * w)),
        );
        let cos_t: Vec<Vec<f64>> = t_rule
            .iter()
            .map(|&(t, _)| xi_r.iter().map(|x| (x * t).cos()).collect())
            .collect();
        let cosm1_t: Vec<Vec<f64>> = t_rule
            .iter()
            .map(|&(t, _)| xi_r.iter().map(|x| cos_m1(x * t)).collect())
            .collect();
        let hole_cosm1: Vec<Vec<f64>> = t_rule
            .iter()
            .map(|&(t, _)| self.hole_xi.iter().map(|h| cos_m1(h.0 * t)).collect())
            .collect();
        // s-weights w·s·J₀(ξs) and w·s·(J₀ − 1) for the rule and the hole's low ξ
        let js = |xi: f64| -> (Vec<f64>, Vec<f64>) {
            s_rule
                .iter()
                .map(|&(s, w)| {
                    let m1 = j0_m1(xi * s);
                    (w * s * (1.0 + m1), w * s * m1)
                })
                .unzip()
        };
        let rule_j: Vec<(Vec<f64>, Vec<f64>)> = xi_r.iter().map(|&x| js(x)).collect();
        let hole_low = self.hole_xi.partition_point(|h| h.0 <= self.xi_l);
        let hole_j: Vec<Vec<f64>> = self.hole_xi[..hole_low].iter().map(|h| js(h.0).1).collect();
        let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(a, b)| a * b).sum::<f64>();
        let v_width = d;
        let h_l = |l: &[f64], t: f64| -> f64 {
            let v0 = ((c - t) * (c + t)).max(0.0).sqrt();
            let end = c + self.tail;
            let v1 = ((end - t) * (end + t)).sqrt();
            -FRAC_2_PI
                * panels(v0, v1, v_width)
                    .iter()
                    .map(|&(v, w)| w * lint.eval(l, (t * t + v * v).sqrt()))
                    .sum::<f64>()
        };
        let mut fitted: Option<Fit> = None;
        let mut last = f64::NAN;
        let mut out = Crack {
            edge: f64::NAN,
            residual: f64::NAN,
            crack_traction: 0.0,
            iterations: 0,
        };
        let scale = self.p0 / c;
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
            let hl: Vec<f64> = t_rule.iter().map(|&(t, _)| h_l(&l, t)).collect();
            let hl_total: f64 = t_rule.iter().zip(&hl).map(|(&(_, w), h)| w * h).sum();
            let m = xi_r.len();
            let mut alpha = vec![0.0; m];
            let mut beta = vec![0.0; m];
            for k in 0..m {
                let (hc, hv) = t_rule
                    .iter()
                    .enumerate()
                    .fold((0.0, 0.0), |acc, (i, &(_, w))| {
                        (
                            acc.0 + w * hl[i] * cos_t[i][k],
                            acc.1 + w * hl[i] * cosm1_t[i][k],
                        )
                    });
                let lbar = dot(&rule_j[k].0, &l);
                let ltil = dot(&rule_j[k].1, &l);
                alpha[k] = -a_r[k] * (lbar + hc);
                beta[k] = -b_r[k] * (ltil + hv);
            }
            let sys = Nystrom::solve_general(rule.clone(), c, n, -l0 - hl_total, &alpha, &beta)
                .ok_or(RecedingError::Singular { c })?;
            let (c0, g, h) = sys.series();
            let psi = |i: usize| -> f64 {
                c0 + (0..m)
                    .map(|k| g[k] * cosm1_t[i][k] - h[k] * cos_t[i][k])
                    .sum::<f64>()
            };
            let phi: Vec<f64> = (0..t_rule.len()).map(|i| psi(i) + hl[i]).collect();
            let edge = sys.phi(c) + h_l(&l, c);
            out.edge = edge / scale;
            out.iterations = it;
            // the crack field's bottom load b = q + l, b̃(ξ) = b̄(ξ) − b̄(0), on the hole rule
            let lc = lint.eval(&l, c);
            let hstep = 1e-3 * lint.width;
            let dl = (-3.0 * lc + 4.0 * lint.eval(&l, c + hstep) - lint.eval(&l, c + 2.0 * hstep))
                / (2.0 * hstep);
            let btil: Vec<f64> = self
                .hole_xi
                .iter()
                .enumerate()
                .map(|(k, &(xi, ..))| {
                    let q: f64 = t_rule
                        .iter()
                        .enumerate()
                        .map(|(i, &(_, w))| w * phi[i] * hole_cosm1[i][k])
                        .sum();
                    let lt = if k < hole_low {
                        dot(&hole_j[k], &l)
                    } else {
                        let x = xi * c;
                        -lc * c * libm::j1(x) / xi - dl * c * libm::j0(x) / (xi * xi) - l0
                    };
                    q + lt
                })
                .collect();
            let nz = self.z_cheb.len();
            let (mut sr, mut tau) = (vec![0.0; nz], vec![0.0; nz]);
            for (k, &(_, w, j0, j1x, j1)) in self.hole_xi.iter().enumerate() {
                let wb = w * btil[k];
                for j in 0..nz {
                    let kk = self.hole_kernels[k][j];
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
            fitted = Some(f);
            if (edge - last).abs() < params.iteration_tol * scale {
                return Ok(out);
            }
            last = edge;
        }
        Ok(out)
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
