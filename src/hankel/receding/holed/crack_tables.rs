//! The tables of one trial contact radius of the holed two-plate model (module `crack`):
//! the Nyström ξ-rule, the t-rule on [0, c] and l's s-rule on [c, c + tail], the cosine and J₀
//! rows on them, the hole's ξ-rule and its rows, and H_l's weights ([`RadiusTables`]). They
//! depend on the radius c and the setup only, not on the Nyström points n nor on a prescribed
//! lift: the setup keeps the last radius's (`Setup::radius_tables`, module `setup_tables`), which the estimate's
//! fewer-nodes variant (at R_o, where the search ended), the pressure's solve at R_o and the
//! finite rim's two solves per radius (module `rim`) take instead of rebuilding them.
//!
//! # Accuracy
//!
//! The same tables as before they were kept: R_o bit for bit the same
//! (`tests/hankel/two_plate_hole_fast.rs`; module [`super`]'s Cost).
//!
//! # Cost
//!
//! Most of a radius's cost (module [`super`]'s Cost, where the time goes); timed by
//! example 19.
//!
//! ```
//! // Internal to the route; reached through its entry point:
//! use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
//! let _ = (two_plate_hole, HoledParams::default());
//! ```

use super::hole_tables::HoleTable;
use crate::hankel::receding::system::XiRule;
use crate::numerics::panel_grid::PanelInterp;
use num_complex::Complex64;
use std::sync::Arc;

/// The tables of one contact radius (module docs).
pub(super) struct RadiusTables {
    /// The Nyström ξ-rule and its nodes and kernel weights.
    pub(super) rule: XiRule,
    pub(super) xi_r: Vec<f64>,
    pub(super) a_r: Vec<f64>,
    pub(super) b_r: Vec<f64>,
    /// l's panels on [c, c + tail] and their Gauss rule (s, w).
    pub(super) lint: PanelInterp,
    pub(super) s_rule: Vec<(f64, f64)>,
    /// The correction's midplane σ_z per mode and per corner column at the s-rule's nodes.
    pub(super) mode_mid: Vec<Vec<Complex64>>,
    pub(super) corner_mid: Vec<Vec<f64>>,
    /// The bilateral plate's midplane σ_z at the s-rule's nodes.
    pub(super) s0: Vec<f64>,
    /// The hole's tables (`Setup::hole_table`, module `setup_tables`) and their G and H at the t- and s-rule's
    /// nodes (H times w·s).
    pub(super) hole: Arc<HoleTable>,
    pub(super) hole_t: Vec<Vec<f64>>,
    pub(super) hole_s: Vec<Vec<f64>>,
    /// The t-rule on [0, c] (t, w).
    pub(super) t_rule: Vec<(f64, f64)>,
    /// cos ξt and cos ξt − 1, one row per node of the Nyström rule.
    pub(super) cos_t: Vec<Vec<f64>>,
    pub(super) cosm1_t: Vec<Vec<f64>>,
    /// The Nyström rule's nodes up to ξ_l and their s-weights w·s·J₀(ξs), w·s·(J₀ − 1); beyond,
    /// (J₀(ξc), J₁(ξc)) for l's endpoint expansion.
    pub(super) rule_low: usize,
    pub(super) rule_j: Vec<(Vec<f64>, Vec<f64>)>,
    pub(super) rule_jc: Vec<(f64, f64)>,
    /// (J₀(ξc), J₁(ξc)) on the hole rule beyond ξ_l.
    pub(super) hole_jc: Vec<(f64, f64)>,
    /// H_l's weights on l's nodes per t-node, and at t = c.
    pub(super) h_rows: Vec<Vec<f64>>,
    pub(super) h_edge: Vec<f64>,
}
