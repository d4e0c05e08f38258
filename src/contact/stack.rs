//! A stack of one or two axisymmetric plates meshed on one radial grid, with supports and ties:
//! assembly, one sparse Cholesky factorization, and solves for many right-hand sides.
//!
//! The upper plate occupies 0 ≤ z ≤ D₁, the lower one (if any) −D₂ ≤ z ≤ 0; both span A ≤ r ≤ C on
//! the same radial node lines, so every interface node of the upper plate has a coincident but
//! distinct partner in the lower plate. A degree of freedom is free, prescribed (u or w given),
//! or tied to another (two nodes share one unknown: the welded or closed contact of a node pair).
//! The reduced system K y = f − K_fp x_p over the free unknowns is assembled (lower triangle,
//! duplicates summed) and factorized once by faer's sparse LLᵀ with its fill-reducing ordering.
//! Elements: [`super::axisym`] rectangles of order 1 (Q4) or 2 (Q9). Forces are totals around
//! the circumference (2π included), z upward, compression negative.
//!
//! (A stand-in for the FE module's mesh, dof map and solver while `fem` is being built; the FE
//! module may absorb it.)
//!
//! ```
//! use boltzone::contact::stack::{Body, Stack};
//! use boltzone::Material;
//! let m = Material::unit(0.3).unwrap();
//! let body = Body { z: vec![0.0, 0.05, 0.1], material: m };
//! let s = Stack::new(1, &[0.1, 0.2, 0.4], body, None).unwrap();
//! assert_eq!(s.nodes(), 3 * 3);
//! ```

use super::axisym::{element_stiffness, gauss, lagrange};
use super::ContactError;
use crate::error::InputError;
use crate::load::FaceLoad;
use crate::material::Material;
use faer::sparse::linalg::solvers::Llt;
use faer::sparse::{SparseColMat, Triplet};
use faer::{linalg::solvers::SolveCore, Conj, Mat, Side};
use nalgebra::DMatrix;
use std::f64::consts::PI;

/// One plate: its axial element boundaries (increasing) and material.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Axial element boundaries, increasing (upper plate from 0, lower plate up to 0).
    pub z: Vec<f64>,
    /// Material of the plate.
    pub material: Material,
}

/// State of one degree of freedom.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Dof {
    /// Unknown number `eq` of the reduced system.
    Free(usize),
    /// Prescribed value.
    Fixed(f64),
}

/// The meshed stack (module docs).
#[derive(Debug, Clone)]
pub struct Stack {
    order: usize,
    r: Vec<f64>,
    z: Vec<Vec<f64>>,
    lame: Vec<(f64, f64)>,
    offset: Vec<usize>,
    dof: Vec<Dof>,
    alias: Vec<usize>,
}

/// Node lines of an element-boundary list for the given order (mid-nodes for order 2).
fn node_lines(order: usize, x: &[f64]) -> Vec<f64> {
    let mut v = vec![x[0]];
    for w in x.windows(2) {
        if order == 2 {
            v.push(0.5 * (w[0] + w[1]));
        }
        v.push(w[1]);
    }
    v
}

impl Stack {
    /// Meshes the upper body (and the lower one, if given) on the radial element boundaries
    /// `r_elements`, all dofs free.
    pub fn new(
        order: usize,
        r_elements: &[f64],
        upper: Body,
        lower: Option<Body>,
    ) -> Result<Self, InputError> {
        if order != 1 && order != 2 {
            return Err(InputError::Parameter {
                field: "element order",
                value: order as f64,
                reason: "must be 1 (Q4) or 2 (Q9)",
            });
        }
        let r = node_lines(order, r_elements);
        let mut bodies = vec![upper];
        bodies.extend(lower);
        let z: Vec<Vec<f64>> = bodies.iter().map(|b| node_lines(order, &b.z)).collect();
        let mut offset = vec![0];
        for zb in &z {
            offset.push(offset.last().unwrap() + zb.len() * r.len());
        }
        let n = *offset.last().unwrap();
        Ok(Self {
            order,
            r,
            z,
            lame: bodies.iter().map(|b| b.material.lame()).collect(),
            offset,
            dof: vec![Dof::Free(0); 2 * n],
            alias: (0..2 * n).collect(),
        })
    }

    /// Number of nodes.
    pub fn nodes(&self) -> usize {
        *self.offset.last().unwrap()
    }

    /// Radial node lines (interface node radii).
    pub fn radii(&self) -> &[f64] {
        &self.r
    }

    /// Axial node lines of body `b`.
    pub fn z_lines(&self, b: usize) -> &[f64] {
        &self.z[b]
    }

    /// Number of bodies (1 or 2).
    pub fn bodies(&self) -> usize {
        self.z.len()
    }

    /// Node at radial line `i`, axial line `j` of body `b`.
    pub fn node(&self, b: usize, i: usize, j: usize) -> usize {
        self.offset[b] + j * self.r.len() + i
    }

    /// Interface node of the upper body at radial line `i` and its partner in the lower body
    /// (None on a rigid plane).
    pub fn interface_pair(&self, i: usize) -> (usize, Option<usize>) {
        let low = (self.bodies() == 2).then(|| self.node(1, i, self.z[1].len() - 1));
        (self.node(0, i, 0), low)
    }

    /// Prescribes component `comp` (0 = u, 1 = w) of `node`.
    pub fn fix(&mut self, node: usize, comp: usize, value: f64) {
        self.dof[2 * node + comp] = Dof::Fixed(value);
    }

    /// Ties component `comp` of node `b` to that of node `a` (one shared unknown).
    pub fn tie(&mut self, a: usize, b: usize, comp: usize) {
        self.alias[2 * b + comp] = 2 * a + comp;
    }

    /// Numbers the free unknowns (after all `fix`/`tie` calls); returns their count.
    pub fn number(&mut self) -> usize {
        let mut n = 0;
        for d in 0..self.dof.len() {
            if self.alias[d] != d {
                continue;
            }
            if let Dof::Free(_) = self.dof[d] {
                self.dof[d] = Dof::Free(n);
                n += 1;
            }
        }
        for d in 0..self.dof.len() {
            if self.alias[d] != d {
                self.dof[d] = self.dof[self.alias[d]];
            }
        }
        n
    }

    /// State of component `comp` of `node`.
    pub fn dof(&self, node: usize, comp: usize) -> Dof {
        self.dof[2 * node + comp]
    }

    /// Elements as (body, node list in local order, r range, z range).
    fn elements(&self) -> impl Iterator<Item = (usize, Vec<usize>, [f64; 2], [f64; 2])> + '_ {
        let p = self.order;
        (0..self.bodies()).flat_map(move |b| {
            let ne_z = (self.z[b].len() - 1) / p;
            let ne_r = (self.r.len() - 1) / p;
            (0..ne_z).flat_map(move |ez| {
                (0..ne_r).map(move |er| {
                    let nodes = (0..=p)
                        .flat_map(|j| (0..=p).map(move |i| (i, j)))
                        .map(|(i, j)| self.node(b, er * p + i, ez * p + j))
                        .collect();
                    let rr = [self.r[er * p], self.r[er * p + p]];
                    let zz = [self.z[b][ez * p], self.z[b][ez * p + p]];
                    (b, nodes, rr, zz)
                })
            })
        })
    }

    /// Element stiffness for body `b` on the rectangle `rr` × `zz`.
    fn ke(&self, b: usize, rr: [f64; 2], zz: [f64; 2]) -> DMatrix<f64> {
        let (l, m) = self.lame[b];
        element_stiffness(self.order, rr, zz, l, m)
    }

    /// Assembles and factorizes the reduced stiffness; returns the solver and the right-hand
    /// side −K_fp x_p of the prescribed values.
    pub fn factorize(&self, n_eq: usize) -> Result<(Solver, Vec<f64>), ContactError> {
        let mut trip = Vec::new();
        let mut rhs = vec![0.0; n_eq];
        for (b, nodes, rr, zz) in self.elements() {
            let ke = self.ke(b, rr, zz);
            let dofs: Vec<Dof> = nodes
                .iter()
                .flat_map(|&n| [self.dof[2 * n], self.dof[2 * n + 1]])
                .collect();
            for (a, da) in dofs.iter().enumerate() {
                let Dof::Free(ea) = *da else { continue };
                for (c, dc) in dofs.iter().enumerate() {
                    match *dc {
                        Dof::Free(ec) if ea >= ec => trip.push(Triplet::new(ea, ec, ke[(a, c)])),
                        Dof::Fixed(v) if v != 0.0 => rhs[ea] -= ke[(a, c)] * v,
                        _ => {}
                    }
                }
            }
        }
        let k = SparseColMat::<usize, f64>::try_new_from_triplets(n_eq, n_eq, &trip)
            .map_err(|e| ContactError::Factorization(format!("{e:?}")))?;
        let llt = k
            .sp_cholesky(Side::Lower)
            .map_err(|e| ContactError::Factorization(format!("{e:?}")))?;
        Ok((Solver { llt, n: n_eq }, rhs))
    }

    /// Adds to `f` (reduced) the consistent forces of `load` on the outer face of body `b`
    /// (top of the upper body pushed down, bottom of the lower body pushed up).
    pub fn add_face_load(&self, b: usize, load: &FaceLoad, f: &mut [f64]) {
        let (j, sign) = if b == 0 {
            (self.z[0].len() - 1, -1.0)
        } else {
            (0, 1.0)
        };
        for (i, w) in self.edge_weights(|r| load.pressure_at(r), load.knots()) {
            if let Dof::Free(e) = self.dof(self.node(b, i, j), 1) {
                f[e] += sign * w;
            }
        }
    }

    /// ∫ q(r) N_i(r) 2πr dr over the radial node lines, exact for piecewise-linear q with the
    /// given knots (3-point Gauss on every piece between element edges and knots).
    pub fn edge_weights(&self, q: impl Fn(f64) -> f64, knots: &[f64]) -> Vec<(usize, f64)> {
        let p = self.order;
        let mut out = vec![0.0; self.r.len()];
        let (pts, wts) = gauss(3);
        for e in 0..(self.r.len() - 1) / p {
            let (r0, r1) = (self.r[e * p], self.r[e * p + p]);
            let mut cuts = vec![r0];
            cuts.extend(knots.iter().copied().filter(|&k| k > r0 && k < r1));
            cuts.push(r1);
            for c in cuts.windows(2) {
                for (&x, &w) in pts.iter().zip(wts) {
                    let r = 0.5 * (c[0] + c[1]) + 0.5 * (c[1] - c[0]) * x;
                    // Evaluate just inside the piece so a jump at a knot is taken from this side.
                    let val = q(r);
                    let xi = 2.0 * (r - r0) / (r1 - r0) - 1.0;
                    let (n, _) = lagrange(p, xi);
                    for a in 0..=p {
                        out[e * p + a] += w * 0.5 * (c[1] - c[0]) * val * n[a] * 2.0 * PI * r;
                    }
                }
            }
        }
        out.into_iter()
            .enumerate()
            .filter(|(_, w)| *w != 0.0)
            .collect()
    }

    /// Full nodal displacements (u, w interleaved) from the reduced solution `y`.
    pub fn expand(&self, y: &[f64]) -> Vec<f64> {
        self.dof
            .iter()
            .map(|d| match *d {
                Dof::Free(e) => y[e],
                Dof::Fixed(v) => v,
            })
            .collect()
    }

    /// Forces (radial, axial) that the upper body's interface row of elements exerts… i.e. the
    /// upper body's internal nodal forces K_upper x at its interface nodes: the contact forces
    /// on the upper plate (no external load acts there). Indexed by radial line.
    pub fn interface_forces(&self, x: &[f64]) -> Vec<[f64; 2]> {
        let mut f = vec![[0.0; 2]; self.r.len()];
        let bottom = self.node(0, 0, 0)..=self.node(0, self.r.len() - 1, 0);
        for (b, nodes, rr, zz) in self.elements() {
            if b != 0 || zz[0] != self.z[0][0] {
                continue;
            }
            let ke = self.ke(b, rr, zz);
            let xe: Vec<f64> = nodes
                .iter()
                .flat_map(|&n| [x[2 * n], x[2 * n + 1]])
                .collect();
            for (a, &n) in nodes.iter().enumerate() {
                if bottom.contains(&n) {
                    for c in 0..2 {
                        let v: f64 = (0..xe.len()).map(|k| ke[(2 * a + c, k)] * xe[k]).sum();
                        f[n - self.offset[0]][c] += v;
                    }
                }
            }
        }
        f
    }
}

/// A factorized reduced stiffness.
#[derive(Debug)]
pub struct Solver {
    llt: Llt<usize, f64>,
    n: usize,
}

impl Solver {
    /// Number of unknowns.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Solves K X = B in place for all columns of `b` (n × k).
    pub fn solve_in_place(&self, b: &mut Mat<f64>) {
        self.llt.solve_in_place_with_conj(Conj::No, b.as_mut());
    }
}
