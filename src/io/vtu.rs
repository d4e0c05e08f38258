//! Finite-element fields as a VTK XML unstructured grid (`.vtu`, ASCII), for ParaView, VisIt and
//! Python's meshio.
//!
//! What is written: the mesh of every plate in the meridian plane, (r, z) → (x, y) with x the
//! radius and y the axial coordinate (the axis of symmetry is the line x = 0; the file says so in
//! an XML comment), and at the nodes the displacement vector (u, w, 0), the stresses σ_r, σ_z,
//! σ_θ, τ_rz (compression negative) and the von Mises stress
//! σ_vm = √(½[(σ_r−σ_z)² + (σ_z−σ_θ)² + (σ_θ−σ_r)²] + 3τ_rz²), and per cell the plate id.
//! Callers may add further point arrays (e.g. the contact pressure on interface nodes).
//! Units are the caller's (boltzone's commands: in, psi).
//!
//! Method: [`Grid::plate`] takes a [`Mesh`], its materials and nodal displacements and recovers
//! nodal stresses by [`nodal_stresses`] (element values at the nodes, averaged); [`Grid::mirrored`]
//! reflects a grid in the plane y = 0 (w, τ_rz change sign, cells keep counter-clockwise order)
//! so that a symmetric joint computed on one plate is shown whole. Cell types: VTK_QUAD (9) for
//! the 4-node elements, VTK_BIQUADRATIC_QUAD (28) for Q9, whose node order (corners
//! counter-clockwise, mid-sides bottom, right, top, left, centre) is boltzone's.
//!
//! Numbers are printed with Rust's shortest round-trip format, so a reader gets the f64 values
//! back bit for bit.
//!
//! # Accuracy
//!
//! `tests/io/vtu.rs` reads the file with meshio (independent reader) and compares points, cell
//! count, displacements and stresses with the library's nodal values.
//!
//! # Cost
//!
//! One pass over the mesh plus the stress recovery, linear in the number of nodes; the text is
//! about 200 bytes per node (measured: `single --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-2
//! --field`, 1254 nodes, 258 kB). Exercised by `tests/io/vtu.rs`.
//!
//! ```
//! use boltzone::fem::{ElementKind, Mesh, PlateSpec, Spacing};
//! use boltzone::io::vtu::Grid;
//! let r = Spacing::uniform(1.0, 2.0, 2)?;
//! let z = Spacing::uniform(0.0, 0.5, 1)?;
//! let mesh = Mesh::structured(ElementKind::Q4, &r, &[PlateSpec { z, material: 0 }])?;
//! let u = vec![[0.0, 0.0]; mesh.n_nodes()];
//! let grid = Grid::plate(&mesh, &[boltzone::Material::unit(0.3)?], &u, 0)?;
//! let text = grid.to_vtu("a demo");
//! assert!(text.contains("NumberOfCells=\"2\""));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::fem::{nodal_stresses, ElementKind, FemError, Mesh, Stress};
use crate::material::Material;
use std::fmt::Write;

/// Names of the per-node arrays every plate carries.
const STRESS_NAMES: [&str; 5] = ["sigma_r", "sigma_z", "sigma_theta", "tau_rz", "von_mises"];

/// An unstructured grid of quadrilaterals in the (x, y) = (r, z) plane with point and cell data.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Grid {
    /// Node coordinates (x = r, y = z).
    pub points: Vec<[f64; 2]>,
    /// Cells as node indices in VTK order.
    pub cells: Vec<Vec<usize>>,
    /// Plate id of each cell.
    pub plate: Vec<i32>,
    /// Displacement (u, w) of each node.
    pub displacement: Vec<[f64; 2]>,
    /// Scalar point arrays: name and one value per node (the stresses first).
    pub scalars: Vec<(String, Vec<f64>)>,
}

impl Grid {
    /// The grid of `mesh` (all its plates) with displacements `u`, nodal stresses recovered
    /// from them, and every cell labelled with plate id `plate_offset` + the mesh's plate.
    pub fn plate(
        mesh: &Mesh,
        materials: &[Material],
        u: &[[f64; 2]],
        plate_offset: i32,
    ) -> Result<Self, FemError> {
        Ok(Self::with_stresses(
            mesh,
            &nodal_stresses(mesh, materials, u)?,
            u,
            plate_offset,
        ))
    }

    /// As [`Grid::plate`] with the nodal stresses `s` given (e.g. the thermal stresses of
    /// [`crate::fem::thermal::Thermal::nodal_stresses`]).
    pub fn with_stresses(mesh: &Mesh, s: &[Stress], u: &[[f64; 2]], plate_offset: i32) -> Self {
        let mut scalars: Vec<(String, Vec<f64>)> = STRESS_NAMES
            .iter()
            .map(|n| (n.to_string(), Vec::with_capacity(s.len())))
            .collect();
        for st in s {
            let vm = (0.5
                * ((st.r - st.z).powi(2) + (st.z - st.theta).powi(2) + (st.theta - st.r).powi(2))
                + 3.0 * st.rz * st.rz)
                .sqrt();
            for (col, v) in scalars.iter_mut().zip([st.r, st.z, st.theta, st.rz, vm]) {
                col.1.push(v);
            }
        }
        // node n of a structured mesh lies on row n % rows of the stacked plates' rows
        let z_rows: Vec<usize> = (0..mesh.n_plates())
            .map(|p| mesh.plate_z(p).len())
            .collect();
        let rows: usize = z_rows.iter().sum();
        let plate = (0..mesh.n_elements())
            .map(|e| {
                if rows == 0 {
                    return plate_offset + mesh.element_material(e) as i32;
                }
                let mut row = mesh.element_nodes(e)[0] % rows;
                let mut id = 0;
                for &r in &z_rows {
                    if row < r {
                        break;
                    }
                    row -= r;
                    id += 1;
                }
                plate_offset + id
            })
            .collect();
        Self {
            points: mesh.nodes().to_vec(),
            cells: (0..mesh.n_elements())
                .map(|e| mesh.element_nodes(e).to_vec())
                .collect(),
            plate,
            displacement: u.to_vec(),
            scalars,
        }
    }

    /// The reflection of the grid in y = 0: y, w and τ_rz change sign, the plate ids are
    /// `plate_offset` + the original ones, cells are reordered to stay counter-clockwise.
    pub fn mirrored(&self, plate_offset: i32) -> Self {
        let flip = |c: &Vec<usize>| -> Vec<usize> {
            match c.len() {
                9 => [3, 2, 1, 0, 6, 5, 4, 7, 8].iter().map(|&k| c[k]).collect(),
                _ => c.iter().rev().copied().collect(),
            }
        };
        Self {
            points: self.points.iter().map(|p| [p[0], -p[1]]).collect(),
            cells: self.cells.iter().map(flip).collect(),
            plate: self.plate.iter().map(|p| p + plate_offset).collect(),
            displacement: self.displacement.iter().map(|u| [u[0], -u[1]]).collect(),
            scalars: self
                .scalars
                .iter()
                .map(|(n, v)| {
                    let sign = if n == "tau_rz" { -1.0 } else { 1.0 };
                    (n.clone(), v.iter().map(|x| sign * x).collect())
                })
                .collect(),
        }
    }

    /// Adds a scalar point array (one value per node; shorter arrays are padded with 0).
    pub fn add_scalar(&mut self, name: &str, mut values: Vec<f64>) {
        values.resize(self.points.len(), 0.0);
        self.scalars.push((name.to_string(), values));
    }

    /// Appends `other` (its node indices shifted), e.g. the second plate of a joint.
    pub fn append(&mut self, other: &Self) {
        let shift = self.points.len();
        self.points.extend_from_slice(&other.points);
        self.cells.extend(
            other
                .cells
                .iter()
                .map(|c| c.iter().map(|n| n + shift).collect::<Vec<_>>()),
        );
        self.plate.extend_from_slice(&other.plate);
        self.displacement.extend_from_slice(&other.displacement);
        for (name, v) in &mut self.scalars {
            match other.scalars.iter().find(|(n, _)| n == name) {
                Some((_, w)) => v.extend_from_slice(w),
                None => v.resize(v.len() + other.points.len(), 0.0),
            }
        }
    }

    /// The grid as VTK XML (UnstructuredGrid, ASCII); `note` goes into an XML comment after the
    /// axisymmetry note (it must not contain "--").
    pub fn to_vtu(&self, note: &str) -> String {
        let (np, nc) = (self.points.len(), self.cells.len());
        let mut s = String::with_capacity(200 * np + 100 * nc + 1000);
        s += "<?xml version=\"1.0\"?>\n";
        let _ = writeln!(
            s,
            "<!-- boltzone {}: axisymmetric field; x = radius r, y = axial coordinate z; the axis \
             of symmetry is x = 0 (revolve about the y axis to see the solid). {} -->",
            env!("CARGO_PKG_VERSION"),
            xml_comment(note)
        );
        s += "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
        s += "<UnstructuredGrid>\n";
        let _ = writeln!(s, "<Piece NumberOfPoints=\"{np}\" NumberOfCells=\"{nc}\">");
        s += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for p in &self.points {
            let _ = writeln!(s, "{:e} {:e} 0", p[0], p[1]);
        }
        s += "</DataArray>\n</Points>\n<Cells>\n";
        s += "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
        for c in &self.cells {
            let line: Vec<String> = c.iter().map(|n| n.to_string()).collect();
            s += &line.join(" ");
            s += "\n";
        }
        s += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
        let mut off = 0;
        for c in &self.cells {
            off += c.len();
            let _ = writeln!(s, "{off}");
        }
        s += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
        for c in &self.cells {
            let _ = writeln!(s, "{}", if c.len() == 9 { 28 } else { 9 });
        }
        s += "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n";
        s += "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for u in &self.displacement {
            let _ = writeln!(s, "{:e} {:e} 0", u[0], u[1]);
        }
        s += "</DataArray>\n";
        for (name, v) in &self.scalars {
            let _ = writeln!(
                s,
                "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">"
            );
            for x in v {
                let _ = writeln!(s, "{x:e}");
            }
            s += "</DataArray>\n";
        }
        s += "</PointData>\n<CellData>\n<DataArray type=\"Int32\" Name=\"plate\" format=\"ascii\">\n";
        for p in &self.plate {
            let _ = writeln!(s, "{p}");
        }
        s += "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
        s
    }
}

/// Whether `kind` is written as a 9-node cell (VTK type 28) rather than a 4-node one (type 9).
pub fn is_biquadratic(kind: ElementKind) -> bool {
    kind.nodes() == 9
}

/// `text` made safe inside an XML comment, which must not contain "--": each "--" (a flag's
/// prefix in a command line) is written "- -".
fn xml_comment(text: &str) -> String {
    let mut s = text.to_string();
    while s.contains("--") {
        s = s.replace("--", "- -");
    }
    s
}
