//! One level of the two-plate study, adapted to the previous one: the mesh graded at A, B and
//! the estimated R_o; the choice of tied points (well inside the last contact zone) and of the
//! LCP window (near its edges); the supports and loads; and the checks that revise that choice.
//!
//! A tied point must press (p ≥ 0) and a point beyond the window must not penetrate (g ≥ 0);
//! when either fails the level is solved again with one reference point tied and a window from
//! A to B + 3D (doubled in length while the gap beyond is negative); a reference that
//! pulls is replaced by the point pressing hardest. Without a hole (A = 0) the axis nodes have
//! u = 0. Units as in [`super::two_plate`].
//!
//! # Accuracy
//!
//! The revised choices keep every level's answer exact for its mesh: `tests/contact/two_plate.rs`
//! (`a_too_small_first_window_grows`, `equilibrium_and_complementarity_symmetric`); the levels' R_o
//! converge at the observed rate (`r_o_converges_at_the_observed_rate`).
//!
//! # Cost
//!
//! A level is usually solved once (a retry when a check fails); `cargo bench --bench contact`.
//!
//! ```
//! use boltzone::contact::two_plate::{solve, TwoPlateParams};
//! use boltzone::{Joint, Material, OuterRadius};
//! let j = Joint::symmetric(0.1, 0.2, 0.1, Material::unit(0.3)?)?
//!     .with_outer_radius(OuterRadius::Finite(1.0))?;
//! let s = solve(&j, &TwoPlateParams { tolerance: 1e-2, ..Default::default() })?;
//! // After the first level only a few points near the edge remain LCP unknowns.
//! assert!(s.info.levels[1..].iter().all(|l| l.window < 40 && l.attempts == 1));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use super::friction_level;
use super::level::{solve_level_mu, LevelSetup, LevelSolution, MeshedJoint};
use super::params::{EdgeSupport, Loading, TwoPlateParams};
use super::temperature::ScaledTemperature;
use crate::fem::spacing::level_grading;
use crate::fem::{Component, ElementKind, Loads, Mesh, PlateSpec, Spacing, Supports};
use crate::joint::Joint;

/// Radii and thicknesses of the joint as meshed.
pub(crate) struct MeshLayout<'a> {
    pub a: f64,
    pub b: f64,
    pub c: f64,
    /// The plates' rim when `c` is a cut (`f64::INFINITY`: infinite plates), None when `c` is
    /// the rim ([`MeshedJoint::exterior`]).
    pub exterior: Option<f64>,
    pub d: [f64; 2],
    pub two: bool,
    pub welded: bool,
    /// The temperature field, if any ([`super::thermal`]; then `two`).
    pub thermal: Option<&'a ScaledTemperature<'a>>,
}

/// What a level keeps of the one before it: its solution, its R_o estimate and element size.
#[derive(Clone)]
pub(crate) struct PreviousLevel {
    /// The previous level's solution.
    pub solution: LevelSolution,
    /// Its estimate of R_o.
    pub r_o: f64,
    /// Its element size at R_o.
    pub h: f64,
}

/// Largest radial element size, in plate thicknesses: longer elements (aspect ratios of
/// thousands) made the stiffness matrix numerically indefinite for C/D ≳ 10⁴.
const H_MAX_OVER_D: f64 = 50.0;

/// The mesh of one level: radial grading at A, B and the estimate of R_o, axial grading at the
/// interface and the outer faces; materials by plate.
pub(crate) fn mesh(
    joint: &Joint,
    g: &MeshLayout,
    kind: ElementKind,
    h: f64,
    r_est: Option<f64>,
    uniform_edge: bool,
) -> Result<MeshedJoint, ContactError> {
    // growth ratios 1.25 radially, 1.5 axially (the fields vary more slowly across the
    // plates near R_o), shrinking on the finest levels ([`level_grading`])
    let (q, q_axial, shrink) = level_grading(h, g.d[0].min(g.d[1]), 1.25, 1.5);
    // (the fitted edge: the axial excess shrinks like the radial one, √h, so that the far
    // mesh's error falls at second order instead of the first that h^¼ leaves; the first
    // elements from the interface are h: [`interface_knots`])
    let q_axial = if uniform_edge {
        1.0 + 0.5 * shrink
    } else {
        q_axial
    };
    let mut foci = vec![g.a, g.b];
    // (the nut's own bearing radius B₂, when it differs from the head's)
    foci.extend(Some(joint.nut_load().outer()).filter(|&b2| b2 != g.b));
    // (a level in full contact estimates R_o = C: the next level is graded at the rim, where
    // the contact ends, as at any other R_o; a knot there is the rim's own node)
    foci.extend(r_est.filter(|&r| r > g.a && r <= g.c));
    let h_max = ((g.c - g.a) / 10.0).min(H_MAX_OVER_D * g.d[0].max(g.d[1]));
    let mut knots = foci[1..].to_vec();
    if uniform_edge {
        knots.extend(uniform_edge_knots(g, h, r_est));
    }
    knots.sort_by(f64::total_cmp);
    let r = Spacing::graded(g.a, g.c, &knots, &foci, h, q, h_max)?;
    // (the fitted edge: the first elements across the plates from the interface z = 0 are
    // exactly h too, so that the mesh around the edge is the same in units of h on every level)
    let zs = |z0: f64, z1: f64| {
        let knots = if uniform_edge {
            interface_knots(z0, z1, h)
        } else {
            Vec::new()
        };
        Spacing::graded(z0, z1, &knots, &[z0, z1], h, q_axial, (z1 - z0) / 3.0)
    };
    let upper_mat = joint.upper().material();
    let model = if g.two {
        let plates = [
            PlateSpec {
                z: zs(-g.d[1], 0.0)?,
                material: 0,
            },
            PlateSpec {
                z: zs(0.0, g.d[0])?,
                material: 1,
            },
        ];
        MeshedJoint {
            mesh: Mesh::structured(kind, &r, &plates)?,
            materials: vec![joint.lower().material(), upper_mat],
            upper: 1,
            lower: Some(0),
            exterior: g.exterior,
        }
    } else {
        let plates = [PlateSpec {
            z: zs(0.0, g.d[0])?,
            material: 0,
        }];
        MeshedJoint {
            mesh: Mesh::structured(kind, &r, &plates)?,
            materials: vec![upper_mat],
            upper: 0,
            lower: None,
            exterior: g.exterior,
        }
    };
    Ok(model)
}

/// Elements of exactly `h` on either side of the estimated R_o ([`super::edge_fit`]).
pub(crate) const UNIFORM_EDGE_ELEMENTS: usize = 4;

/// Knots at R_o ± i·h, i = 1..=[`UNIFORM_EDGE_ELEMENTS`], inside (A, C) and at least h from
/// A, B and C: the trial edges of the fitted edge then meet the same elements, scaled by h, on
/// every level.
fn uniform_edge_knots(g: &MeshLayout, h: f64, r_est: Option<f64>) -> Vec<f64> {
    let Some(r) = r_est.filter(|&r| r > g.a && r < g.c) else {
        return Vec::new();
    };
    (1..=UNIFORM_EDGE_ELEMENTS)
        .flat_map(|i| [r - i as f64 * h, r + i as f64 * h])
        .filter(|&x| [g.a, g.b, g.c].iter().all(|&y| (x - y).abs() >= h))
        .collect()
}

/// Knots at z = ±i·h, i = 1..=[`UNIFORM_EDGE_ELEMENTS`], from the interface z = 0 into the
/// plate [z0, z1] (one end of which is 0), at least h from its other face.
fn interface_knots(z0: f64, z1: f64, h: f64) -> Vec<f64> {
    let (sign, far) = if z0 < 0.0 { (-1.0, z0) } else { (1.0, z1) };
    (1..=UNIFORM_EDGE_ELEMENTS)
        .map(|i| sign * i as f64 * h)
        .filter(|&z| (far - z).abs() >= h)
        .collect()
}

/// Solves one level, choosing tied and window points from the previous level and widening the
/// window or untying points when the solution shows the choice was wrong.
pub(crate) fn solve_adaptive(
    model: &MeshedJoint,
    joint: &Joint,
    g: &MeshLayout,
    params: &TwoPlateParams,
    prev: Option<&PreviousLevel>,
    thermal: Option<&Loads>,
) -> Result<(LevelSolution, usize, usize), ContactError> {
    let r = model.mesh.radial_nodes().to_vec();
    let load = joint.load();
    let (supports, mut loads) = boundary(model, joint, g, params)?;
    if let Some(t) = thermal {
        for (n, f) in t.forces().iter().enumerate() {
            loads.add_point(n, *f);
        }
    }
    let held: Vec<bool> = (0..r.len())
        .map(|i| {
            let (up, low) = model.pair(i);
            std::iter::once(up)
                .chain(low)
                .any(|n| supports.get(n).fixed[1].is_some())
        })
        .collect();
    // First choice: from the previous level; fallback: one reference point under the load.
    let mut reference = nearest(&r, centroid(load));
    let fix_rigid = params.edge == EdgeSupport::Free && params.loading == Loading::Pressure;
    let mu = params.interface.friction_coefficient().filter(|_| g.two);
    let mut plan = match mu {
        None => prev.and_then(|p| refined_plan(&r, p)),
        Some(_) => prev.map(|p| friction_level::plan(&r, reference, fix_rigid, p.r_o + 6.0 * p.h)),
    };
    let mut r_win = (g.b + params.window * g.d[0].max(g.d[1])).min(g.c);
    let mut tries = 0;
    loop {
        tries += 1;
        let (mut tied, mut window) = match &plan {
            Some(p) => p.clone(),
            None if mu.is_some() => friction_level::plan(&r, reference, fix_rigid, r_win),
            None => (
                vec![reference],
                (0..r.len())
                    .filter(|&i| i != reference && r[i] <= r_win)
                    .collect(),
            ),
        };
        // Interface nodes held by an edge support are no contact points.
        tied.retain(|&i| !held[i]);
        window.retain(|&i| !held[i]);
        let setup = LevelSetup {
            tied: &tied,
            window: &window,
            welded: g.welded,
            fix_rigid,
            lcp: params.lcp,
            nut: (g.a, g.b),
        };
        let sol = solve_level_mu(model, &setup, mu, &supports, &loads)?;
        let fmax = sol.force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
        let gmax = sol.gap.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        // Round-off level of the checks: the LCP's own tolerance.
        let tol = params.lcp.tolerance;
        let pulls = tied.iter().copied().find(|&i| sol.force[i] < -tol * fmax);
        let wmax = window.iter().map(|&i| r[i]).fold(0.0, f64::max);
        // (A welded zone chosen by the report's rule admits penetration anyway: no widening.)
        let penetrates = !sol.lcp.prefix
            && (0..r.len()).any(|i| r[i] > wmax && !tied.contains(&i) && sol.gap[i] < -tol * gmax);
        if tries > 12 {
            return Err(ContactError::NotConverged {
                iterations: tries,
                violations: 1,
            });
        }
        match (pulls, penetrates) {
            (None, false) => return Ok((sol, window.len(), tries)),
            (Some(i), _) if plan.is_none() => {
                // The reference pulls: take the point pressing hardest instead.
                let best = (0..r.len())
                    .filter(|&j| sol.closed[j])
                    .max_by(|&x, &y| sol.force[x].total_cmp(&sol.force[y]));
                match best {
                    Some(j) if j != reference => reference = j,
                    _ => {
                        return Err(ContactError::ReferenceInTension {
                            radius: r[i],
                            reaction: sol.force[i],
                        })
                    }
                }
            }
            (Some(_), _) => plan = None,
            (None, true) => {
                if plan.is_some() {
                    plan = None;
                } else if r_win >= g.c {
                    return Err(ContactError::WindowExhausted { radius: g.c });
                } else {
                    r_win = (g.a + 2.0 * (r_win - g.a)).min(g.c);
                }
            }
        }
    }
}

/// Ties and window from the previous level: points closed there and farther than three old
/// elements from every contact boundary are tied; the rest up to R_o + 6 old elements are unknown.
fn refined_plan(r: &[f64], prev: &PreviousLevel) -> Option<(Vec<usize>, Vec<usize>)> {
    let PreviousLevel {
        solution: s,
        r_o,
        h,
    } = prev;
    let margin = 3.0 * h;
    let mut bounds: Vec<f64> = s
        .closed
        .windows(2)
        .zip(s.radius.windows(2))
        .filter(|(c, _)| c[0] != c[1])
        .map(|(_, x)| 0.5 * (x[0] + x[1]))
        .collect();
    bounds.push(*r_o);
    let closed_at = |x: f64| s.closed[nearest(&s.radius, x)];
    let tied: Vec<usize> = (0..r.len())
        .filter(|&i| {
            closed_at(r[i]) && r[i] < *r_o && bounds.iter().all(|b| (r[i] - b).abs() > margin)
        })
        .collect();
    let window: Vec<usize> = (0..r.len())
        .filter(|&i| !tied.contains(&i) && r[i] <= r_o + 2.0 * margin)
        .collect();
    (!tied.is_empty()).then_some((tied, window))
}

/// Index of the radius closest to `x`.
fn nearest(r: &[f64], x: f64) -> usize {
    (0..r.len())
        .min_by(|&i, &j| (r[i] - x).abs().total_cmp(&(r[j] - x).abs()))
        .expect("non-empty grid")
}

/// Force centroid ∫p r² dr / ∫p r dr of the load.
fn centroid(load: &crate::load::FaceLoad) -> f64 {
    let n = 64;
    let (a, b) = (load.inner(), load.outer());
    let (mut m1, mut m2) = (0.0, 0.0);
    for i in 0..n {
        let r = a + (b - a) * (i as f64 + 0.5) / n as f64;
        let p = load.pressure_at(r);
        m1 += p * r;
        m2 += p * r * r;
    }
    if m1 > 0.0 {
        m2 / m1
    } else {
        0.5 * (a + b)
    }
}

/// Edge supports, prescribed nut displacements and face loads.
fn boundary(
    model: &MeshedJoint,
    joint: &Joint,
    g: &MeshLayout,
    params: &TwoPlateParams,
) -> Result<(Supports, Loads), ContactError> {
    let mesh = &model.mesh;
    let plates: Vec<usize> = std::iter::once(model.upper).chain(model.lower).collect();
    let mut s = Supports::new(mesh.n_nodes());
    if g.a == 0.0 {
        // No hole: the axis r = 0, where u = 0 by symmetry.
        for &p in &plates {
            for n in mesh.inner(p) {
                s.roller_r(n);
            }
        }
    }
    if params.edge == EdgeSupport::Fixed {
        for &p in &plates {
            for n in mesh.outer(p) {
                s.fix(n);
            }
        }
    }
    let mut loads = Loads::new(mesh.n_nodes());
    match params.loading {
        Loading::NutDisplacement(delta) => {
            let eps = 1e-12 * g.b;
            let under = |n: &usize| mesh.nodes()[*n][0] <= g.b + eps;
            for n in mesh.top(model.upper).into_iter().filter(under) {
                s.prescribe(n, Component::Z, -delta);
            }
            if let Some(l) = model.lower {
                let b2 = joint.nut_load().outer() + eps;
                let under = |n: &usize| mesh.nodes()[*n][0] <= b2;
                for n in mesh.bottom(l).into_iter().filter(under) {
                    s.prescribe(n, Component::Z, delta);
                }
            }
        }
        Loading::Pressure => {
            loads.add_face_pressure(mesh, &mesh.top(model.upper), 1.0, joint.load())?;
            if let Some(l) = model.lower {
                loads.add_face_pressure(mesh, &mesh.bottom(l), -1.0, joint.nut_load())?;
            }
        }
    }
    Ok((s, loads))
}
