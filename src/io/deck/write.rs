//! Writing decks: any [`Deck`] back to Appendix B or C cards (omitted cards stay omitted, so
//! the listing's generation rebuilds them), and a single plate of the library
//! ([`SinglePlate`] on a [`Mesh::structured`] mesh of the report's element) as an Appendix B
//! deck — the `boltzone deck --emit` output.
//!
//! Reals are written in the 10 columns of an F10.0 field with as many digits as fit (F or E
//! form, whichever reads back closer): about 8 significant digits, so a deck reproduces a mesh
//! to ~1e-8 relative unless its coordinates are short decimals.
//!
//! # Accuracy
//!
//! A written deck reads back to the same model and solves to the library's answer:
//! `tests/io/exact.rs` (`table1_single_plate_deck_matches_the_library`,
//! `emitted_table1_deck_is_stable`).
//!
//! # Cost
//!
//! Linear in the nodes and elements.

use super::model::{Appendix, Code, Deck, DeckElement, DeckMaterial, DeckNode, PressureCard};
use crate::error::InputError;
use crate::fem::{ElementKind, Mesh, PlateSpec, Spacing};
use crate::joint::SinglePlate;
use crate::load::Profile;
use std::fmt::Write;

/// `v` in `w` columns, right-justified, the closest form that fits.
fn real(v: f64, w: usize) -> Result<String, InputError> {
    let mut best: Option<(f64, String)> = None;
    let mut consider = |s: String| {
        if s.len() <= w {
            if let Ok(back) = s.parse::<f64>() {
                let err = (back - v).abs();
                if best.as_ref().is_none_or(|b| err < b.0) {
                    best = Some((err, s));
                }
            }
        }
    };
    // F forms first: an E form is taken only when it reads back strictly closer
    for d in 0..w {
        let s = format!("{v:.d$}");
        consider(if d == 0 { format!("{s}.") } else { s });
    }
    for d in 0..w {
        consider(format!("{v:.d$e}").replace('e', "E"));
    }
    match best {
        Some((_, s)) if v.is_finite() => Ok(format!("{s:>w$}")),
        _ => Err(InputError::Parameter {
            field: "deck real field",
            value: v,
            reason: "does not fit its columns",
        }),
    }
}

/// `v` in `w` columns.
fn int(v: usize, w: usize) -> Result<String, InputError> {
    let s = format!("{v:>w$}");
    if s.len() > w {
        return Err(InputError::Parameter {
            field: "deck integer field",
            value: v as f64,
            reason: "does not fit its columns",
        });
    }
    Ok(s)
}

/// The cards of `deck` (Appendix B or C as its `appendix`), generated nodes and elements left
/// out, a `*****` card after it.
pub fn write_deck(deck: &Deck) -> Result<String, InputError> {
    let c = deck.appendix == Appendix::C;
    let mut o = String::new();
    let title: String = deck.title.chars().take(72).collect();
    let _ = writeln!(o, "{title}");
    let counts = [
        deck.nodes.len(),
        deck.elements.len(),
        deck.materials.len(),
        0,
        deck.pressures.len(),
    ];
    for n in counts {
        o += &int(n, 5)?;
    }
    if c {
        o += &real(deck.t_ref, 10)?;
    }
    o.push('\n');
    for m in &deck.materials {
        o += &int(m.id, 5)?;
        if c {
            o += &int(m.table.len(), 5)?;
        }
        let _ = writeln!(o, "{}{}", real(m.sigma_z0, 10)?, real(m.sigma_r0, 10)?);
        for r in &m.table {
            let row = if c { &r[..] } else { &r[1..3] };
            for v in row {
                o += &real(*v, 10)?;
            }
            o.push('\n');
        }
    }
    for n in deck.nodes.iter().filter(|n| !n.generated) {
        let code = match n.code {
            Code::Skew(a) => real(a, 5)?,
            k => int(k.value() as usize, 5)?,
        };
        o += &int(n.n, 5)?;
        o += &code;
        for v in [n.r, n.z, n.xr, n.xz] {
            o += &real(v, 10)?;
        }
        if c {
            o += &real(n.t, 10)?;
        }
        o.push('\n');
    }
    for e in deck.elements.iter().filter(|e| !e.generated) {
        o += &int(e.n, 5)?;
        for v in e.nodes {
            o += &int(v, 5)?;
        }
        o += &int(e.material, 5)?;
        o.push('\n');
    }
    for p in &deck.pressures {
        let _ = writeln!(o, "{}{}{}", int(p.i, 5)?, int(p.j, 5)?, real(p.p, 10)?);
    }
    o += "*****\n";
    Ok(o)
}

/// The upper half of `plate` (0 ≤ z ≤ D, the midplane on rollers, code 2) on the mesh
/// `radial` × `axial` of the report's element, as an Appendix B deck: node numbers are the
/// mesh's (column by column) plus one, element cards are written only where the listing's
/// generation (+1 on I, J, K, L) would not rebuild them, and the uniform face pressure is one
/// pressure card per loaded top edge. A plate without a hole has u = 0 on the axis (code 1).
pub fn single_plate_deck(
    plate: &SinglePlate,
    radial: &Spacing,
    axial: &Spacing,
    title: &str,
) -> Result<Deck, InputError> {
    plate_on_plane_deck(plate, radial, axial, title, None)
}

/// As [`single_plate_deck`], with the bottom held (code 2) only where r ≤ `contact` (None:
/// everywhere): one plate of an equal pair on its frictionless interface, in contact out to a
/// given radius — how the 1970 program ran the two-plate model, one trial contact zone per deck.
pub fn plate_on_plane_deck(
    plate: &SinglePlate,
    radial: &Spacing,
    axial: &Spacing,
    title: &str,
    contact: Option<f64>,
) -> Result<Deck, InputError> {
    let load = plate.load();
    if load.profile() != Profile::Uniform {
        return Err(InputError::Parameter {
            field: "face load profile",
            value: 0.0,
            reason:
                "a deck's pressure cards are uniform per edge: only a uniform load can be written",
        });
    }
    let mesh = Mesh::structured(
        ElementKind::Cst4,
        radial,
        &[PlateSpec {
            z: axial.clone(),
            material: 0,
        }],
    )?;
    let m = plate.material();
    let (bottom, inner) = (mesh.bottom(0), mesh.inner(0));
    let nodes = mesh
        .nodes()
        .iter()
        .enumerate()
        .map(|(k, x)| {
            let held = contact.is_none_or(|c| x[0] <= c * (1.0 + 1e-12));
            let (on_mid, on_axis) = (
                held && bottom.contains(&k),
                plate.hole_radius() == 0.0 && inner.contains(&k),
            );
            let code = match (on_mid, on_axis) {
                (true, true) => Code::Both,
                (true, false) => Code::Z,
                (false, true) => Code::R,
                _ => Code::Free,
            };
            DeckNode {
                n: k + 1,
                code,
                r: x[0],
                z: x[1],
                xr: 0.0,
                xz: 0.0,
                t: 0.0,
                line: 0,
                generated: false,
            }
        })
        .collect();
    let mut elements: Vec<DeckElement> = Vec::new();
    for e in 0..mesh.n_elements() {
        let nodes: Vec<usize> = mesh.element_nodes(e).iter().map(|n| n + 1).collect();
        let nodes = [nodes[0], nodes[1], nodes[2], nodes[3]];
        let generated = e + 1 < mesh.n_elements()
            && elements
                .last()
                .is_some_and(|p| p.nodes.map(|v| v + 1) == nodes);
        elements.push(DeckElement {
            n: e + 1,
            nodes,
            material: 1,
            line: 0,
            generated,
        });
    }
    let top = mesh.top(0);
    let tol = 1e-12 * load.outer();
    let pressures = top
        .windows(2)
        .filter_map(|w| {
            let (r0, r1) = (mesh.nodes()[w[0]][0], mesh.nodes()[w[1]][0]);
            (r0 >= load.inner() - tol && r1 <= load.outer() + tol).then(|| PressureCard {
                i: w[1] + 1,
                j: w[0] + 1,
                p: load.pressure_at(0.5 * (r0 + r1)),
                line: 0,
            })
        })
        .collect();
    let material = DeckMaterial {
        id: 1,
        sigma_z0: 0.0,
        sigma_r0: 0.0,
        table: vec![[0.0, m.youngs_modulus(), m.poisson_ratio(), 0.0]],
        line: 0,
    };
    Ok(Deck {
        appendix: Appendix::B,
        title: title.to_string(),
        line: 0,
        norm: 0,
        t_ref: 0.0,
        materials: vec![material],
        nodes,
        elements,
        pressures,
    })
}
