//! Structured quadrilateral meshes of one plate or a stack of plates in the (r, z) half-plane.
//!
//! A mesh is the tensor product of one radial [`Spacing`] (shared by every plate) with one axial
//! spacing per plate. Plates are stacked bottom to top and touch (top of plate k = bottom of
//! plate k + 1); each plate has its OWN nodes on the interface, coincident but distinct, so a
//! contact model can tie them or let them separate. Each plate carries a material index.
//!
//! Numbering: node columns at fixed r, column by column outward; inside a column plate 0 bottom to
//! top, then plate 1, … . Plates are thin compared with their radius, so the half-bandwidth is
//! about two columns (a sane order even before the solver's own fill-reducing ordering).
//! Quadratic elements (Q9) put nodes at element mid-sides and centres, so node lines are the
//! spacings' points plus midpoints.
//!
//! # Accuracy
//!
//! Exact (a structured grid): `tests/fem/system.rs`
//! (`stacked_plates_have_distinct_interface_nodes_and_their_own_materials`).
//!
//! # Cost
//!
//! Linear in the nodes; example 08 builds meshes up to 10⁶ equations.
//!
//! ```
//! use boltzone::fem::{ElementKind, Mesh, PlateSpec, Spacing};
//! let r = Spacing::uniform(0.1, 1.0, 9)?;
//! let z = Spacing::uniform(0.0, 0.1, 2)?;
//! let m = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }])?;
//! assert_eq!(m.n_nodes(), 19 * 5);
//! assert_eq!(m.n_elements(), 18);
//! assert_eq!(m.top(0).len(), 19);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::element::ElementKind;
use super::spacing::Spacing;
use crate::error::InputError;

/// One plate of a stack: its axial spacing (absolute z) and material index.
#[derive(Debug, Clone, PartialEq)]
pub struct PlateSpec {
    /// Element boundaries in z.
    pub z: Spacing,
    /// Index into the material list passed to assembly.
    pub material: usize,
}

#[derive(Debug, Clone, PartialEq)]
struct PlateNodes {
    offset: usize,
    z: Vec<f64>,
}

/// A structured mesh: nodes, connectivity, element materials, and the plate/grid layout.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    kind: ElementKind,
    nodes: Vec<[f64; 2]>,
    connectivity: Vec<usize>,
    material: Vec<usize>,
    r: Vec<f64>,
    plates: Vec<PlateNodes>,
    rows: usize,
}

/// Node coordinates along a line: element boundaries, plus midpoints for quadratic elements.
fn node_line(s: &Spacing, order: usize) -> Vec<f64> {
    if order == 1 {
        return s.points().to_vec();
    }
    let mut v: Vec<f64> = s
        .points()
        .windows(2)
        .flat_map(|w| [w[0], 0.5 * (w[0] + w[1])])
        .collect();
    v.push(*s.points().last().expect("two points"));
    v
}

impl Mesh {
    /// The tensor-product mesh of `radial` with each plate's axial spacing.
    pub fn structured(
        kind: ElementKind,
        radial: &Spacing,
        plates: &[PlateSpec],
    ) -> Result<Self, InputError> {
        if plates.is_empty() {
            return Err(InputError::Parameter {
                field: "number of plates",
                value: 0.0,
                reason: "a mesh needs at least one plate",
            });
        }
        if radial.points()[0] < 0.0 {
            return Err(InputError::Negative {
                field: "mesh inner radius",
                value: radial.points()[0],
            });
        }
        for w in plates.windows(2) {
            // a Spacing has at least two points (checked when it is built)
            let (lower, upper) = (w[0].z.points(), w[1].z.points());
            let (top, bottom) = (lower[lower.len() - 1], upper[0]);
            if (top - bottom).abs() > 1e-12 * (1.0 + top.abs()) {
                return Err(InputError::Parameter {
                    field: "plate bottom z",
                    value: bottom,
                    reason: "plates must be stacked: each starts where the one below ends",
                });
            }
        }
        let o = kind.order();
        let r = node_line(radial, o);
        let mut layout = Vec::with_capacity(plates.len());
        let mut rows = 0;
        for p in plates {
            let z = node_line(&p.z, o);
            let len = z.len();
            layout.push(PlateNodes { offset: rows, z });
            rows += len;
        }
        let mut nodes = Vec::with_capacity(r.len() * rows);
        for &ri in &r {
            for p in &layout {
                nodes.extend(p.z.iter().map(|&zj| [ri, zj]));
            }
        }
        let mut mesh = Self {
            kind,
            nodes,
            connectivity: Vec::new(),
            material: Vec::new(),
            r,
            plates: layout,
            rows,
        };
        let s = o; // node step per element
        for i in (0..mesh.r.len() - 1).step_by(s) {
            for (k, spec) in plates.iter().enumerate() {
                for j in (0..mesh.plates[k].z.len() - 1).step_by(s) {
                    let n = |di: usize, dj: usize| mesh.node_at(k, i + di, j + dj);
                    let mut el = vec![n(0, 0), n(s, 0), n(s, s), n(0, s)];
                    if o == 2 {
                        el.extend([n(1, 0), n(2, 1), n(1, 2), n(0, 1), n(1, 1)]);
                    }
                    mesh.connectivity.extend(el);
                    mesh.material.push(spec.material);
                }
            }
        }
        Ok(mesh)
    }

    /// A mesh of any topology: node coordinates, `connectivity` ([`ElementKind::nodes`] node
    /// indices per element, in the element's order) and one material index per element (e.g. a
    /// 1970 card deck). It has no plate layout: the plate, row and face queries
    /// ([`Mesh::top`], [`Mesh::node_at`], …) belong to structured meshes and must not be used on it.
    pub fn from_elements(
        kind: ElementKind,
        nodes: Vec<[f64; 2]>,
        connectivity: Vec<usize>,
        material: Vec<usize>,
    ) -> Result<Self, InputError> {
        if connectivity.len() != kind.nodes() * material.len() {
            return Err(InputError::Parameter {
                field: "connectivity length",
                value: connectivity.len() as f64,
                reason: "must be the nodes per element times the number of element materials",
            });
        }
        if let Some(&bad) = connectivity.iter().find(|&&n| n >= nodes.len()) {
            return Err(InputError::Parameter {
                field: "element node index",
                value: bad as f64,
                reason: "must be less than the number of nodes",
            });
        }
        Ok(Self {
            kind,
            nodes,
            connectivity,
            material,
            r: Vec::new(),
            plates: Vec::new(),
            rows: 0,
        })
    }

    /// Replaces the element materials (one index per element), e.g. one material per element
    /// for moduli that follow a temperature field ([`crate::fem::thermal`]).
    pub fn set_element_materials(&mut self, material: Vec<usize>) -> Result<(), InputError> {
        if material.len() != self.material.len() {
            return Err(InputError::Parameter {
                field: "number of element materials",
                value: material.len() as f64,
                reason: "must equal the number of elements",
            });
        }
        self.material = material;
        Ok(())
    }

    /// Moves every node to `f(r, z)` (e.g. to distort a patch-test mesh). The plate/row layout is
    /// kept, so the face and row queries still name the same nodes.
    pub fn transform_nodes(&mut self, f: impl Fn([f64; 2]) -> [f64; 2]) {
        for x in &mut self.nodes {
            *x = f(*x);
        }
    }

    /// The element kind.
    pub fn kind(&self) -> ElementKind {
        self.kind
    }

    /// All node coordinates (r, z).
    pub fn nodes(&self) -> &[[f64; 2]] {
        &self.nodes
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Number of elements.
    pub fn n_elements(&self) -> usize {
        self.material.len()
    }

    /// Node indices of element `e` (see [`ElementKind::stiffness`] for the order).
    pub fn element_nodes(&self, e: usize) -> &[usize] {
        let n = self.kind.nodes();
        &self.connectivity[e * n..(e + 1) * n]
    }

    /// Node coordinates of element `e`.
    pub fn element_coords(&self, e: usize) -> Vec<[f64; 2]> {
        self.element_nodes(e)
            .iter()
            .map(|&i| self.nodes[i])
            .collect()
    }

    /// Material index of element `e`.
    pub fn element_material(&self, e: usize) -> usize {
        self.material[e]
    }

    /// Number of plates in the stack.
    pub fn n_plates(&self) -> usize {
        self.plates.len()
    }

    /// Radii of the node columns, inner to outer.
    pub fn radial_nodes(&self) -> &[f64] {
        &self.r
    }

    /// z of the node rows of `plate`, bottom to top.
    pub fn plate_z(&self, plate: usize) -> &[f64] {
        &self.plates[plate].z
    }

    /// The node of `plate` in column `i` (radial) and row `j` (axial, within the plate).
    pub fn node_at(&self, plate: usize, i: usize, j: usize) -> usize {
        i * self.rows + self.plates[plate].offset + j
    }

    /// Nodes of row `j` of `plate`, sorted by r.
    pub fn row(&self, plate: usize, j: usize) -> Vec<usize> {
        (0..self.r.len())
            .map(|i| self.node_at(plate, i, j))
            .collect()
    }

    /// Nodes on the bottom face of `plate`, sorted by r.
    pub fn bottom(&self, plate: usize) -> Vec<usize> {
        self.row(plate, 0)
    }

    /// Nodes on the top face of `plate`, sorted by r.
    pub fn top(&self, plate: usize) -> Vec<usize> {
        self.row(plate, self.plates[plate].z.len() - 1)
    }

    /// Nodes of column `i` of `plate`, sorted by z.
    pub fn column(&self, plate: usize, i: usize) -> Vec<usize> {
        (0..self.plates[plate].z.len())
            .map(|j| self.node_at(plate, i, j))
            .collect()
    }

    /// Nodes on the inner edge (hole, or axis when r = 0) of `plate`, sorted by z.
    pub fn inner(&self, plate: usize) -> Vec<usize> {
        self.column(plate, 0)
    }

    /// Nodes on the outer rim of `plate`, sorted by z.
    pub fn outer(&self, plate: usize) -> Vec<usize> {
        self.column(plate, self.r.len() - 1)
    }

    /// All nodes with |z − `z`| ≤ `tol`, sorted by (r, plate): on an interface both plates' nodes
    /// appear, the lower plate's first.
    pub fn nodes_at_z(&self, z: f64, tol: f64) -> Vec<usize> {
        (0..self.nodes.len())
            .filter(|&n| (self.nodes[n][1] - z).abs() <= tol)
            .collect()
    }
}
