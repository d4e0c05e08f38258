//! One mesh level of the two-plate study ([`super::two_plate`]): the level's mesh solved with
//! its contact window ([`super::refine::solve_adaptive`]) and its R_o read from the solution
//! ([`super::separation::estimate`]: from the gap's shape beyond the last closed node, or the
//! report's own half-interval where its welded-zone rule decided), with the level's record.
//!
//! # Accuracy
//!
//! Through the study: `tests/contact/` (the receding contact and the semi-analytic routes as
//! references, `receding_vs_fe.rs`, `two_plate.rs`).
//!
//! # Cost
//!
//! One contact solve per level (example 04, `cargo bench --bench fem`).
//!
//! ```
//! // Internal to the study; reached through its entry point:
//! use boltzone::contact::two_plate::{solve, TwoPlateParams};
//! let _ = (solve, TwoPlateParams::default());
//! ```

use super::error::ContactError;
use super::level::{LevelSolution, MeshedJoint};
use super::params::TwoPlateParams;
use super::refine::{mesh, solve_adaptive, MeshLayout, PreviousLevel};
use super::separation::{estimate, NodalInterface, SeparationEstimate};
use crate::joint::Joint;
use serde::Serialize;

/// One mesh level of the study.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TwoPlateLevel {
    /// Element size at R_o.
    pub h: f64,
    /// Nodes of the mesh.
    pub nodes: usize,
    /// Reduced unknowns.
    pub dofs: usize,
    /// LCP unknowns (window points).
    pub window: usize,
    /// R_o on this level.
    pub r_o: f64,
    /// Spread of the R_o estimators on this level.
    pub spread: f64,
    /// Active-set iterations.
    pub iterations: usize,
    /// Active-set changes.
    pub changes: usize,
    /// Solves of the level (1 unless the tied set or the window had to be revised).
    pub attempts: usize,
    /// Whether the welded zone came from the report's rule (no Signorini solution found; see
    /// [`super::lcp`]): then `residual` says how far the conditions are from holding.
    pub report_rule: bool,
    /// Relative KKT residual of the interface LCP ([`super::lcp::LcpInfo::residual`]).
    pub residual: f64,
    /// Assembly + factorization + load solve, seconds.
    pub time_linear: f64,
    /// Flexibility solves + LCP + recovery, seconds.
    pub time_contact: f64,
    /// R_o from the fitted contact edge ([`super::edge_fit`]), where it applies.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub r_o_fit: Option<f64>,
    /// R_o from the fitted edge's force at the edge node ([`super::edge_fit`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub r_o_fit_force: Option<f64>,
    /// R_o from K fitted to the reactions of the last closed nodes ([`super::edge_fit`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub r_o_fit_reaction: Option<f64>,
}

/// One solved mesh level and its R_o.
pub(super) struct Level {
    pub(super) model: MeshedJoint,
    pub(super) sol: LevelSolution,
    pub(super) est: SeparationEstimate,
    pub(super) record: TwoPlateLevel,
}

/// Solves the level of element size `h` at R_o, A and B on the plates cut at `g.c`.
pub(super) fn solve_level_at(
    joint: &Joint,
    g: &MeshLayout,
    params: &TwoPlateParams,
    h: f64,
    prev: Option<&PreviousLevel>,
) -> Result<Level, ContactError> {
    let mut model = mesh(
        joint,
        g,
        params.element,
        h,
        prev.map(|p| p.r_o),
        params.fitted_edge,
    )?;
    let thermal = g.thermal.map(|t| t.apply(&mut model)).transpose()?;
    let nodes = model.mesh.n_nodes();
    let (sol, window, attempts) = solve_adaptive(&model, joint, g, params, prev, thermal.as_ref())?;
    // (only when asked: the default study's records and cost stay as they were)
    let fitted = params
        .fitted_edge
        .then(|| fitted_edge(&model, &sol))
        .flatten();
    let est = match separation(&sol) {
        Some(est) => est,
        // Closed out to the rim: full contact, R_o = C (an answer, not a failure).
        None if sol.closed.last() == Some(&true) => SeparationEstimate {
            r_o: g.c,
            r_o_gap_far: None,
            r_o_pressure: None,
            last_contact: g.c,
            first_open: g.c,
            spread: 0.0,
        },
        None => return Err(ContactError::WindowExhausted { radius: g.c }),
    };
    let est = match &fitted {
        Some(f) => SeparationEstimate {
            r_o: f.r_o_force.unwrap_or(f.r_o),
            ..est
        },
        _ => est,
    };
    let record = TwoPlateLevel {
        h,
        nodes,
        dofs: sol.dofs,
        window,
        r_o: est.r_o,
        spread: est.spread,
        iterations: sol.lcp.iterations,
        changes: sol.lcp.changes,
        attempts,
        report_rule: sol.lcp.prefix,
        residual: sol.lcp.residual,
        time_linear: sol.time_linear.as_secs_f64(),
        time_contact: sol.time_contact.as_secs_f64(),
        r_o_fit: fitted.as_ref().map(|f| f.r_o),
        r_o_fit_force: fitted.as_ref().and_then(|f| f.r_o_force),
        r_o_fit_reaction: fitted.as_ref().and_then(|f| f.r_o_reaction),
    };
    Ok(Level {
        model,
        sol,
        est,
        record,
    })
}

/// R_o of a level: from the gap's shape ([`estimate`]); where the welded zone came from the
/// report's rule and the open side penetrates (no smooth separation to fit), or where the
/// contact reaches the node before a finite rim and only the rim's node is open (no two open
/// nodes to extrapolate the gap from: `tests/contact/near_rim.rs`), the midpoint between the
/// last closed and the first open node, ± half that interval (the report's own resolution).
fn separation(sol: &LevelSolution) -> Option<SeparationEstimate> {
    let p = closed_pressure(sol);
    let est = estimate(&NodalInterface {
        radius: &sol.radius,
        pressure: &p,
        gap: &sol.gap,
    });
    let k = p.iter().rposition(|&x| x > 0.0)?;
    // Contact up to the node before the rim, the rim alone open: no two open nodes to
    // extrapolate the gap from, so R_o is bracketed as under the report's rule.
    let rim_alone_open = k + 2 == sol.radius.len();
    if est.is_some() || !(sol.lcp.prefix || rim_alone_open) {
        return est;
    }
    let (r0, r1) = (sol.radius[k], *sol.radius.get(k + 1)?);
    Some(SeparationEstimate {
        r_o: 0.5 * (r0 + r1),
        r_o_gap_far: None,
        r_o_pressure: None,
        last_contact: r0,
        first_open: r1,
        spread: 0.5 * (r1 - r0),
    })
}

/// Pressure on closed nodes (at least the smallest positive number), 0 on open ones.
pub(super) fn closed_pressure(s: &LevelSolution) -> Vec<f64> {
    s.pressure
        .iter()
        .zip(&s.closed)
        .map(|(&p, &c)| if c { p.max(f64::MIN_POSITIVE) } else { 0.0 })
        .collect()
}

/// R_o of the fitted edge ([`super::edge_fit`]) when the level has its Schur complement.
fn fitted_edge(model: &MeshedJoint, sol: &LevelSolution) -> Option<super::edge_fit::EdgeFit> {
    let sys = sol.edge.as_ref()?;
    let step = if model.mesh.kind().nodes() == 9 { 2 } else { 1 };
    let active: Vec<bool> = sys.window.iter().map(|&i| sol.closed[i]).collect();
    super::edge_fit::fit(sys, &sol.radius, &active, step)
}
