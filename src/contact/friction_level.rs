//! Coulomb friction on one mesh level of the two-plate model: which interface points carry
//! which unknowns, the load on the held reference point, and the choice of the window from one
//! level to the next.
//!
//! With friction every closed point has a tangential unknown, so the level cannot tie points
//! well inside the contact zone as the frictionless and welded models do (a tied pair would
//! transmit shear without the Coulomb bound). The window therefore reaches from A to past the
//! previous level's R_o, and only the stack's reference point stays tied: held axially by
//! supports on both plates when nothing else holds the stack (free edge, pressure load), its
//! radial motion free and its tangential force an unknown bounded by μ(W − Σλₙ), where W is the
//! total load on the upper plate (its axial equilibrium); with a fixed edge or a nut
//! displacement the supports hold the stack and no point is tied. Units and signs as in
//! [`super::level`]; the solver is [`super::friction`].
//!
//! # Accuracy
//!
//! `tests/contact/friction.rs`: μ = 0 gives the frictionless model
//! (`mu_zero_is_the_frictionless_model`), a large μ the welded one
//! (`mu_large_is_the_welded_model_for_table2_case5`,
//! `fixed_edge_and_nut_displacement_reach_the_welded_limit`, the held and unheld reference point),
//! complementarity node by node (`complementarity_holds_node_by_node_on_table2_case5`).
//!
//! # Cost
//!
//! A window from A to past R_o on every level (more LCP unknowns than the frictionless model);
//! `examples/21_friction.rs` prints the time against the frictionless model.
//!
//! ```
//! use boltzone::contact::two_plate::{solve, InterfaceModel, TwoPlateParams};
//! use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
//! let steel = Material::new(30e6, 0.3)?;
//! let joint = Joint::new(0.1, OuterRadius::Finite(1.0), Plate::new(0.1, steel)?,
//!     Plate::new(0.2, steel)?, FaceLoad::uniform(0.1, 0.2, 1.0)?)?;
//! let params = TwoPlateParams { interface: InterfaceModel::Friction { mu: 0.3 },
//!     tolerance: 1e-2, ..Default::default() };
//! let s = solve(&joint, &params)?;
//! let f = s.friction.as_ref().ok_or("no friction record")?;
//! assert!(s.converged && f.state.iter().any(|st| st.closed()));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use super::friction::{solve_friction, FrictionProblem, FrictionZones, PointState};
use super::lcp::LcpSolution;
use super::level_types::{LevelSetup, LevelSolution, MeshedJoint};
use crate::fem::Loads;
use nalgebra::{DMatrix, DVector};

/// The tied point whose tangential motion is an unknown: the first tied point when it is held
/// by supports (`fix_rigid`) and friction is on.
pub(crate) fn held(setup: &LevelSetup<'_>, mu: Option<f64>) -> Option<usize> {
    (mu.is_some() && setup.fix_rigid)
        .then(|| setup.tied.first().copied())
        .flatten()
}

/// Solves the level's frictional problem from its flexibility and gaps under the load (normal
/// unknowns of the window, their tangential ones, then the held point's), returning it in the
/// layout of the welded LCP and the state of every interface node.
pub(crate) fn solve(
    model: &MeshedJoint,
    setup: &LevelSetup<'_>,
    mu: f64,
    flexibility: DMatrix<f64>,
    gap0: DVector<f64>,
    loads: &Loads,
) -> Result<(LcpSolution, Vec<PointState>), ContactError> {
    let held_line = held(setup, Some(mu));
    // the load pressing the upper plate down (z up: its face forces are negative)
    let w = held_line.map(|_| {
        -model
            .mesh
            .top(model.upper)
            .iter()
            .map(|&n| loads.forces()[n][1])
            .sum::<f64>()
    });
    let problem = FrictionProblem {
        flexibility,
        gap0,
        mu,
        held: w,
    };
    let s = solve_friction(&problem, &setup.lcp)?;
    let m = setup.window.len();
    let mut states = vec![PointState::Open; model.mesh.radial_nodes().len()];
    for (k, &i) in setup.window.iter().enumerate() {
        states[i] = s.state[k];
    }
    if let Some(i) = held_line {
        states[i] = s.state[m];
    }
    Ok((s.lcp, states))
}

/// The next level's tied points and window under friction: the reference alone (when
/// `fix_rigid`) and every other point out to R_o + 6 elements of the previous level.
pub(crate) fn plan(
    r: &[f64],
    reference: usize,
    fix_rigid: bool,
    reach: f64,
) -> (Vec<usize>, Vec<usize>) {
    let tied: Vec<usize> = if fix_rigid { vec![reference] } else { vec![] };
    let window = (0..r.len())
        .filter(|&i| !tied.contains(&i) && r[i] <= reach)
        .collect();
    (tied, window)
}

/// The friction record of a solved level (None without friction): states and the slip
/// u_upper − u_lower at each interface node (open nodes: their relative radial motion).
pub(crate) fn zones(model: &MeshedJoint, sol: &LevelSolution, mu: f64) -> Option<FrictionZones> {
    let state = sol.friction.clone()?;
    let slip = (0..sol.radius.len())
        .map(|i| match model.pair(i) {
            (up, Some(low)) => sol.u[up][0] - sol.u[low][0],
            (_, None) => 0.0,
        })
        .collect();
    Some(FrictionZones { mu, slip, state })
}
