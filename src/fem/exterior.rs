//! The exact exterior of a plate cut at r = c: the free layer beyond the cut, as a radial
//! spring on the cut face (a Dirichlet-to-Neumann condition).
//!
//! Beyond the contact zone both faces of a plate are free and no net force crosses a cylinder
//! around the bolt (the load and the contact pressure balance inside it). The layer's
//! axisymmetric states of that kind are, exactly in 3D elasticity,
//! - u_r = f(z)/r, u_z = −f′ ln r with f linear in z (the Lamé state and the plate's
//!   logarithmic bending mode): σ_rr = −2μ u_r/r, σ_zz = σ_rz = 0;
//! - u_r = f(z) r (uniform stretching and uniform bending, u_z = f′ r²/2 + …):
//!   σ_rr = E/(1 − ν) · u_r/r, σ_zz = σ_rz = 0;
//! - and the self-equilibrated Papkovich–Fadle modes, which decay like e^(−4.21 (r − R_o)/D)
//!   (sin 2λ + 2λ = 0, λ₁ ≈ 2.106 + 1.125i on the half thickness; Timoshenko & Goodier §25,
//!   Fadle 1941).
//!
//! On the annulus c ≤ r ≤ C with a free rim at C (C = ∞: only the first family stays bounded),
//! σ_rr(C) = 0 fixes the mix of the first two families with the same f(z), and on the cut
//! σ_rr = −κ u_r for every z with
//!
//! κ·c = 2μ (1 − c²/C²) / (1 + (1 − ν)/(1 + ν) · c²/C²),
//!
//! so κ = 2μ/c for an infinite plate and κ = 0 when the cut is the rim. Adding
//! ∫ κ N_i N_j 2πc dz to the radial rows of the cut face's nodes makes the cut exact up to the
//! decaying modes: e^(−4.21 (c − R_o)/D) relative, below 1e-40 at the cuts of
//! [`crate::contact::two_plate`]. Without it, a free face at c stood for the infinite plate and
//! R_o carried an error ∝ c⁻² (the logarithmic mode's moment ∝ 1/r² was set to zero there).
//!
//! Units: any consistent set (κ is a stress per length).
//!
//! # Accuracy
//!
//! `tests/contact/exterior.rs`: a Lamé annulus cut at 3 with the spring of a rim at 5, 30 or ∞
//! has the closed-form hole displacement of the whole annulus (errors 5.3e-5, 4.6e-6, 3.3e-7 on
//! 8, 16, 32 Q9 elements; a free cut misses by far); infinite plates in the two-plate model agree
//! with the semi-analytic receding contact within both estimates. Measured once (not a test):
//! on B = 0.55 D, ν ≈ 0, eight levels, free rims at 125 D and 250 D meshed whole and extrapolated
//! in C⁻² gave R_o 8.3e-6 above the receding value, the spring at the cut 7.9e-6 (the same
//! levels' own error); and `tests/hankel/grid_study.rs` (10 × 10 plates with a hole).
//!
//! # Cost
//!
//! One pass over the cut face's edges; the sparsity pattern is unchanged (the face's nodes
//! share elements).
//!
//! ```
//! use boltzone::fem::exterior::spring_coefficient;
//! use boltzone::Material;
//! let m = Material::unit(0.3)?;
//! let mu = m.shear_modulus();
//! assert!((spring_coefficient(&m, 2.0, f64::INFINITY) - mu).abs() < 1e-15); // 2μ/c
//! assert_eq!(spring_coefficient(&m, 2.0, 2.0), 0.0); // the cut is the free rim
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::assemble::{Pattern, Stiffness};
use super::dofs::{Component, DofMap};
use super::element::GAUSS3;
use super::error::FemError;
use super::loads::edges;
use super::mesh::Mesh;
use super::recover::material;
use crate::material::Material;
use std::f64::consts::PI;

/// κ of the module docs: the radial traction on a cut at `cut` per unit radial displacement,
/// for a free layer of `material` out to a free rim at `rim` (`f64::INFINITY`: infinite plate).
pub fn spring_coefficient(material: &Material, cut: f64, rim: f64) -> f64 {
    let two_mu = 2.0 * material.shear_modulus();
    let nu = material.poisson_ratio();
    let s = if rim.is_finite() {
        (cut / rim).powi(2)
    } else {
        0.0
    };
    two_mu * (1.0 - s) / (1.0 + (1.0 - nu) / (1.0 + nu) * s) / cut
}

/// Adds the exterior spring of plate `plate` (its outer face r = c, the cut) to `stiffness`:
/// ∫ κ N_i N_j 2πc dz on the radial equations, κ from the material of the element at each
/// face edge and the plate's rim `rim` beyond the cut.
pub fn add_exterior(
    stiffness: &mut Stiffness,
    pattern: &Pattern,
    mesh: &Mesh,
    materials: &[Material],
    dofs: &DofMap,
    plate: usize,
    rim: f64,
) -> Result<(), FemError> {
    let x = mesh.nodes();
    let line = mesh.outer(plate);
    let Some(&first) = line.first() else {
        return Ok(());
    };
    let c = x[first][0];
    // elements are numbered column by column (radially), plate by plate, bottom to top
    let order = mesh.kind().order();
    let rows: Vec<usize> = (0..mesh.n_plates())
        .map(|p| (mesh.plate_z(p).len() - 1) / order)
        .collect();
    let columns = (mesh.radial_nodes().len() - 1) / order;
    let first_element =
        (columns - 1) * rows.iter().sum::<usize>() + rows[..plate].iter().sum::<usize>();
    let values = stiffness.matrix.val_mut();
    for (k, edge) in edges(&line, order).enumerate() {
        let e = first_element + k;
        let nodes = mesh.element_nodes(e);
        if !edge.iter().all(|n| nodes.contains(n)) {
            return Err(FemError::PatternMismatch {
                row: edge[0],
                col: e,
            });
        }
        let m = material(mesh, materials, e)?;
        let kappa = spring_coefficient(m, c, rim);
        let (za, zb) = (x[edge[0]][1], x[edge[edge.len() - 1]][1]);
        let mut local = [[0.0; 3]; 3];
        for &(xi, w) in &GAUSS3 {
            let s = 0.5 + 0.5 * xi;
            let n = super::loads::edge_shape(edge.len(), s);
            let wt = kappa * 2.0 * PI * c * 0.5 * (zb - za) * w;
            for i in 0..edge.len() {
                for j in 0..edge.len() {
                    local[i][j] += n[i] * n[j] * wt;
                }
            }
        }
        for (i, &ni) in edge.iter().enumerate() {
            for (j, &nj) in edge.iter().enumerate() {
                let (Some(a), Some(b)) = (
                    dofs.equation(ni, Component::R),
                    dofs.equation(nj, Component::R),
                ) else {
                    continue;
                };
                if dofs.frame(ni).is_some() || dofs.frame(nj).is_some() {
                    return Err(FemError::PatternMismatch { row: a, col: b });
                }
                if a >= b {
                    let pos = pattern
                        .position(a, b)
                        .ok_or(FemError::PatternMismatch { row: a, col: b })?;
                    values[pos] += local[i][j];
                }
            }
        }
    }
    Ok(())
}
