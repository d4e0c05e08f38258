//! A deck as read: the cards of Appendix B or C after node and element generation, each item
//! with the line of the card it came from.
//!
//! # Accuracy
//!
//! Plain data, read and written back unchanged: `tests/io/exact.rs`
//! (`emitted_table1_deck_is_stable`).
//!
//! # Cost
//!
//! None.

use serde::Serialize;

/// Which program the deck was written for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Appendix {
    /// Appendix B: isotropic elastic, no temperatures.
    B,
    /// Appendix C: thermal strains (temperature tables, nodal temperatures, reference temperature).
    C,
}

/// Boundary code of a nodal card (columns 6–10).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Code {
    /// 0: XR and XZ are loads.
    Free,
    /// 1: XR is the r-displacement, XZ the z-load.
    R,
    /// 2: XR is the r-load, XZ the z-displacement.
    Z,
    /// 3: XR and XZ are displacements.
    Both,
    /// A skew roller at this angle in degrees, in [−180, −0.001]: XR is the load along s and XZ
    /// the displacement along n, s = (cos α, sin α), n = (−sin α, cos α).
    Skew(f64),
}

impl Code {
    /// The code as the deck writes it.
    pub fn value(self) -> f64 {
        match self {
            Self::Free => 0.0,
            Self::R => 1.0,
            Self::Z => 2.0,
            Self::Both => 3.0,
            Self::Skew(a) => a,
        }
    }
}

/// A material: identification, initial stresses (echoed; the programs use them only with
/// NORM ≠ 0), and its table of (T, E, ν, α) rows (Appendix B: one row, T = α = 0).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeckMaterial {
    /// Material number (1..=number of materials).
    pub id: usize,
    /// Initial σ_z.
    pub sigma_z0: f64,
    /// Initial σ_r.
    pub sigma_r0: f64,
    /// Rows (T, E, ν, α), T increasing.
    pub table: Vec<[f64; 4]>,
    /// Line of the material's first card.
    pub line: usize,
}

/// A nodal point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeckNode {
    /// Node number (from 1).
    pub n: usize,
    /// Boundary code.
    pub code: Code,
    /// Radius.
    pub r: f64,
    /// Axial coordinate.
    pub z: f64,
    /// Load or displacement along r (or s), per the code; loads per radian.
    pub xr: f64,
    /// Load or displacement along z (or n), per the code; loads per radian.
    pub xz: f64,
    /// Temperature (Appendix C; 0 in Appendix B).
    pub t: f64,
    /// Line of the node's card; for a generated node, the line of the card that closed the gap.
    pub line: usize,
    /// True if the node was generated (no card of its own).
    pub generated: bool,
}

/// An element: nodes I, J, K, L counter-clockwise (a triangle repeats K: I, J, K, K).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeckElement {
    /// Element number (from 1).
    pub n: usize,
    /// Node numbers I, J, K, L (from 1).
    pub nodes: [usize; 4],
    /// Material number.
    pub material: usize,
    /// Line of the element's card, or of the card that closed the generation gap.
    pub line: usize,
    /// True if generated.
    pub generated: bool,
}

impl DeckElement {
    /// True for a triangle (K = L).
    pub fn is_triangle(&self) -> bool {
        self.nodes[2] == self.nodes[3]
    }
}

/// A pressure card: uniform normal pressure p on the edge I→J, the element on its left; p > 0
/// pushes on the body (a tensile traction is a negative pressure).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PressureCard {
    /// First node.
    pub i: usize,
    /// Second node.
    pub j: usize,
    /// Pressure.
    pub p: f64,
    /// Line of the card.
    pub line: usize,
}

/// One deck.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Deck {
    /// Appendix B or C.
    pub appendix: Appendix,
    /// The title card (columns 1–72), trailing blanks removed.
    pub title: String,
    /// Line of the title card.
    pub line: usize,
    /// NORM of the control card (only 0 is accepted: "use NORM = 0 for this application").
    pub norm: i64,
    /// Reference (stress-free) temperature (Appendix C; 0 in Appendix B).
    pub t_ref: f64,
    /// Materials, in number order (`materials[k].id == k + 1`).
    pub materials: Vec<DeckMaterial>,
    /// Nodes, in number order (`nodes[k].n == k + 1`).
    pub nodes: Vec<DeckNode>,
    /// Elements, in number order.
    pub elements: Vec<DeckElement>,
    /// Pressure cards, in deck order.
    pub pressures: Vec<PressureCard>,
}
