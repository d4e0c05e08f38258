//! The input of the two-plate model ([`super::two_plate::solve`]): how the plates interact,
//! what presses them, how the outer edge is held, and the knobs of the level study. Kept apart
//! from the driver so that the level-by-level machinery (module `refine`) can read them
//! without importing the driver.
//!
//! # Accuracy
//!
//! Plain data; the models it selects are measured in `tests/contact/two_plate.rs`
//! (`unequal_plates_welded_and_frictionless`, `report_load_variants`,
//! `bad_parameters_are_typed_errors`).
//!
//! # Cost
//!
//! None: the driver's cost is in `cargo bench --bench contact`.

use super::lcp::LcpParams;
use crate::error::InputError;
use crate::fem::ElementKind;
use serde::Serialize;

/// How the two plates interact inside the contact zone.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum InterfaceModel {
    /// u and w tied where in contact (the report's model).
    Welded,
    /// Only w tied, unilaterally; no shear.
    Frictionless,
    /// Unilateral contact with Coulomb friction of coefficient `mu` ≥ 0 ([`super::friction`]).
    Friction {
        /// The friction coefficient μ.
        mu: f64,
    },
}

impl InterfaceModel {
    /// μ of the frictional model, None for the others.
    pub fn friction_coefficient(&self) -> Option<f64> {
        match *self {
            Self::Friction { mu } => Some(mu),
            _ => None,
        }
    }
}

/// What presses the plates together.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Loading {
    /// The joint's face pressure on both outer faces over A..B.
    Pressure,
    /// A uniform axial displacement δ of each outer face over A..B toward the interface
    /// (report Fig. 21: 50 µin under each nut); u is free there.
    NutDisplacement(f64),
}

/// Support of the outer edge r = C.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum EdgeSupport {
    /// Traction-free (the report's standard case).
    Free,
    /// u = w = 0 on r = C for both plates (report Fig. 20(c)).
    Fixed,
}

/// Knobs of [`super::two_plate::solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoPlateParams {
    /// Element (default Q9). Q4, Q4Bbar and the report's Cst4 work as well and are about four
    /// times cheaper per level, but their R_o sequences are erratic: over Table 1 and Table 2
    /// case 5 at the default tolerance their actual error reached 1.3–1.6e-3 (the tolerance is
    /// 5e-4) and exceeded the error estimate by up to 150 times, against at most 2.2e-4 and
    /// 1.2 times with Q9. Trust `r_o_error` with Q9 only.
    pub element: ElementKind,
    /// Interface model for unequal or dissimilar plates (default frictionless); equal plates of
    /// one material use the exact symmetric model whatever this says.
    pub interface: InterfaceModel,
    /// Load (default: the joint's face pressure).
    pub loading: Loading,
    /// Outer edge (default free).
    pub edge: EdgeSupport,
    /// Wanted relative error of R_o (default 5e-4 = 0.05 %).
    pub tolerance: f64,
    /// Fewest mesh levels (default 3, so that a convergence rate is observed).
    pub min_levels: usize,
    /// Most mesh levels (default 9).
    pub max_levels: usize,
    /// Element size at R_o, A and B on the first level, as a fraction of the thinner plate's
    /// D (default 0.25); halved on each further level. (A load narrower than that is one
    /// element wide on the first level: A and B are always nodes. Over the design map, first
    /// sizes of 0.125, 0.25 and 0.5 D, and the earlier min(0.25 D, B − A), all met the
    /// tolerance; 0.25 D was the cheapest.)
    pub coarse: f64,
    /// The first level's LCP window reaches from A to B + `window`·D (thickest plate; default
    /// 3); it doubles while points beyond it would penetrate.
    pub window: f64,
    /// Mesh both plates even for a symmetric joint (default false; for cross-checks).
    pub both_plates: bool,
    /// LCP knobs.
    pub lcp: LcpParams,
    /// R_o of each level from the fitted contact edge ([`super::edge_fit`]: the root of the
    /// edge force over trial edges, extrapolated in h, with a floor of 5e-7 R_o instead of
    /// 2e-5) where it applies (frictionless or symmetric contact), else from the gap's shape
    /// (default false). Its bars held on the random plates of example 22 from 1e-4 to 1e-6
    /// (docs/fem.md); it needs more levels (the route layer allows 10 below a tolerance of
    /// 3e-5, `route::two_plate::Question::fem_params`) and at the default tolerance costs 2–3×
    /// the gap-shape study.
    pub fitted_edge: bool,
}

impl Default for TwoPlateParams {
    fn default() -> Self {
        Self {
            element: ElementKind::Q9,
            interface: InterfaceModel::Frictionless,
            loading: Loading::Pressure,
            edge: EdgeSupport::Free,
            tolerance: 5e-4,
            min_levels: 3,
            max_levels: 9,
            coarse: 0.25,
            window: 3.0,
            both_plates: false,
            lcp: LcpParams::default(),
            fitted_edge: false,
        }
    }
}

/// Checks the knobs of `p` (each message names the field and the value).
pub(crate) fn check(p: &TwoPlateParams) -> Result<(), InputError> {
    let bad = |field, value: f64, reason| {
        Err(InputError::Parameter {
            field,
            value,
            reason,
        })
    };
    if !(p.tolerance > 0.0 && p.tolerance < 1.0) {
        return bad(
            "TwoPlateParams::tolerance",
            p.tolerance,
            "must lie in (0, 1)",
        );
    }
    if !(p.coarse > 0.0 && p.coarse <= 1.0) {
        return bad("TwoPlateParams::coarse", p.coarse, "must lie in (0, 1]");
    }
    if !(p.window > 0.0 && p.window.is_finite()) {
        return bad("TwoPlateParams::window", p.window, "must be positive");
    }
    if p.min_levels < 1 || p.max_levels < p.min_levels || p.max_levels > 14 {
        return bad(
            "TwoPlateParams::max_levels",
            p.max_levels as f64,
            "need 1 ≤ min_levels ≤ max_levels ≤ 14",
        );
    }
    if let Some(mu) = p.interface.friction_coefficient() {
        if !(mu >= 0.0 && mu.is_finite()) {
            return bad("TwoPlateParams::interface mu", mu, "must be finite and ≥ 0");
        }
    }
    if let Loading::NutDisplacement(v) = p.loading {
        crate::error::positive("nut displacement", v)?;
    }
    Ok(())
}
