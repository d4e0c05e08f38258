//! The rules of a deck that matter to the result, checked after generation: element nodes and
//! materials exist, nodes run counter-clockwise around every element and each of its triangles
//! has positive area, pressure cards name an element edge with the element on the left, and every
//! node belongs to an element (or is fixed in both directions).
//!
//! # Accuracy
//!
//! Not numerical: every rule is exercised by `tests/io/read.rs`
//! (`bad_decks_name_line_columns_and_field`) and the mutated decks of `tests/io/mutants.rs`.
//!
//! # Cost
//!
//! Linear in the cards.

use super::model::{Code, Deck, DeckElement};
use super::DeckError;

/// Signed double area of the triangle (a, b, c): positive when counter-clockwise in (r, z).
pub(crate) fn double_area(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
}

/// The directed edges I→J of an element (three for a triangle).
pub(crate) fn element_edges(e: &DeckElement) -> Vec<(usize, usize)> {
    let n = e.nodes;
    if e.is_triangle() {
        vec![(n[0], n[1]), (n[1], n[2]), (n[2], n[0])]
    } else {
        (0..4).map(|k| (n[k], n[(k + 1) % 4])).collect()
    }
}

fn element_error(e: &DeckElement, field: &str, value: String, reason: &str) -> DeckError {
    let what = if e.generated {
        format!("generated element {}: {reason}", e.n)
    } else {
        format!("element {}: {reason}", e.n)
    };
    DeckError::new(e.line, field, &value, &what)
}

/// Checks `deck` (see the module doc).
pub(crate) fn check(deck: &Deck) -> Result<(), DeckError> {
    let nn = deck.nodes.len();
    let mut used = vec![false; nn];
    for e in &deck.elements {
        for (k, &v) in e.nodes.iter().enumerate() {
            if v == 0 || v > nn {
                let f = format!("element node {}", ["I", "J", "K", "L"][k]);
                let err = element_error(e, &f, v.to_string(), "no such nodal point");
                return Err(if e.generated {
                    err
                } else {
                    err.at_columns(6 + 5 * k, 10 + 5 * k)
                });
            }
            used[v - 1] = true;
        }
        if e.material == 0 || e.material > deck.materials.len() {
            let err = element_error(
                e,
                "material number",
                e.material.to_string(),
                "no such material",
            );
            return Err(if e.generated {
                err
            } else {
                err.at_columns(26, 30)
            });
        }
        let n = e.nodes;
        let distinct = if e.is_triangle() { 3 } else { 4 };
        let repeated = (0..distinct).any(|a| (0..a).any(|b| n[a] == n[b]));
        let nodes = format!("{},{},{},{}", n[0], n[1], n[2], n[3]);
        if repeated {
            return Err(element_error(
                e,
                "element nodes I,J,K,L",
                nodes,
                "a node repeated (only a triangle I,J,K,K may repeat K)",
            ));
        }
        let x = n.map(|v| [deck.nodes[v - 1].r, deck.nodes[v - 1].z]);
        let tris: Vec<[[f64; 2]; 3]> = if e.is_triangle() {
            vec![[x[0], x[1], x[2]]]
        } else {
            let c = [0, 1].map(|i| x.iter().map(|p| p[i]).sum::<f64>() / 4.0);
            (0..4).map(|k| [x[k], x[(k + 1) % 4], c]).collect()
        };
        if tris.iter().any(|t| {
            double_area(t[0], t[1], t[2]).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
        }) {
            return Err(element_error(
                e,
                "element nodes I,J,K,L",
                nodes,
                "zero or negative area: nodes must run counter-clockwise around a convex element",
            ));
        }
    }
    for p in &deck.pressures {
        let field = "pressure card I, J";
        let value = format!("{},{}", p.i, p.j);
        if p.i == 0 || p.j == 0 || p.i > nn || p.j > nn {
            return Err(
                DeckError::new(p.line, field, &value, "no such nodal point").at_columns(1, 10)
            );
        }
        let on_edge = deck
            .elements
            .iter()
            .any(|e| element_edges(e).contains(&(p.i, p.j)));
        if !on_edge {
            return Err(DeckError::new(
                p.line,
                field,
                &value,
                "not an element edge run with its element on the left (I to J counter-clockwise)",
            )
            .at_columns(1, 10));
        }
    }
    for (node, &u) in deck.nodes.iter().zip(&used) {
        if !u && node.code != Code::Both {
            return Err(DeckError::new(
                node.line,
                "node number",
                &node.n.to_string(),
                "belongs to no element and is not fixed (code 3): the stiffness would be singular",
            )
            .at_columns(1, 5));
        }
    }
    Ok(())
}
