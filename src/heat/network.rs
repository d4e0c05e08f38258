//! Steady conduction through a network of lumped nodes: the program of the report's Appendix D.
//!
//! Nodes 1..=N (numbered from 1, as in the report) are joined by conductances g_ij; node i may be
//! tied by one conductance g_i0 to a ground at a fixed temperature T_i0, and receives an internal
//! power Q_i. Energy balance at each node,
//!
//! Σ_j g_ij (T_i − T_j) + g_i0 (T_i − T_i0) = Q_i,
//!
//! is G T = b with G symmetric positive definite when every connected group of nodes has a ground
//! (the program built the same matrix with the opposite sign, A = −G, B = −b). Units: any
//! consistent set (W/K, K, W or Btu/(hr·°F), °F, Btu/hr); heat flows toward a node are positive.
//!
//! Method: G assembled sparse (lower triangle) and factored by the sparse Cholesky of
//! [`crate::fem::Factorization`] (the program inverted a dense 50 × 50 matrix by Gauss–Jordan
//! steps). The residual is reported as the program printed it: RES_i = |B_i| − |(A T)_i|, with
//! [`NetworkSolution::residual`] the largest |RES_i|.
//!
//! # Accuracy
//!
//! `tests/heat/network.rs` checks the energy balance Σ ground flows + Σ Q = 0 to 1e-10 of the
//! largest flow, a chain of N resistors against the closed form of a series circuit, and a deck
//! written by hand against the same network built here.
//!
//! # Cost
//!
//! One sparse factorization, O(N) for a chain; the Chapter V network of
//! `examples/15_lap_joint_heat.rs` prints its time.
//!
//! ```
//! use boltzone::heat::network::Network;
//! // Two nodes in series between grounds at 100 and 0: each link 1.
//! let mut net = Network::new(2)?;
//! net.connect(1, 2, 1.0)?;
//! net.ground(1, 1.0, 100.0)?;
//! net.ground(2, 1.0, 0.0)?;
//! let s = net.solve()?;
//! assert!((s.nodes[0].t - 200.0 / 3.0).abs() < 1e-12);
//! assert!((s.nodes[0].ground_flow - 100.0 / 3.0).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::fem::{Factorization, SolveParams};
use faer::sparse::{SparseColMat, Triplet};
use serde::Serialize;
use std::fmt;
use thiserror::Error;

/// A network that cannot be built or solved; node numbers from 1.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum NetworkError {
    /// The number of nodes is 0.
    #[error("the network needs at least one node (N = 0)")]
    Empty,
    /// A node number outside 1..=N.
    #[error("{field}: node {node} is not in 1..={n}")]
    Node {
        /// Which input.
        field: &'static str,
        /// The number given.
        node: usize,
        /// The number of nodes.
        n: usize,
    },
    /// A link from a node to itself.
    #[error("conductance from node {node} to itself")]
    SelfLink {
        /// The node.
        node: usize,
    },
    /// A value that must be finite and (for conductances) not negative.
    #[error("{field} of node {node} = {value}: {reason}")]
    Value {
        /// Which input.
        field: &'static str,
        /// Node number.
        node: usize,
        /// The value given.
        value: f64,
        /// What it must be.
        reason: &'static str,
    },
    /// A group of connected nodes without a ground: its temperature is undetermined.
    #[error("nodes connected to node {node} ({size} of them) have no ground conductance: their temperature is undetermined")]
    Floating {
        /// The lowest node of the group.
        node: usize,
        /// How many nodes it holds.
        size: usize,
    },
    /// The factorization failed.
    #[error("network solve: {0}")]
    Solver(String),
}

/// A conductance network (module docs).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Network {
    links: Vec<(usize, usize, f64)>,
    ground: Vec<f64>,
    ground_temperature: Vec<f64>,
    power: Vec<f64>,
}

/// One node of a solution (the program's printout per node).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NodeTemperature {
    /// Node number (from 1).
    pub n: usize,
    /// Temperature.
    pub t: f64,
    /// Internal power Q.
    pub power: f64,
    /// Conductance to ground.
    pub ground_conductance: f64,
    /// Ground temperature.
    pub ground_temperature: f64,
    /// Heat flow from the ground into the node, g_i0 (T_i0 − T_i).
    pub ground_flow: f64,
    /// The program's augmenting vector B_i = −(Q_i + g_i0 T_i0).
    pub b: f64,
    /// The same computed from the solution, (A T)_i.
    pub bc: f64,
    /// The program's residual error |B_i| − |BC_i|.
    pub residual: f64,
}

/// Temperatures and flows of a solved network.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NetworkSolution {
    /// Per node, in order.
    pub nodes: Vec<NodeTemperature>,
    /// The largest |RES_i| (module docs).
    pub residual: f64,
}

impl Network {
    /// A network of `n` ≥ 1 nodes, no links, no grounds, no power.
    pub fn new(n: usize) -> Result<Self, NetworkError> {
        if n == 0 {
            return Err(NetworkError::Empty);
        }
        Ok(Self {
            links: Vec::new(),
            ground: vec![0.0; n],
            ground_temperature: vec![0.0; n],
            power: vec![0.0; n],
        })
    }

    /// Number of nodes.
    pub fn n(&self) -> usize {
        self.ground.len()
    }

    fn index(&self, field: &'static str, node: usize) -> Result<usize, NetworkError> {
        if node >= 1 && node <= self.n() {
            Ok(node - 1)
        } else {
            Err(NetworkError::Node {
                field,
                node,
                n: self.n(),
            })
        }
    }

    /// Adds a conductance g ≥ 0 between nodes i ≠ j (in parallel with any already there).
    pub fn connect(&mut self, i: usize, j: usize, g: f64) -> Result<(), NetworkError> {
        let a = self.index("conductance, first node", i)?;
        let b = self.index("conductance, second node", j)?;
        if a == b {
            return Err(NetworkError::SelfLink { node: i });
        }
        check(i, "conductance", g, true)?;
        self.links.push((a.max(b), a.min(b), g));
        Ok(())
    }

    /// Ties node i to a ground at temperature `t` by a conductance g ≥ 0 (replaces an earlier one:
    /// one ground per node).
    pub fn ground(&mut self, i: usize, g: f64, t: f64) -> Result<(), NetworkError> {
        let a = self.index("ground conductance, node", i)?;
        check(i, "ground conductance", g, true)?;
        check(i, "ground temperature", t, false)?;
        self.ground[a] = g;
        self.ground_temperature[a] = t;
        Ok(())
    }

    /// Adds an internal power Q to node i.
    pub fn power(&mut self, i: usize, q: f64) -> Result<(), NetworkError> {
        let a = self.index("internal power, node", i)?;
        check(i, "internal power", q, false)?;
        self.power[a] += q;
        Ok(())
    }

    /// Solves G T = b (module docs).
    pub fn solve(&self) -> Result<NetworkSolution, NetworkError> {
        let n = self.n();
        self.check_grounded()?;
        let mut diag = self.ground.clone();
        let mut trip = Vec::with_capacity(self.links.len() + n);
        for &(a, b, g) in &self.links {
            diag[a] += g;
            diag[b] += g;
            trip.push(Triplet::new(a, b, -g));
        }
        trip.extend(diag.iter().enumerate().map(|(i, &d)| Triplet::new(i, i, d)));
        let g = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trip)
            .map_err(|e| NetworkError::Solver(format!("assembly: {e:?}")))?;
        let rhs: Vec<f64> = (0..n)
            .map(|i| self.power[i] + self.ground[i] * self.ground_temperature[i])
            .collect();
        let f = Factorization::new(&g, &SolveParams::default())
            .map_err(|e| NetworkError::Solver(e.to_string()))?;
        let t = f.solve(&rhs);
        // (G T)_i from the links, as the program multiplied its full matrix.
        let mut gt: Vec<f64> = (0..n).map(|i| diag[i] * t[i]).collect();
        for &(a, b, g) in &self.links {
            gt[a] -= g * t[b];
            gt[b] -= g * t[a];
        }
        let nodes: Vec<NodeTemperature> = (0..n)
            .map(|i| NodeTemperature {
                n: i + 1,
                t: t[i],
                power: self.power[i],
                ground_conductance: self.ground[i],
                ground_temperature: self.ground_temperature[i],
                ground_flow: self.ground[i] * (self.ground_temperature[i] - t[i]),
                b: -rhs[i],
                bc: -gt[i],
                residual: rhs[i].abs() - gt[i].abs(),
            })
            .collect();
        let residual = nodes.iter().map(|r| r.residual.abs()).fold(0.0, f64::max);
        if !nodes.iter().all(|r| r.t.is_finite()) {
            return Err(NetworkError::Solver("temperatures are not finite".into()));
        }
        Ok(NetworkSolution { nodes, residual })
    }

    /// Every connected group of nodes must hold a node with a positive ground conductance.
    fn check_grounded(&self) -> Result<(), NetworkError> {
        let n = self.n();
        let mut parent: Vec<usize> = (0..n).collect();
        fn root(p: &mut [usize], mut i: usize) -> usize {
            while p[i] != i {
                p[i] = p[p[i]];
                i = p[i];
            }
            i
        }
        for &(a, b, g) in &self.links {
            if g > 0.0 {
                let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
        let mut grounded = vec![false; n];
        let mut size = vec![0usize; n];
        for i in 0..n {
            let r = root(&mut parent, i);
            size[r] += 1;
            grounded[r] |= self.ground[i] > 0.0;
        }
        // The root of a group is its lowest node (unions keep the smaller index).
        match (0..n).find(|&i| parent[i] == i && !grounded[i]) {
            Some(i) => Err(NetworkError::Floating {
                node: i + 1,
                size: size[i],
            }),
            None => Ok(()),
        }
    }
}

fn check(node: usize, field: &'static str, v: f64, conductance: bool) -> Result<(), NetworkError> {
    let reason = if !v.is_finite() {
        "not a finite number"
    } else if conductance && v < 0.0 {
        "a conductance must not be negative"
    } else {
        return Ok(());
    };
    Err(NetworkError::Value {
        field,
        node,
        value: v,
        reason,
    })
}

impl fmt::Display for NetworkSolution {
    /// The program's printout: per node I, Q, ground conductance and temperature, T, then B, BC
    /// and the residual error (numbers in the network's own consistent units).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "units: those of the input (conductance x temperature = power), e.g. Btu/(hr F), F, Btu/hr"
        )?;
        writeln!(
            f,
            "{:>5} {:>15} {:>15} {:>15} {:>15} {:>15} {:>15} {:>15}",
            "I", "Q", "GRD. COND.", "GRD. TEMP.", "T", "B", "BC", "RESIDUAL"
        )?;
        for r in &self.nodes {
            writeln!(
                f,
                "{:>5} {:>15.8e} {:>15.8e} {:>15.8e} {:>15.8e} {:>15.8e} {:>15.8e} {:>15.8e}",
                r.n,
                r.power,
                r.ground_conductance,
                r.ground_temperature,
                r.t,
                r.b,
                r.bc,
                r.residual
            )?;
        }
        write!(f, "largest |residual error| {:.3e}", self.residual)
    }
}
