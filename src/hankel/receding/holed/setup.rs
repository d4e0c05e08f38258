//! The fixed parts of one geometry of the semi-analytic two-plate route with the hole
//! ([`super`]): the bilateral holed plate, the correction basis (hole modes, corner
//! fields), the tables that every trial contact radius reuses ([`Setup`]), the hole's ξ-rule
//! for the hole tables ([`Setup::hole_rule`]),
//! and one contact radius solved ([`Crack`]). The root search over the radius is
//! [`super::search`]; the public entry points and their record are [`super`].
//!
//! # Accuracy
//!
//! As [`super`]: `tests/hankel/two_plate_hole.rs`, `tests/hankel/two_plate_hole_fast.rs`.
//!
//! # Cost
//!
//! Example 19 (`examples/19_two_plate_hankel.rs`): about 0.2 s per geometry before they were
//! cut to [A, B + 3D + tail] (the slab's midplane curve 0.12 s, the corner table 0.07 s on
//! Table 1 row 1, over the whole reach), shared with the
//! estimate's coarse setups ([`Setup::sharing`]), as is the bilateral plate where the hole
//! knobs are the same (the heights and ξ_l variants) and the hole tables (with the panels
//! built so far) where the hole ξ-rule, heights and tail are (the modes variant). The hole
//! rule is built per hole table (module `hole_tables`), not per radius. At the knobs for 1e-6
//! the setups are 16 % of the route's CPU on (1, 1.3) (`perf record`; the
//! bilateral plates 5 %), the hole tables' panels 9 %. With the modes variant on the setup's
//! hole tables (one thread, three runs each, this route's binary and main's after the tables
//! round): the hole tables' panels under the estimate 14 % → 10 % of each binary's samples
//! (module [`super`]'s Cost).
//!
//! ```
//! // Internal to the route; reached through its entry point:
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let _ = (two_plate_hole, HoledParams::default());
//! ```

use super::crack_tables::RadiusTables;
use super::hole_tables::{HoleRule, HoleTable};
use super::params::HoledParams;
use crate::error::InputError;
use crate::hankel::hole::corner::CornerLoads;
use crate::hankel::hole::eigen::{symmetric_roots, Mode};
use crate::hankel::hole::fit::{heights, Fit};
use crate::hankel::hole::{HoleParams, HolePlate};
use crate::hankel::midplane::MidplaneCurve;
use crate::hankel::receding::contact::RecedingError;
use crate::hankel::receding::layer_field::bottom_kernels;
use crate::hankel::receding::system::panels;
use crate::hankel::transform::LoadTransform;
use crate::joint::{OuterRadius, SinglePlate};
use crate::numerics::panel_grid::PanelInterp;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::{Arc, Mutex, OnceLock};

/// The load's outer radius, in D, up to which the Nyström points are not scaled.
const NODES_SPAN: f64 = 3.5;

/// The geometry's fixed parts: the bilateral plate, the correction basis, the hole's ξ-rule.
pub(super) struct Setup {
    pub(super) a: f64,
    pub(super) d: f64,
    /// p̄(0) of the load.
    pub(super) p0: f64,
    /// P, the mean pressure.
    pub(super) p_ref: f64,
    pub(super) bilateral: HolePlate,
    /// The hole knobs `bilateral` was solved with.
    pub(super) hole: HoleParams,
    /// The slab's midplane σ_z on [A, B + 3D + tail], and on [A, `r_max`] once needed.
    pub(super) slab_mid: Arc<MidplaneCurve>,
    pub(super) slab_far: Arc<OnceLock<Option<MidplaneCurve>>>,
    pub(super) modes: Vec<Mode>,
    pub(super) corner: Option<CornerLoads>,
    /// Radius up to which the corner fields' midplane rule is built.
    pub(super) r_max: f64,
    /// Length beyond c over which l is integrated.
    pub(super) tail: f64,
    /// Fit heights (face to plane) and the corner columns there.
    pub(super) z_fit: Vec<f64>,
    pub(super) corner_cols: Vec<f64>,
    /// Upper Chebyshev heights and the barycentric matrices (fit height × Chebyshev height)
    /// for even (σ_r) and odd (τ_rz) extension.
    pub(super) z_cheb: Vec<f64>,
    pub(super) interp_even: Vec<Vec<f64>>,
    pub(super) interp_odd: Vec<Vec<f64>>,
    /// Poisson's ratio.
    pub(super) nu: f64,
    /// The Nyström points' factor for this load, max(1, B/(3.5D)) ([`Setup::nodes_for`]).
    pub(super) node_scale: f64,
    /// The hole ξ-rule's end: e^(−ξ z_min) = e^(−`hole_decay`) at the lowest height.
    pub(super) xi_h: f64,
    /// ξ beyond which l̄ is taken from its endpoint expansion.
    pub(super) xi_l: f64,
    /// The corner fields' midplane σ_z (the basis rows of [`CornerLoads::midplane_basis`]) on
    /// panels of D/2 over [A, r_max], interpolated by every trial radius.
    pub(super) corner_table: Option<Arc<(PanelInterp, Vec<Vec<f64>>)>>,
    /// The last contact radius's tables, keyed by (c, iteration tolerance) bits
    /// ([`Setup::radius_tables`]).
    pub(super) last_tables: Mutex<Option<TablesKey>>,
    /// The hole's tables independent of the radius ([`Setup::hole_table`]).
    pub(super) hole_tables: Mutex<Option<Arc<HoleTable>>>,
}

/// A radius's tables with their key (module `crack_tables`).
pub(super) type TablesKey = ((u64, u64), Arc<RadiusTables>);

/// One contact radius solved.
pub(super) struct Crack {
    /// c·φ(c)/p̄(0).
    pub(super) edge: f64,
    pub(super) residual: f64,
    pub(super) crack_traction: f64,
    pub(super) iterations: usize,
    /// The contact pressure at the radii asked for.
    pub(super) pressure: Vec<f64>,
    /// The hole correction's last fit (a warm start for a nearby radius).
    pub(super) fit: Option<Fit>,
}

impl Setup {
    pub(super) fn new(plate: &SinglePlate, params: &HoledParams) -> Result<Self, RecedingError> {
        Self::sharing(plate, params, None)
    }

    /// As [`Setup::new`], taking from `shared` (a setup of the same plate, e.g. the estimate's
    /// finer run) the parts that do not depend on the knobs changed: the slab's midplane curve
    /// (when the range is the same) and the corner table (when the corner terms are too).
    pub(super) fn sharing(
        plate: &SinglePlate,
        params: &HoledParams,
        shared: Option<&Setup>,
    ) -> Result<Self, RecedingError> {
        let (a, d) = (plate.hole_radius(), plate.half_thickness());
        if a <= 0.0 {
            return Err(InputError::Parameter {
                field: "hole radius A",
                value: a,
                reason: "the holed two-plate route needs A > 0 (use the receding solver)",
            }
            .into());
        }
        if plate.outer_radius() != OuterRadius::Infinite {
            return Err(InputError::Parameter {
                field: "outer radius C",
                value: f64::NAN,
                reason: "the holed two-plate route supports infinite plates only so far",
            }
            .into());
        }
        let b_over_d = plate.load().outer() / d;
        if b_over_d > super::params::MAX_B_OVER_D {
            return Err(InputError::Parameter {
                field: "load outer radius over plate thickness B/D",
                value: b_over_d,
                reason: "at most 16 for the holed two-plate route (its cost grows like (B/D)²: \
                         4.7 s and 0.6 GB at 16); use the finite elements",
            }
            .into());
        }
        let a_over_d = plate.hole_radius() / d;
        if a_over_d < super::params::MIN_A_OVER_D {
            return Err(InputError::Parameter {
                field: "hole radius over plate thickness A/D",
                value: a_over_d,
                reason: "at least 0.04 for the holed two-plate route (smaller holes left residual \
                         tractions of 1e1-1e4 P on the hole; the receding contact without a hole \
                         is within A² of them: --a 0); use the finite elements",
            }
            .into());
        }
        if params.heights < 4 || params.heights % 2 == 1 || params.heights > 128 {
            return Err(InputError::Parameter {
                field: "Chebyshev heights",
                value: params.heights as f64,
                reason: "an even number in 4..=128",
            }
            .into());
        }
        crate::error::positive("holed xi_l", params.xi_l)?;
        crate::error::positive("holed tail", params.tail)?;
        crate::error::positive("holed hole_decay", params.hole_decay)?;
        let mat = plate.material();
        let nu = mat.poisson_ratio();
        let g = mat.shear_modulus();
        let load = plate.load();
        let p_ref = load.mean_pressure().abs().max(f64::MIN_POSITIVE);
        // a setup of the same plate with the same hole knobs (a variant changing only the
        // heights, ξ_l or the Nyström points) has the same bilateral plate: not solved again
        let bilateral = match shared.filter(|s| s.hole == params.hole && s.a == a && s.d == d) {
            Some(s) => s.bilateral.clone(),
            None => HolePlate::new(plate, &params.hole)?,
        };
        let n = bilateral.info().terms;
        let b = load.outer();
        let tail = params.tail * d;
        let r_max = b + params.reach * d + tail + d;
        // the curve and the corner table up to the radii of a search ending within 2D of B;
        // the search's farther radii take the curve over the whole reach, built on first use
        let r_near = (b + 2.0 * d + tail + d).min(r_max);
        let shared = shared.filter(|s| s.r_max == r_max && s.a == a && s.d == d);
        let (slab_mid, slab_far) = match shared {
            Some(s) => (Arc::clone(&s.slab_mid), Arc::clone(&s.slab_far)),
            None => (
                Arc::new(MidplaneCurve::new(
                    bilateral.slab(),
                    a,
                    r_near,
                    1e-12 * p_ref,
                )?),
                Arc::new(OnceLock::new()),
            ),
        };
        let modes: Vec<Mode> = symmetric_roots(n)
            .iter()
            .map(|x| Mode::new(*x, a, d, nu, g))
            .collect();
        let ct = params.hole.corner_terms;
        let corner = (ct > 0).then(|| CornerLoads::new(a, d, nu, g, ct));
        let z_fit = heights(d, if ct > 0 { 8 * n } else { 4 * n });
        let corner_cols = corner.as_ref().map_or_else(Vec::new, |cl| {
            cl.tractions(a, &z_fit)
                .iter()
                .flat_map(|t| {
                    let mut sr = Vec::new();
                    let mut tau = Vec::new();
                    for c in t {
                        sr.extend([c[0].re, c[0].im, c[1].re, c[1].im]);
                        tau.extend([c[2].re, c[2].im, c[3].re, c[3].im]);
                    }
                    sr.extend(tau);
                    sr
                })
                .collect()
        });
        // Chebyshev points of the first kind on [−D, D]; the upper half are integrated
        let m = params.heights;
        let theta = |j: usize| PI * (j as f64 + 0.5) / m as f64;
        let x_all: Vec<f64> = (0..m).map(|j| theta(j).cos()).collect();
        let w_all: Vec<f64> = (0..m)
            .map(|j| if j % 2 == 0 { 1.0 } else { -1.0 } * theta(j).sin())
            .collect();
        let z_cheb: Vec<f64> = x_all[..m / 2].iter().map(|x| d * x).collect();
        let interp = |odd: bool| -> Vec<Vec<f64>> {
            z_fit
                .iter()
                .map(|&z| {
                    let x = z / d;
                    let mut row = vec![0.0; m / 2];
                    if let Some(j) = x_all.iter().position(|&xj| (xj - x).abs() < 1e-15) {
                        let (k, s) = if j < m / 2 {
                            (j, 1.0)
                        } else {
                            (m - 1 - j, -1.0)
                        };
                        row[k] = if odd { s } else { 1.0 };
                        return row;
                    }
                    let terms: Vec<f64> = (0..m).map(|j| w_all[j] / (x - x_all[j])).collect();
                    let total: f64 = terms.iter().sum();
                    for (j, t) in terms.iter().enumerate() {
                        // the lower point m−1−k mirrors the upper point k
                        let (k, s) = if j < m / 2 {
                            (j, 1.0)
                        } else {
                            (m - 1 - j, -1.0)
                        };
                        row[k] += if odd { s } else { 1.0 } * t / total;
                    }
                    row
                })
                .collect()
        };
        let (interp_even, interp_odd) = (interp(false), interp(true));
        // the corner fields are analytic in a strip of half-width ≈ D about the midplane's
        // r-axis (their corner is D away): 20-point panels of D/2 interpolate them to ~1e-18
        let same_corner = shared
            .filter(|s| s.corner.as_ref().map(|c| c.count()) == corner.as_ref().map(|c| c.count()));
        let corner_table = match same_corner {
            Some(s) => s.corner_table.clone(),
            None => corner.as_ref().map(|cl| {
                let interp = PanelInterp::new(a, r_near, 0.5 * d);
                let grid = interp.grid();
                let rows =
                    cl.midplane_basis_rows(r_near, grid.len(), |xi, row| grid.j0_row(xi, row));
                Arc::new((interp, rows))
            }),
        };
        let xi_h = (params.hole_decay / z_cheb[m / 2 - 1]).max(2.0 * params.xi_l / d);
        // the hole tables depend on the hole ξ-rule, the heights and the tail, not on the modes
        // or the Nyström points: a setup changing only those (the estimate's modes variant)
        // takes the shared setup's, with the panels its radii have built
        let same_rule = shared.filter(|s| {
            (s.nu, s.xi_h, s.xi_l, s.tail) == (nu, xi_h, params.xi_l / d, tail)
                && s.z_cheb == z_cheb
        });
        let hole_tables = same_rule
            .and_then(|s| s.hole_tables.lock().ok().and_then(|t| t.clone()))
            .map_or_else(|| Mutex::new(None), |t| Mutex::new(Some(t)));
        Ok(Self {
            corner_table,
            last_tables: Mutex::new(None),
            hole_tables,
            a,
            d,
            p0: LoadTransform::new(load).eval(0.0),
            p_ref,
            bilateral,
            hole: params.hole,
            slab_mid,
            slab_far,
            modes,
            corner,
            r_max,
            tail,
            z_fit,
            corner_cols,
            z_cheb,
            interp_even,
            interp_odd,
            nu,
            node_scale: (b / (NODES_SPAN * d)).max(1.0),
            xi_h,
            xi_l: params.xi_l / d,
        })
    }

    /// The hole ξ-rule for contact radii up to `c`: ends at ξ_h; 20-point panels of 2.25 periods
    /// (Gauss–Legendre's error on them ≈ (e·ωh/80)^40 ≈ 2e-13) of cos ξ(r ± A) for the crack
    /// loads within c + 8D up to ξ_l, and of the contact edge c beyond (l's transform is its
    /// endpoint expansion there). Built per hole table (module `hole_tables`, c = 2D beyond
    /// its first radius), not for the scan's farthest radius: that rule would be 1.6 (below
    /// ξ_l) to 2.4 (beyond) times as dense near R_o on Table 1 row 1.
    pub(super) fn hole_rule(&self, c: f64) -> HoleRule {
        let (a, d) = (self.a, self.d);
        let width = |omega: f64| (4.5 * PI / omega).min(1.0 / d);
        let mut rule = panels(0.0, self.xi_l, width(c + 8.0 * d + a));
        // beyond ξ_l the kernels are exponentials e^(−ξz), e^(−ξ(D − z)) times quadratics in ξ:
        // no panel of 4/D resolves them worse than (e·4/80)^40 ≈ 1e-32
        let far = (4.5 * PI / (c + a + d)).min(4.0 / d);
        rule.extend(panels(self.xi_l, self.xi_h, far));
        let xi: Vec<(f64, f64, f64, f64, f64)> = rule
            .into_iter()
            .map(|(xi, w)| {
                let x = xi * a;
                let j1 = libm::j1(x);
                (xi, w, libm::j0(x), j1 / x, j1)
            })
            .collect();
        let kernels = xi
            .par_iter()
            .map(|&(xi, ..)| {
                self.z_cheb
                    .iter()
                    .map(|&z| {
                        let k = bottom_kernels(xi, d, z, self.nu);
                        [k.r0, k.r1, k.t]
                    })
                    .collect()
            })
            .collect();
        HoleRule { xi, kernels }
    }

    /// The Nyström points on [0, c] for `n` asked: `n` for loads out to B = 3.5D (all of
    /// Table 1, whose R_o ≤ 3.7D), proportionally more beyond, since the crack field varies on
    /// the scale D and the contact zone spans c/D of it. On (A/D, B/A, ν) = (2.5, 3.5, 0.1)
    /// (B/D = 8.75) the fewer-nodes variant moved R_o by 2e-3, 2e-4, 3e-5 of R_o at 6, 8, 10
    /// points, by 2e-6, 5e-8, 9e-10 at 15, 20, 25.
    pub(super) fn nodes_for(&self, n: usize) -> usize {
        (n as f64 * self.node_scale).ceil() as usize
    }

    /// The bilateral plate's midplane σ_z.
    pub(super) fn s0(&self, r: f64) -> f64 {
        self.slab_sigma_z(r) + self.bilateral.correction_midplane(r)
    }

    /// The slab's midplane σ_z at A ≤ r ≤ `r_max`: from the near curve, or beyond it from the
    /// whole reach's, built on first use (NaN if that fails: [`MidplaneCurve::new`] refuses
    /// only lengths beyond 40 000 D, far beyond B + reach + tail).
    pub(super) fn slab_sigma_z(&self, r: f64) -> f64 {
        let near = self.slab_mid.eval(r);
        if near.error.is_finite() {
            return near.value;
        }
        self.slab_far
            .get_or_init(|| {
                let tol = 1e-12 * self.p_ref;
                MidplaneCurve::new(self.bilateral.slab(), self.a, self.r_max, tol).ok()
            })
            .as_ref()
            .map_or(f64::NAN, |c| c.eval(r).value)
    }
}
