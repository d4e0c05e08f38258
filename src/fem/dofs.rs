//! Supports and the degree-of-freedom map (report Appendix B, nodal boundary codes; eqs.
//! A.17–A.20).
//!
//! Every node has two displacement components. By default they are (u_r, u_z) in the global
//! frame; a skew node uses a rotated frame (s, n). Each component is either free (an equation of
//! the system) or prescribed (eliminated: its value moves to the right-hand side, A.20).
//!
//! Boundary codes of the 1970 program and their equivalents here:
//! - 0 free; 1 u_r prescribed ([`Supports::prescribe`] with [`Component::R`]; 1 with value 0 is
//!   [`Supports::roller_r`]); 2 u_z prescribed ([`Supports::roller_z`] for 0); 3 both
//!   ([`Supports::fix`]);
//! - a negative code −θ (0.001 ≤ θ ≤ 180 degrees) is a skew roller ([`Supports::skew`]): the
//!   displacement along n is prescribed and the node is free (or loaded) along s, where
//!   s = (cos α, sin α), n = (−sin α, cos α) in (r, z) and α = the code in degrees (negative).
//!   So −90 is a roller on a vertical wall (n = r) and −180 a roller on a horizontal one (n = −z);
//!   +1 and −179 describe the same line.
//!
//! Eliminating (rather than penalising) constrained components keeps the matrix symmetric
//! positive definite, and the sparsity pattern depends only on WHICH components are constrained:
//! changing prescribed values or materials reuses the symbolic factorization.
//!
//! # Accuracy
//!
//! Exact (a bookkeeping map): `tests/fem/system.rs`
//! (`prescribed_displacement_under_a_flat_punch_gives_exact_reactions_and_axis_is_handled`) and
//! skew rollers in `tests/fem/elements.rs` (`traction_patch_test_with_skew_rollers`,
//! `skew_code_rejects_positive_angles`).
//!
//! # Cost
//!
//! Linear in the nodes.
//!
//! ```
//! use boltzone::fem::{Component, DofMap, Supports};
//! let mut s = Supports::new(3);
//! s.roller_z(0);
//! s.prescribe(1, Component::R, 0.01);
//! s.skew(2, -135.0, 0.0)?;
//! let d = DofMap::new(&s);
//! assert_eq!(d.n_equations(), 3);
//! assert_eq!(d.equation(0, Component::Z), None);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::InputError;

/// A displacement component of a node: radial/axial, or s/n at a skew node.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Component {
    /// u_r (or s at a skew node).
    R = 0,
    /// u_z (or n at a skew node).
    Z = 1,
}

/// How one node is supported.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct NodeSupport {
    /// Frame rotation α (radians): components are (s, n) with s = (cos α, sin α); None: (r, z).
    pub angle: Option<f64>,
    /// Prescribed values of the two components (in the node's frame); None: free.
    pub fixed: [Option<f64>; 2],
}

/// Supports of all nodes of a mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Supports {
    nodes: Vec<NodeSupport>,
}

impl Supports {
    /// All `n_nodes` nodes free.
    pub fn new(n_nodes: usize) -> Self {
        Self {
            nodes: vec![NodeSupport::default(); n_nodes],
        }
    }

    /// Prescribes component `c` of `node` (report codes 1, 2, 3).
    pub fn prescribe(&mut self, node: usize, c: Component, value: f64) {
        self.nodes[node].fixed[c as usize] = Some(value);
    }

    /// Roller with w = 0 (u free): a plane of symmetry z = const.
    pub fn roller_z(&mut self, node: usize) {
        self.prescribe(node, Component::Z, 0.0);
    }

    /// Roller with u = 0 (w free): the axis r = 0, or a wall r = const.
    pub fn roller_r(&mut self, node: usize) {
        self.prescribe(node, Component::R, 0.0);
    }

    /// u = w = 0.
    pub fn fix(&mut self, node: usize) {
        self.roller_r(node);
        self.roller_z(node);
    }

    /// The report's negative-angle code: skew roller at `angle_deg` ∈ [−180, −0.001] with the
    /// displacement along n prescribed to `n_displacement`; s is free.
    pub fn skew(
        &mut self,
        node: usize,
        angle_deg: f64,
        n_displacement: f64,
    ) -> Result<(), InputError> {
        if !(-180.0..=-0.001).contains(&angle_deg) {
            return Err(InputError::Parameter {
                field: "skew boundary angle (degrees)",
                value: angle_deg,
                reason: "the report's code must lie in [-180, -0.001]",
            });
        }
        self.nodes[node] = NodeSupport {
            angle: Some(angle_deg.to_radians()),
            fixed: [None, Some(n_displacement)],
        };
        Ok(())
    }

    /// Support of `node`.
    pub fn get(&self, node: usize) -> NodeSupport {
        self.nodes[node]
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }
}

const NONE: usize = usize::MAX;

/// Map (node, component) → equation index, with the nodes' frames and prescribed values.
#[derive(Debug, Clone, PartialEq)]
pub struct DofMap {
    eq: Vec<[usize; 2]>,
    support: Vec<NodeSupport>,
    n_eq: usize,
}

impl DofMap {
    /// Numbers the free components node by node (the mesh's node order).
    pub fn new(s: &Supports) -> Self {
        Self::numbered(s, 0..s.nodes.len())
    }

    /// Numbers the free components node by node in the order `nodes` (every node once, e.g.
    /// [`super::node_dissection`]): a node's components are numbered together, R before Z.
    /// An order that is not a permutation of the nodes is refused.
    ///
    /// ```
    /// use boltzone::fem::{Component, DofMap, Supports};
    /// let d = DofMap::in_node_order(&Supports::new(2), &[1, 0])?;
    /// assert_eq!(d.equation(1, Component::Z), Some(1));
    /// assert_eq!(d.equation(0, Component::R), Some(2));
    /// assert!(DofMap::in_node_order(&Supports::new(2), &[1, 1]).is_err());
    /// # Ok::<(), boltzone::error::InputError>(())
    /// ```
    pub fn in_node_order(s: &Supports, nodes: &[usize]) -> Result<Self, InputError> {
        let mut seen = vec![false; s.nodes.len()];
        for &n in nodes {
            if n >= seen.len() || std::mem::replace(&mut seen[n], true) {
                return Err(InputError::Parameter {
                    field: "node order",
                    value: n as f64,
                    reason: "must list every node of the supports once",
                });
            }
        }
        if nodes.len() != seen.len() {
            return Err(InputError::Parameter {
                field: "node order",
                value: nodes.len() as f64,
                reason: "must list every node of the supports once",
            });
        }
        Ok(Self::numbered(s, nodes.iter().copied()))
    }

    fn numbered(s: &Supports, order: impl Iterator<Item = usize>) -> Self {
        let mut n_eq = 0;
        let mut eq = vec![[NONE; 2]; s.nodes.len()];
        for n in order {
            eq[n] = s.nodes[n].fixed.map(|f| {
                if f.is_some() {
                    NONE
                } else {
                    n_eq += 1;
                    n_eq - 1
                }
            });
        }
        Self {
            eq,
            support: s.nodes.clone(),
            n_eq,
        }
    }

    /// Number of equations (free components).
    pub fn n_equations(&self) -> usize {
        self.n_eq
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.eq.len()
    }

    /// Equation of (node, component), or None if prescribed.
    pub fn equation(&self, node: usize, c: Component) -> Option<usize> {
        let e = self.eq[node][c as usize];
        (e != NONE).then_some(e)
    }

    /// Prescribed value of (node, component) in the node's frame, None if free.
    pub fn prescribed(&self, node: usize, c: Component) -> Option<f64> {
        self.support[node].fixed[c as usize]
    }

    /// Rotation (cos α, sin α) of a skew node's frame.
    pub fn frame(&self, node: usize) -> Option<(f64, f64)> {
        self.support[node].angle.map(|a| (a.cos(), a.sin()))
    }

    /// Global (r, z) vector from the node's frame components.
    pub fn to_global(&self, node: usize, v: [f64; 2]) -> [f64; 2] {
        match self.frame(node) {
            None => v,
            Some((c, s)) => [c * v[0] - s * v[1], s * v[0] + c * v[1]],
        }
    }

    /// The node's frame components of a global (r, z) vector.
    pub fn to_local(&self, node: usize, v: [f64; 2]) -> [f64; 2] {
        match self.frame(node) {
            None => v,
            Some((c, s)) => [c * v[0] + s * v[1], -s * v[0] + c * v[1]],
        }
    }

    /// Nodal displacements in the global frame from the equation vector `x` (prescribed
    /// components take their values).
    pub fn expand(&self, x: &[f64]) -> Vec<[f64; 2]> {
        (0..self.eq.len())
            .map(|n| {
                let local = [0, 1].map(|c| match self.eq[n][c] {
                    NONE => self.support[n].fixed[c].unwrap_or(0.0),
                    e => x[e],
                });
                self.to_global(n, local)
            })
            .collect()
    }

    /// Gathers a global nodal force field (r, z per node) into equation order (rotating skew
    /// nodes' forces into their frames).
    pub fn gather(&self, f: &[[f64; 2]]) -> Vec<f64> {
        let mut out = vec![0.0; self.n_eq];
        for (n, fv) in f.iter().enumerate() {
            let l = self.to_local(n, *fv);
            for c in 0..2 {
                if self.eq[n][c] != NONE {
                    out[self.eq[n][c]] += l[c];
                }
            }
        }
        out
    }
}
