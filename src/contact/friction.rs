//! Coulomb friction on the interface: the frictional contact problem on the interface unknowns.
//!
//! With the plates factorized once (as for [`super::lcp`]), each interface point i has a normal
//! pair force λₙ,ᵢ (> 0 compression) and a tangential one λₜ,ᵢ (the radial force on the upper
//! plate, outward > 0; the opposite on the lower plate). The flexibility F (normal unknowns first,
//! then the tangential ones) gives the gaps g and the relative tangential displacements
//! s = u_upper − u_lower (the slip, outward > 0) as g, s = g⁰, s⁰ + F λ. The conditions are the
//! Signorini conditions of the report's eq. 2.7 and Coulomb's law with coefficient μ:
//!
//! g ≥ 0, λₙ ≥ 0, g λₙ = 0;  |λₜ| ≤ μ λₙ, and λₜ = −μ λₙ sign(s) where s ≠ 0,
//!
//! i.e. λₜ = Proj_[−μλₙ, μλₙ](λₜ − c s) for any c > 0. A point held closed by a support (the
//! stack's reference point, [`FrictionProblem::held`]) has only a tangential unknown; its normal
//! force is the load W minus the other normal forces (equilibrium of the upper plate).
//! Units: those of F (length per force); forces are totals around the circle.
//!
//! **Loading path.** Bolt tightening is proportional: the load grows as t·(load) from t = 0
//! with the plates flat and touching, so g⁰ and s⁰ are t times their values at t = 1 and the
//! initial gap is zero. The conditions above are positively homogeneous of degree one in
//! (λ, g, s): if (λ, g, s) solves the problem at t = 1, then t·(λ, g, s) solves it at every t,
//! with the same contact, stick and slip zones, and the slip grows in one direction only. The
//! rate form of Coulomb's law (λₜ opposes the slip *increment*) is then met by the total
//! solution, so one solve of the total problem is the proportional-loading solution — the
//! receding-contact argument of the report carried over to friction (Spence 1975 for the
//! self-similar Hertz problem with friction makes the same step). Computed, not only argued:
//! [`solve_friction_incremental`] loads in n steps with the history-dependent law and returns
//! the same forces for every n (`tests/contact/friction.rs`,
//! `proportional_loading_needs_one_increment`).
//!
//! **Method.** Primal–dual active sets (semismooth Newton on the projection equations): each
//! point is open (λ = 0), sticking (g = 0, s = 0) or slipping out/in (g = 0,
//! λₜ = ∓μλₙ); on the current states one dense LU solve gives λ; then a closed point that
//! pulls opens, an open point that penetrates closes (sticking when its slip is below μ times
//! its penetration, else slipping the way it moves), a sticking point beyond the
//! cone slips in the direction its force says, a slipping point whose slip runs against its
//! force sticks. Stop when no condition is violated beyond the relative tolerance of
//! [`LcpParams::tolerance`]. A state that repeats (a cycle) switches to changing the first
//! violated point only; a repeat then, or [`LcpParams::max_iterations`], ends with
//! [`ContactError::NotConverged`].
//!
//! # Accuracy
//!
//! Against enumeration of every open/stick/slip state of small problems
//! (`tests/contact/friction.rs`, `agrees_with_enumeration_of_all_states`); on the two-plate
//! model μ = 0 gives the frictionless model and μ = 10³ the welded one (same file).
//!
//! # Cost
//!
//! One LU of the closed points' size per iteration; `examples/21_friction.rs` prints
//! the two-plate time against the frictionless model.
//!
//! ```
//! use boltzone::contact::friction::{solve_friction, FrictionProblem, PointState};
//! use boltzone::contact::LcpParams;
//! use nalgebra::{DMatrix, DVector};
//! // One point: normal and tangential flexibility 1, uncoupled; pressed in by 1, pushed
//! // outward by 1; μ = 0.5 lets it slip outward with λₜ = −0.5 and s = 0.5.
//! let p = FrictionProblem {
//!     flexibility: DMatrix::identity(2, 2),
//!     gap0: DVector::from_vec(vec![-1.0, 1.0]),
//!     mu: 0.5,
//!     held: None,
//! };
//! let s = solve_friction(&p, &LcpParams::default())?;
//! let f = &s.lcp.force;
//! assert!((f[0] - 1.0).abs() < 1e-15 && (f[1] + 0.5).abs() < 1e-15);
//! assert_eq!(s.state, vec![PointState::SlipOut]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use super::lcp::{LcpInfo, LcpParams, LcpSolution};
use crate::error::InputError;
use nalgebra::{DMatrix, DVector};
use serde::Serialize;
use std::collections::HashSet;
use std::time::Instant;

/// A frictional interface problem (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionProblem {
    /// Flexibility F, symmetric positive definite, (2m + h) square: the m normal unknowns, then
    /// the m tangential ones in the same point order, then (h = 1) the held point's tangential.
    pub flexibility: DMatrix<f64>,
    /// Gaps and slips under the load alone, in the order of F.
    pub gap0: DVector<f64>,
    /// Coulomb coefficient μ ≥ 0.
    pub mu: f64,
    /// The load W pressing the held point when every other normal force is zero: its normal
    /// force is W − Σ λₙ. None: no held point (h = 0).
    pub held: Option<f64>,
}

/// The state of an interface point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PointState {
    /// Open: no forces.
    Open,
    /// In contact, no slip: |λₜ| ≤ μ λₙ.
    Stick,
    /// In contact, the upper plate slips outward (s > 0): λₜ = −μ λₙ.
    SlipOut,
    /// In contact, the upper plate slips inward (s < 0): λₜ = +μ λₙ.
    SlipIn,
}

impl PointState {
    /// Whether the point is in contact.
    pub fn closed(self) -> bool {
        self != Self::Open
    }

    /// The code of the CSV column `state`: 0 open, 1 stick, 2 slip (either direction).
    pub fn code(self) -> f64 {
        match self {
            Self::Open => 0.0,
            Self::Stick => 1.0,
            Self::SlipOut | Self::SlipIn => 2.0,
        }
    }
}

/// The frictional record of a two-plate solution ([`super::two_plate::TwoPlateSolution`]),
/// per interface node of the finest level.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionZones {
    /// The friction coefficient μ.
    pub mu: f64,
    /// Slip s = u_upper − u_lower (length; outward > 0; 0 where sticking).
    pub slip: Vec<f64>,
    /// Open, stick or slip at each node.
    pub state: Vec<PointState>,
}

impl FrictionZones {
    /// Runs of nodes that stick (`slip` false) or slip (true) as [first radius, last radius]
    /// intervals, node to node, in the unit of `radius` (the interface nodes' radii).
    pub fn zones(&self, radius: &[f64], slip: bool) -> Vec<[f64; 2]> {
        let want = |st: PointState| match st {
            PointState::Stick => !slip,
            PointState::SlipOut | PointState::SlipIn => slip,
            PointState::Open => false,
        };
        let mut out: Vec<[f64; 2]> = Vec::new();
        let mut prev = false;
        for (&st, &r) in self.state.iter().zip(radius) {
            let on = want(st);
            match (on, prev, out.last_mut()) {
                (true, true, Some(z)) => z[1] = r,
                (true, _, _) => out.push([r, r]),
                _ => {}
            }
            prev = on;
        }
        out
    }

    /// The largest |slip| inside the contact zone (closed nodes under pressure; `pressure` the
    /// interface pressure of each node, compression > 0), in the unit of [`FrictionZones::slip`].
    pub fn max_slip(&self, pressure: &[f64]) -> f64 {
        (0..self.slip.len().min(pressure.len()))
            .filter(|&i| self.state[i].closed() && pressure[i] > 0.0)
            .fold(0.0, |m, i| m.max(self.slip[i].abs()))
    }
}

/// The solution of a [`FrictionProblem`].
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionSolution {
    /// Forces λ and gaps and slips g⁰ + F λ in the order of F, the closed points, and the
    /// iteration record (`residual`: the largest relative violation of the conditions, see
    /// [`FrictionProblem::residual`]).
    pub lcp: LcpSolution,
    /// The state of each point (m, then the held point).
    pub state: Vec<PointState>,
}

impl FrictionProblem {
    /// Points with a normal unknown (m).
    pub fn points(&self) -> usize {
        (self.gap0.len() - usize::from(self.held.is_some())) / 2
    }

    /// Normal force of point k (k = m: the held point) under the forces `x`.
    pub fn normal_force(&self, k: usize, x: &DVector<f64>) -> f64 {
        let m = self.points();
        match self.held {
            Some(w) if k == m => w - x.rows(0, m).sum(),
            _ => x[k],
        }
    }

    /// Largest relative violation of the conditions of the module docs at (`x`, `g`): negative
    /// normal forces and gaps, g λₙ, the cone |λₜ| − μ λₙ, and the slip against its force
    /// (slip × (λₜ + μλₙ sign s)); forces relative to max|λ|, gaps and slips to max|g⁰|.
    pub fn residual(&self, x: &DVector<f64>, g: &DVector<f64>) -> f64 {
        let m = self.points();
        let lf = x.amax().max(f64::MIN_POSITIVE);
        let lg = self.gap0.amax().max(f64::MIN_POSITIVE);
        let mut worst: f64 = 0.0;
        for k in 0..m + usize::from(self.held.is_some()) {
            let n = self.normal_force(k, x) / lf;
            let t = x[m + k] / lf;
            let s = g[m + k] / lg;
            if k < m {
                let gn = g[k] / lg;
                worst = worst.max(-gn).max((n * gn).abs());
            }
            worst = worst.max(-n).max(t.abs() - self.mu * n);
            if s != 0.0 {
                worst = worst.max((s * (t + self.mu * n * s.signum())).abs());
            }
        }
        worst
    }

    fn check(&self) -> Result<(), InputError> {
        let n = self.gap0.len();
        let h = usize::from(self.held.is_some());
        if self.flexibility.nrows() != n || self.flexibility.ncols() != n || (n - h) % 2 != 0 {
            return Err(InputError::Parameter {
                field: "friction problem size",
                value: n as f64,
                reason: "the flexibility must be square, of size 2m (+1 with a held point)",
            });
        }
        if !(self.mu >= 0.0 && self.mu.is_finite()) {
            return Err(InputError::Parameter {
                field: "friction coefficient mu",
                value: self.mu,
                reason: "must be finite and ≥ 0",
            });
        }
        let data = self.gap0.iter().chain(self.flexibility.iter());
        match data.chain(self.held.iter()).find(|x| !x.is_finite()) {
            Some(x) => Err(InputError::NotFinite {
                field: "friction problem data",
                value: *x,
            }),
            None => Ok(()),
        }
    }

    /// Forces and gaps with every point in its `state` (module docs, Method).
    fn solve_on(&self, state: &[PointState]) -> Result<(DVector<f64>, DVector<f64>), ContactError> {
        let m = self.points();
        let n = self.gap0.len();
        let mut idx: Vec<usize> = (0..m).filter(|&i| state[i].closed()).collect();
        let tang: Vec<usize> = (0..state.len())
            .filter(|&k| state[k].closed())
            .map(|k| m + k)
            .collect();
        idx.extend(&tang);
        let mut x = DVector::zeros(n);
        if !idx.is_empty() {
            let size = idx.len();
            let mut a = DMatrix::zeros(size, size);
            let mut b = DVector::zeros(size);
            for (row, &u) in idx.iter().enumerate() {
                let sign = match (u >= m).then(|| state[u - m]) {
                    Some(PointState::SlipOut) => Some(-1.0),
                    Some(PointState::SlipIn) => Some(1.0),
                    _ => None,
                };
                match sign {
                    // λₜ − σ μ N = 0 with N = λₙ (or W − Σλₙ for the held point)
                    Some(sigma) => {
                        let k = u - m;
                        a[(row, row)] = 1.0;
                        let c = sigma * self.mu;
                        match self.held {
                            Some(w) if k == m => {
                                for (col, _) in idx.iter().enumerate().filter(|(_, &v)| v < m) {
                                    a[(row, col)] += c;
                                }
                                b[row] = c * w;
                            }
                            _ => {
                                if let Some(col) = idx.iter().position(|&v| v == k) {
                                    a[(row, col)] -= c;
                                }
                            }
                        }
                    }
                    // g = 0 (normal) or s = 0 (stick)
                    None => {
                        for (col, &v) in idx.iter().enumerate() {
                            a[(row, col)] = self.flexibility[(u, v)];
                        }
                        b[row] = -self.gap0[u];
                    }
                }
            }
            let sol = a.lu().solve(&b).ok_or(ContactError::NotConverged {
                iterations: 0,
                violations: size,
            })?;
            for (k, &u) in idx.iter().enumerate() {
                x[u] = sol[k];
            }
        }
        let g = &self.gap0 + &self.flexibility * &x;
        Ok((x, g))
    }
}

/// Solves the frictional problem by primal–dual active sets (module docs), starting with the
/// points that penetrate under the load alone (and the held point) sticking.
pub fn solve_friction(
    p: &FrictionProblem,
    params: &LcpParams,
) -> Result<FrictionSolution, ContactError> {
    p.check()?;
    params.check()?;
    let start = Instant::now();
    let m = p.points();
    let nt = m + usize::from(p.held.is_some());
    let mut state: Vec<PointState> = (0..nt)
        .map(|k| {
            if k == m || p.gap0[k] < 0.0 {
                PointState::Stick
            } else {
                PointState::Open
            }
        })
        .collect();
    let tol_g = params.tolerance * p.gap0.amax().max(f64::MIN_POSITIVE);
    let mut seen = HashSet::new();
    let mut info = LcpInfo::default();
    for it in 1..=params.max_iterations {
        info.iterations = it;
        let (x, g) = p.solve_on(&state).map_err(|e| match e {
            ContactError::NotConverged { violations, .. } => ContactError::NotConverged {
                iterations: it,
                violations,
            },
            e => e,
        })?;
        let tol_l = params.tolerance * x.amax().max(f64::MIN_POSITIVE);
        let next: Vec<PointState> = (0..nt)
            .map(|k| {
                let (st, t, s) = (state[k], x[m + k], g[m + k]);
                let n = p.normal_force(k, &x);
                match st {
                    PointState::Open if g[k] < -tol_g => closing(p.mu, g[k], s),
                    PointState::Open => st,
                    _ if k < m && x[k] < -tol_l => PointState::Open,
                    PointState::Stick if t.abs() > p.mu * n + tol_l => {
                        if t > 0.0 {
                            PointState::SlipIn
                        } else {
                            PointState::SlipOut
                        }
                    }
                    PointState::SlipOut if s < -tol_g => PointState::Stick,
                    PointState::SlipIn if s > tol_g => PointState::Stick,
                    _ => st,
                }
            })
            .collect();
        let violated: Vec<usize> = (0..nt).filter(|&k| next[k] != state[k]).collect();
        if violated.is_empty() {
            info.residual = p.residual(&x, &g);
            info.active = (0..m).filter(|&k| state[k].closed()).count();
            info.time = start.elapsed();
            let active = state[..m].iter().map(|s| s.closed()).collect();
            return Ok(FrictionSolution {
                lcp: LcpSolution {
                    force: x,
                    gap: g,
                    active,
                    info,
                },
                state,
            });
        }
        seen.insert(state.clone());
        let mut candidate = next;
        if info.murty || seen.contains(&candidate) {
            // a block change would revisit a state: change the first violated point only
            info.murty = true;
            candidate = state.clone();
            let k = violated[0];
            candidate[k] = match (state[k], g.get(k)) {
                (PointState::Open, _) => closing(p.mu, g[k], g[m + k]),
                _ if k < m && x[k] < -tol_l => PointState::Open,
                (PointState::Stick, _) if x[m + k] > 0.0 => PointState::SlipIn,
                (PointState::Stick, _) => PointState::SlipOut,
                _ => PointState::Stick,
            };
            info.changes += 1;
            if seen.contains(&candidate) {
                return Err(ContactError::NotConverged {
                    iterations: it,
                    violations: violated.len(),
                });
            }
        } else {
            info.changes += violated.len();
        }
        state = candidate;
    }
    Err(ContactError::NotConverged {
        iterations: params.max_iterations,
        violations: nt,
    })
}

/// The state of an open point that penetrates by −`g` > 0 while its faces move apart by `s`:
/// the projection rule of the module docs with λ = 0, i.e. sticking when |s| < μ|g|, else
/// slipping the way s runs.
fn closing(mu: f64, g: f64, s: f64) -> PointState {
    if s.abs() < -mu * g {
        PointState::Stick
    } else if s > 0.0 {
        PointState::SlipOut
    } else {
        PointState::SlipIn
    }
}

/// The proportional-loading path in `steps` equal increments with the rate form of Coulomb's
/// law (λₜ opposes the slip increment s − s_previous), returning the state at full load. By
/// the module docs' argument the result does not depend on `steps`.
pub fn solve_friction_incremental(
    p: &FrictionProblem,
    params: &LcpParams,
    steps: usize,
) -> Result<FrictionSolution, ContactError> {
    if steps == 0 {
        return Err(InputError::Parameter {
            field: "increments",
            value: 0.0,
            reason: "need at least one load increment",
        }
        .into());
    }
    let m = p.points();
    let mut slip = DVector::<f64>::zeros(p.gap0.len() - m);
    let mut last = None;
    for k in 1..=steps {
        let t = k as f64 / steps as f64;
        let mut step = p.clone();
        step.gap0 *= t;
        step.held = p.held.map(|w| w * t);
        // slips are measured from the previous increment's
        for (j, s) in slip.iter().enumerate() {
            step.gap0[m + j] -= s;
        }
        let mut sol = solve_friction(&step, params)?;
        for (j, s) in slip.iter().enumerate() {
            sol.lcp.gap[m + j] += s;
        }
        slip.copy_from(&sol.lcp.gap.rows(m, slip.len()));
        last = Some(sol);
    }
    last.ok_or(ContactError::NotConverged {
        iterations: 0,
        violations: 0,
    })
}
