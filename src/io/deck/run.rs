//! Running a deck on boltzone's finite elements with the report's element
//! ([`ElementKind::Cst4`]): the deck's own nodes and elements, its boundary codes and skew
//! rollers, its nodal loads and pressure cards, and (Appendix C) its temperatures.
//!
//! # Accuracy
//!
//! Uniform stress to rounding, the Lamé cylinder at the observed rate 2, the thermal decks against
//! their exact solutions: `tests/io/exact.rs`; the report's Table 2 case:
//! `tests/io/report_cases.rs`.
//!
//! # Cost
//!
//! One sparse factorization per deck; `tests/io/exact.rs` (`emitted_table1_deck_is_stable`) prints
//! the time.

use super::model::{Appendix, Code, Deck, DeckElement};
use super::DeckError;
use crate::fem::element::cst4;
use crate::fem::{assemble, Component, DofMap, ElementKind, Factorization, FemError, Mesh};
use crate::fem::{Pattern, SolveParams, Supports};
use crate::material::Material;
use serde::Serialize;
use std::f64::consts::PI;
use std::time::Instant;

/// The row (T, E, ν, α) of a material table at a temperature (moved to [`crate::fem::thermal`]).
pub use crate::fem::thermal::interpolate;

/// A node's displacement as the program printed it: (u_r, u_z), or (u_s, u_n) at a skew node.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NodeResult {
    /// Node number.
    pub n: usize,
    /// Radius.
    pub r: f64,
    /// Axial coordinate.
    pub z: f64,
    /// u_r, or the displacement along s at a skew node.
    pub u: f64,
    /// u_z, or the displacement along n at a skew node.
    pub w: f64,
}

/// Stresses at an element's centre (the listing's STRESS routine), tension positive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ElementResult {
    /// Element number.
    pub n: usize,
    /// Radius of the centre.
    pub r: f64,
    /// Axial coordinate of the centre.
    pub z: f64,
    /// σ_r.
    pub sigma_r: f64,
    /// σ_z.
    pub sigma_z: f64,
    /// σ_θ.
    pub sigma_t: f64,
    /// τ_rz.
    pub tau_rz: f64,
    /// Principal stresses of the (r, z) plane, larger first.
    #[serde(skip)]
    pub principal: [f64; 2],
    /// Angle (degrees) from r to the direction of the larger principal stress.
    #[serde(skip)]
    pub angle_deg: f64,
    /// Element temperature (Appendix C: mean of its four nodes).
    #[serde(skip)]
    pub temperature: f64,
}

/// The solution of one deck.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeckSolution {
    /// Nodal displacements, in node order.
    pub nodes: Vec<NodeResult>,
    /// Element-centre stresses, in element order.
    pub elements: Vec<ElementResult>,
    /// Equations solved.
    #[serde(skip)]
    pub equations: usize,
    /// Wall-clock seconds of assembly and solve.
    #[serde(skip)]
    pub seconds: f64,
}

/// Principal stresses of the (r, z) plane and the angle of the larger from r, in degrees.
/// (The listing's STRESS routine took σ_θ where τ_rz belongs under the root and 57.396 for
/// 180/π, and printed neither; this is the textbook form.)
/// A shear below 1e-12 of the normal stresses is taken as zero (the listing zeroed it below
/// 1e-9 psi), so that rounding does not flip the angle between ±90°.
pub fn principal(sr: f64, sz: f64, trz: f64) -> ([f64; 2], f64) {
    let trz = if trz.abs() <= 1e-12 * (sr.abs() + sz.abs()) {
        0.0
    } else {
        trz
    };
    let (c, b) = (0.5 * (sr + sz), 0.5 * (sr - sz));
    let rad = b.hypot(trz);
    let angle = if b == 0.0 && trz == 0.0 {
        0.0
    } else {
        0.5 * trz.atan2(b)
    };
    ([c + rad, c - rad], angle.to_degrees())
}

/// The element's temperature (mean of I, J, K, L as listed), its material at that temperature
/// (E, ν, α interpolated linearly between table rows) and its thermal strain α (T − T_ref).
pub fn element_state(deck: &Deck, e: &DeckElement) -> Result<(f64, Material, f64), DeckError> {
    let t = e.nodes.iter().map(|&n| deck.nodes[n - 1].t).sum::<f64>() / 4.0;
    let m = &deck.materials[e.material - 1];
    let row = match deck.appendix {
        Appendix::B => m.table[0],
        Appendix::C => interpolate(&m.table, t).ok_or_else(|| {
            let (lo, hi) = (m.table[0][0], m.table[m.table.len() - 1][0]);
            let reason = format!(
                "element {}: outside material {}'s temperature table [{lo}, {hi}]",
                e.n, m.id
            );
            DeckError::new(e.line, "element temperature", &t.to_string(), &reason)
        })?,
    };
    let mat = Material::new(row[1], row[2]).map_err(|err| {
        DeckError::new(
            e.line,
            "E, nu at the element temperature",
            &t.to_string(),
            &err.to_string(),
        )
    })?;
    let eth = match deck.appendix {
        Appendix::B => 0.0,
        Appendix::C => row[3] * (t - deck.t_ref),
    };
    Ok((t, mat, eth))
}

/// Runs `deck`: assembles the report's element over the deck's mesh, applies its codes, loads,
/// pressures and temperatures, solves, and recovers the centre stresses.
///
/// A solver failure is reported on the deck's title line: a stiffness that is not positive
/// definite names the nodal codes (the supports leave a rigid-body motion free).
pub fn run(deck: &Deck) -> Result<DeckSolution, DeckError> {
    let t0 = Instant::now();
    let fem = |source: FemError| {
        let field = match source {
            FemError::NotPositiveDefinite(_) => "nodal point codes (supports)",
            _ => "deck",
        };
        DeckError::new(deck.line, field, &deck.title, &source.to_string())
    };
    let coords: Vec<[f64; 2]> = deck.nodes.iter().map(|n| [n.r, n.z]).collect();
    let conn: Vec<usize> = deck
        .elements
        .iter()
        .flat_map(|e| e.nodes.map(|n| n - 1))
        .collect();
    let states = deck
        .elements
        .iter()
        .map(|e| element_state(deck, e))
        .collect::<Result<Vec<_>, _>>()?;
    let materials: Vec<Material> = states.iter().map(|s| s.1).collect();
    let mesh = Mesh::from_elements(
        ElementKind::Cst4,
        coords,
        conn,
        (0..materials.len()).collect(),
    )
    .map_err(|e| fem(e.into()))?;
    // the one rigid-body motion of an axisymmetric body is a translation along z (the hoop
    // strain holds u_r): some node must hold z, or rounding turns K's zero pivot into a solution
    let holds_z = deck.nodes.iter().any(|n| match n.code {
        Code::Z | Code::Both => true,
        Code::Skew(a) => a.to_radians().cos().abs() > 1e-12,
        _ => false,
    });
    if !holds_z {
        return Err(DeckError::new(
            deck.line,
            "nodal point codes (supports)",
            &deck.title,
            "no node holds z (code 2, 3 or a skew roller not at -90): the body is free to move along the axis",
        ));
    }
    let mut s = Supports::new(deck.nodes.len());
    let mut forces = vec![[0.0; 2]; deck.nodes.len()];
    for (k, n) in deck.nodes.iter().enumerate() {
        // the listing turns a free node on the axis into code 1 (XR then its r-displacement)
        let code = if n.r == 0.0 && n.code == Code::Free {
            Code::R
        } else {
            n.code
        };
        let ring = 2.0 * PI; // deck loads act on one radian; boltzone's on the whole ring
        match code {
            Code::Free => forces[k] = [ring * n.xr, ring * n.xz],
            Code::R => {
                s.prescribe(k, Component::R, n.xr);
                forces[k][1] = ring * n.xz;
            }
            Code::Z => {
                s.prescribe(k, Component::Z, n.xz);
                forces[k][0] = ring * n.xr;
            }
            Code::Both => {
                s.prescribe(k, Component::R, n.xr);
                s.prescribe(k, Component::Z, n.xz);
            }
            Code::Skew(a) => {
                s.skew(k, a, n.xz)
                    .map_err(|e| DeckError::new(n.line, "CODE", &a.to_string(), &e.to_string()))?;
                let (sn, cs) = a.to_radians().sin_cos();
                forces[k] = [ring * n.xr * cs, ring * n.xr * sn];
            }
        }
    }
    for p in &deck.pressures {
        let (a, b) = (&deck.nodes[p.i - 1], &deck.nodes[p.j - 1]);
        // consistent forces of a uniform pressure on the edge I→J (inward normal on the left)
        let dir = [a.z - b.z, b.r - a.r];
        for (k, weight) in [(p.i - 1, 2.0 * a.r + b.r), (p.j - 1, a.r + 2.0 * b.r)] {
            for c in 0..2 {
                forces[k][c] += 2.0 * PI * p.p / 6.0 * weight * dir[c];
            }
        }
    }
    for (e, st) in states.iter().enumerate() {
        if st.2 != 0.0 {
            let f = cst4::thermal_load(&mesh.element_coords(e), &st.1, st.2);
            for (a, &n) in mesh.element_nodes(e).iter().enumerate() {
                forces[n][0] += f[2 * a];
                forces[n][1] += f[2 * a + 1];
            }
        }
    }
    let dofs = DofMap::new(&s);
    let k = assemble(&mesh, &materials, &dofs, &Pattern::new(&mesh, &dofs)).map_err(fem)?;
    let mut rhs = dofs.gather(&forces);
    for (a, b) in rhs.iter_mut().zip(&k.prescribed_load) {
        *a += b;
    }
    let x = if rhs.is_empty() {
        Vec::new() // every component prescribed
    } else {
        Factorization::new(&k.matrix, &SolveParams::default())
            .map_err(fem)?
            .solve(&rhs)
    };
    let u = dofs.expand(&x);
    if !u.iter().flatten().all(|v| v.is_finite()) {
        return Err(DeckError::new(
            deck.line,
            "deck",
            &deck.title,
            "the displacements are not finite: coordinates, loads or moduli out of range",
        ));
    }
    let nodes = deck
        .nodes
        .iter()
        .enumerate()
        .map(|(k, n)| {
            let l = dofs.to_local(k, u[k]);
            NodeResult {
                n: n.n,
                r: n.r,
                z: n.z,
                u: l[0],
                w: l[1],
            }
        })
        .collect();
    let elements = deck
        .elements
        .iter()
        .enumerate()
        .map(|(e, el)| {
            let ue: Vec<f64> = mesh.element_nodes(e).iter().flat_map(|&n| u[n]).collect();
            let p = cst4::listing_centre(&mesh.element_coords(e), &states[e].1, &ue, states[e].2);
            let st = p.stress;
            let (principal, angle_deg) = principal(st.r, st.z, st.rz);
            ElementResult {
                n: el.n,
                r: p.r,
                z: p.z,
                sigma_r: st.r,
                sigma_z: st.z,
                sigma_t: st.theta,
                tau_rz: st.rz,
                principal,
                angle_deg,
                temperature: states[e].0,
            }
        })
        .collect();
    Ok(DeckSolution {
        nodes,
        elements,
        equations: dofs.n_equations(),
        seconds: t0.elapsed().as_secs_f64(),
    })
}
