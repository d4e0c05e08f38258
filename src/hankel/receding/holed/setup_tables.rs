//! A setup's tables for one trial contact radius of the holed two-plate route: the hole's
//! tables independent of the radius ([`HoleTable`], module `hole_tables`), kept by the setup
//! until a radius lies beyond them, and the radius's own tables ([`RadiusTables`], module
//! `crack_tables`), the last radius's kept so that the estimate's fewer-nodes variant at R_o,
//! the pressure's solve at R_o and the finite rim's two solves per radius (module `rim`)
//! take them instead of rebuilding them.
//!
//! # Accuracy
//!
//! The unit test here (`interpolated_tables_match_the_sums`) measures the hole tables'
//! interpolant against their sums (module `hole_tables`); the kept radius tables are the same
//! tables, bit for bit (`tests/hankel/two_plate_hole_fast.rs`). The graded cap's cosines by
//! the addition theorem along ξ differ from one `sin_cos` per entry by the rounding of the
//! argument ξt (module `numerics::panel_grid`'s Accuracy): on Table 1 R_o moved by at most 2.4e-13 of R_o at
//! 1e-6 (module [`super`]'s Cost).
//!
//! # Cost
//!
//! Most of a radius's cost (module [`super`]'s Cost, where the time goes); timed by
//! example 19. Three savings per radius (row (1, 1.3) at 1e-6, one thread, `perf
//! record`, shares of the whole run's CPU): the bilateral plate's modes at the s-rule taken
//! from the correction's table of the same modes (`HolePlate::modes_midplane_with`; bit for
//! bit the same s₀) instead of evaluated again, 5.4 % → 0.4 %; the graded cap's cos ξt by
//! the addition theorem along the Nyström rule's ξ-panels ([`XiRule::grid`]) instead of one
//! sin/cos pair per entry (the same values within the rounding of ξt); l's J₀ rows scaled
//! in place. Through the route: module [`super`]'s Cost.
//!
//! ```
//! // Internal to the route; reached through its entry point:
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let _ = (two_plate_hole, HoledParams::default());
//! ```

use super::crack_tables::RadiusTables;
use super::hole_tables::HoleTable;
use super::params::HoledParams;
use super::setup::Setup;
use crate::hankel::hole::eigen::Mode;
use crate::hankel::receding::contact::RecedingError;
use crate::hankel::receding::layer::Stack;
use crate::hankel::receding::system::{panels, XiRule};
use crate::hankel::transform::LoadTransform;
use crate::load::FaceLoad;
use crate::numerics::panel_grid::{cos_and_m1, j0_m1, PanelGrid, PanelInterp};
use num_complex::Complex64;
use rayon::prelude::*;
use std::f64::consts::{FRAC_2_PI, PI};
use std::sync::Arc;

impl Setup {
    /// The tables for contact radius `c`: the last radius's when `c` and the iteration
    /// tolerance (which sets the Nyström rule's tail) are the same, else built and kept.
    pub(super) fn radius_tables(
        &self,
        c: f64,
        params: &HoledParams,
    ) -> Result<Arc<RadiusTables>, RecedingError> {
        let key = (c.to_bits(), params.iteration_tol.to_bits());
        let kept = self.last_tables.lock().ok().and_then(|last| {
            last.as_ref()
                .filter(|(k, _)| *k == key)
                .map(|(_, t)| Arc::clone(t))
        });
        if let Some(tables) = kept {
            return Ok(tables);
        }
        let tables = Arc::new(self.build_tables(c, params)?);
        if let Ok(mut last) = self.last_tables.lock() {
            *last = Some((key, Arc::clone(&tables)));
        }
        Ok(tables)
    }

    /// Builds the tables for contact radius `c` (module docs).
    fn build_tables(&self, c: f64, params: &HoledParams) -> Result<RadiusTables, RecedingError> {
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
        let s_rule: Vec<(f64, f64)> = s_grid.pairs().collect();
        let mode_mid: Vec<Vec<Complex64>> = s_rule
            .iter()
            .map(|&(s, _)| {
                // a mode below 1e-20 here (times an amplitude of order P) adds nothing
                let value = |m: &Mode| match m.midplane_bound(s) < 1e-20 {
                    true => Complex64::ZERO,
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
        // and the bilateral plate's modes are the correction's when it has no rim (the same
        // roots, A, D, ν, G): their values at the s-rule serve both too (bit for bit: a mode
        // left out of `mode_mid` as negligible there, evaluated if the plate's sum takes it)
        let weights = self.bilateral.corner_weights();
        let same_modes = self.bilateral.modes() == self.modes.as_slice();
        let s0: Vec<f64> = s_rule
            .iter()
            .zip(&corner_mid)
            .zip(&mode_mid)
            .map(|((&(s, _), basis), row)| {
                let corner = match (weights.is_empty(), weights.len() == basis.len()) {
                    (true, _) => 0.0,
                    (false, true) => weights.iter().zip(basis).map(|(w, b)| w * b).sum(),
                    (false, false) => return self.s0(s),
                };
                let modes = match same_modes {
                    true => {
                        self.bilateral
                            .modes_midplane_with(s, |k| match row[k] == Complex64::ZERO {
                                true => self.modes[k].midplane_sigma_z(s),
                                false => row[k],
                            })
                    }
                    false => self.bilateral.modes_midplane(s),
                };
                self.slab_sigma_z(s) + modes + corner
            })
            .collect();
        // t-grid on [0, c]: panels resolving cos ξt up to the hole rule's end, and on the last
        // δ = min(c/2, D/2) t = c − u² (H_l ~ √(c − t) becomes smooth)
        let hole = self.hole_table(c);
        let xi_h = hole.xi.last().copied().unwrap_or(self.xi_l);
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
        let t_rule: Vec<(f64, f64)> = t_grid.pairs().chain(graded.iter().copied()).collect();
        let nt = t_rule.len();
        // the tables, one row per ξ (contiguous in t or s): cos ξt, cos ξt − 1 on the rule's
        // ξ (rows in parallel: they are independent). On the graded cap, whose t are no panel
        // grid, by the addition theorem along the rule's ξ-panels instead (ξt = tξ), a column
        // per t: two sin/cos pairs per ξ-panel and offset instead of one per entry (the same
        // values within the rounding of ξt, module `numerics::panel_grid`); directly if the rule were no grid
        let xi_grid = Some(rule.grid()).filter(|g| g.nodes() == xi_r.as_slice());
        let cap: Vec<(Vec<f64>, Vec<f64>)> = graded
            .par_iter()
            .map(|&(t, _)| match &xi_grid {
                Some(g) => {
                    let (mut cos, mut cosm1) = (vec![0.0; g.len()], vec![0.0; g.len()]);
                    g.cos_rows(t, &mut cos, &mut cosm1);
                    (cos, cosm1)
                }
                None => xi_r.iter().map(|&x| cos_and_m1(x * t)).unzip(),
            })
            .collect();
        let (cos_t, cosm1_t): (Vec<Vec<f64>>, Vec<Vec<f64>>) = xi_r
            .par_iter()
            .enumerate()
            .map(|(k, &x)| {
                let (mut cos, mut cosm1) = (vec![0.0; nt], vec![0.0; nt]);
                t_grid.cos_rows(x, &mut cos[..nf], &mut cosm1[..nf]);
                for (i, (c, m1)) in cap.iter().enumerate() {
                    (cos[nf + i], cosm1[nf + i]) = (c[k], m1[k]);
                }
                (cos, cosm1)
            })
            .unzip();
        let t_nodes: Vec<f64> = t_rule.iter().map(|r| r.0).collect();
        let hole_t = hole.g(&t_nodes);
        let (s_nodes, ws): (Vec<f64>, Vec<f64>) = s_rule.iter().map(|&(s, w)| (s, w * s)).unzip();
        let hole_s = hole.h(&s_nodes, &ws);
        // s-weights w·s·J₀(ξs) and w·s·(J₀ − 1) for the rule and the hole's low ξ
        // (in place: both rows written once)
        let js = |xi: f64| -> (Vec<f64>, Vec<f64>) {
            let mut j = vec![0.0; s_nodes.len()];
            s_grid.j0_row(xi, &mut j);
            let mut m1 = j.clone();
            for ((j, m1), (&s, &ws)) in j.iter_mut().zip(&mut m1).zip(s_nodes.iter().zip(&ws)) {
                let x = xi * s;
                *m1 = ws * if x < 0.1 { j0_m1(x) } else { *m1 - 1.0 };
                *j *= ws;
            }
            (j, m1)
        };
        // beyond ξ_l l̄ is its endpoint expansion on the rule too (its weights there are
        // below 30e^(−28) of their peak), with J₀(ξc), J₁(ξc) once per radius
        let rule_low = xi_r.partition_point(|&x| x <= self.xi_l);
        let rule_j: Vec<(Vec<f64>, Vec<f64>)> =
            xi_r[..rule_low].par_iter().map(|&x| js(x)).collect();
        let bessel_c = |xi: &[f64]| -> Vec<(f64, f64)> {
            xi.par_iter()
                .map(|&x| (libm::j0(x * c), libm::j1(x * c)))
                .collect()
        };
        let rule_jc = bessel_c(&xi_r[rule_low..]);
        let hole_jc = bessel_c(&hole.xi[hole.low..]);
        // H_l(t) = −(2/π)∫_c^{c+tail} l(s) s ds/√(s² − t²): linear in l's node values, so one
        // row of weights per t, reused by every iteration. Where s² − t² vanishes a quarter
        // s-panel or more before a panel, that panel's own rule converges (Bernstein ellipse
        // ρ ≥ 2.6, ρ⁻⁴⁰ < 2e-17): every panel when c − t ≥ a quarter panel, else every panel
        // but the first (ρ ≥ 5.8 there), whose part is −(2/π)∫ l(√(t² + v²)) dv with v from
        // √(c² − t²) to √((c + h)² − t²), h the panel's width, on panels no wider than D
        let h_row = |t: f64| -> Vec<f64> {
            let direct = |&(s, w): &(f64, f64)| -FRAC_2_PI * w * s / ((s - t) * (s + t)).sqrt();
            if c - t >= 0.25 * lint.width {
                return s_rule.iter().map(direct).collect();
            }
            let mut row: Vec<f64> = vec![0.0; 20];
            row.extend(s_rule[20..].iter().map(direct));
            let v0 = ((c - t) * (c + t)).max(0.0).sqrt();
            let end = c + lint.width;
            let v1 = ((end - t) * (end + t)).sqrt();
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
        Ok(RadiusTables {
            rule,
            xi_r,
            a_r,
            b_r,
            lint,
            s_rule,
            mode_mid,
            corner_mid,
            s0,
            hole,
            hole_t,
            hole_s,
            t_rule,
            cos_t,
            cosm1_t,
            rule_low,
            rule_j,
            rule_jc,
            hole_jc,
            h_rows,
            h_edge,
        })
    }
}

impl Setup {
    /// The hole table for contact radius `c`: the setup's, or a new one from c to c + 2D when
    /// `c` lies beyond it.
    pub(super) fn hole_table(&self, c: f64) -> Arc<HoleTable> {
        let kept = self
            .hole_tables
            .lock()
            .ok()
            .and_then(|t| t.as_ref().filter(|t| c <= t.c_hi).map(Arc::clone));
        if let Some(t) = kept {
            return t;
        }
        let table = Arc::new(self.new_hole_table(c + 2.0 * self.d));
        if let Ok(mut t) = self.hole_tables.lock() {
            *t = Some(Arc::clone(&table));
        }
        table
    }
}

impl Setup {
    /// A hole table for radii up to `c_hi` (module `hole_tables`): G on [0, c_hi + D], H on
    /// [0, c_hi + tail + D].
    fn new_hole_table(&self, c_hi: f64) -> HoleTable {
        let (nz, d) = (self.z_cheb.len(), self.d);
        let rule = self.hole_rule(c_hi);
        HoleTable::new(&rule, nz, self.xi_l, c_hi, c_hi + d, c_hi + self.tail + d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hankel::receding::holed::HoledParams;
    use crate::{FaceLoad, Material, OuterRadius, SinglePlate};

    /// G and H interpolated against their sums over the rule at the same points, at 400 points
    /// spread over each band (Table 1 row (1, 1.3), the knobs for 1e-6): the module's bound is
    /// 3e-12 of Σ_k |w_k K_kj|; asserted 1e-11 of it.
    #[test]
    fn interpolated_tables_match_the_sums() {
        let (load, mat) = (FaceLoad::uniform(0.1, 0.13, 1.0), Material::unit(0.3));
        let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, mat.unwrap(), load.unwrap());
        let plate = plate.unwrap();
        let setup = Setup::new(&plate, &HoledParams::for_tolerance(1e-6)).unwrap();
        let c = 0.17;
        let table = setup.hole_table(c);
        let m = 2 * table.nz;
        let scale: Vec<f64> = (0..m)
            .map(|j| table.wk.iter().map(|w| 2.0 * w[j].abs()).sum())
            .collect();
        let check = |points: Vec<f64>, bessel: bool| -> f64 {
            let got = if bessel {
                table.h(&points, &vec![1.0; points.len()])
            } else {
                table.g(&points)
            };
            let mut worst: f64 = 0.0;
            for (&x, g) in points.iter().zip(&got) {
                let count = if bessel { table.low } else { table.xi.len() };
                for j in 0..m {
                    let sum: f64 = table.xi[..count]
                        .iter()
                        .zip(&table.wk)
                        .map(|(&k, w)| {
                            w[j] * if bessel {
                                libm::j0(k * x) - 1.0
                            } else {
                                (k * x).cos() - 1.0
                            }
                        })
                        .sum();
                    worst = worst.max((g[j] - sum).abs() / scale[j]);
                }
            }
            worst
        };
        let t_err = check(
            (0..400).map(|i| c * (i as f64 + 0.37) / 400.0).collect(),
            false,
        );
        let s_end = c + setup.tail;
        let s_err = check(
            (0..400)
                .map(|i| c + (s_end - c) * (i as f64 + 0.37) / 400.0)
                .collect(),
            true,
        );
        println!("G: {t_err:e}, H: {s_err:e} of the sums' scale");
        assert!(t_err < 1e-11 && s_err < 1e-11, "{t_err:e} {s_err:e}");
    }
}
