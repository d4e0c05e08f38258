//! Reading decks: split the file at `*****` cards, read each deck's cards in the listing's
//! order (title, control, materials, nodes, elements, pressures), generate omitted nodes and
//! elements as the listing does, and check the rules that matter to the result.
//!
//! # Accuracy
//!
//! Generation as the listing does it, against hand-computed coordinates: `tests/io/read.rs`
//! (`node_and_element_generation_as_the_listing`,
//! `appendix_c_generated_nodes_interpolate_temperature`); ≥ 10⁴ mutated decks never panic
//! (`tests/io/mutants.rs`).
//!
//! # Cost
//!
//! Linear in the cards; `tests/io/mutants.rs`'s ignored test reads 100 000 mutated decks.

use super::check::check;
use super::model::{Appendix, Code, Deck, DeckElement, DeckMaterial, DeckNode, PressureCard};
use crate::fortran::{Card, Cards, DeckError};
use crate::material::Material;

/// Reads every deck of a file, each as Appendix B or C by its own cards (see
/// [`read_decks_as`]).
pub fn read_decks(text: &str) -> Result<Vec<Deck>, DeckError> {
    read_decks_as(text, None)
}

/// Reads every deck of a file as `appendix`, or, when None, each deck as the appendix its cards
/// fit: C if its control card has a reference temperature (columns 26–35), else B if the deck
/// reads as B, else C. Decks are separated by a card starting `*****`; blank lines at the end of
/// a deck are ignored, a file with no deck is an error.
pub fn read_decks_as(text: &str, appendix: Option<Appendix>) -> Result<Vec<Deck>, DeckError> {
    let mut decks = Vec::new();
    let mut chunk: Vec<Card> = Vec::new();
    let mut last_line = 0;
    for card in Card::lines(text) {
        last_line = card.line;
        if card.text.starts_with("*****") {
            if let Some(d) = read_chunk(std::mem::take(&mut chunk), card.line, appendix)? {
                decks.push(d);
            }
        } else {
            chunk.push(card);
        }
    }
    if let Some(d) = read_chunk(chunk, last_line + 1, appendix)? {
        decks.push(d);
    }
    if decks.is_empty() {
        return Err(DeckError::new(
            last_line.max(1),
            "title card",
            "",
            "the file holds no deck",
        ));
    }
    Ok(decks)
}

fn read_chunk(
    mut cards: Vec<Card>,
    end: usize,
    appendix: Option<Appendix>,
) -> Result<Option<Deck>, DeckError> {
    while cards.last().is_some_and(|c| c.text.trim().is_empty()) {
        cards.pop();
    }
    if cards.is_empty() {
        return Ok(None);
    }
    let read = |a| read_deck(Cards::new(cards.clone(), end), a);
    let deck = match appendix {
        Some(a) => read(a)?,
        None if cards.len() > 1 && !cards[1].columns(26, 35).trim().is_empty() => {
            read(Appendix::C)?
        }
        None => match read(Appendix::B) {
            Ok(d) => d,
            Err(b) => read(Appendix::C).map_err(|c| if c.line > b.line { c } else { b })?,
        },
    };
    Ok(Some(deck))
}

fn read_deck(mut cards: Cards, appendix: Appendix) -> Result<Deck, DeckError> {
    let title = cards.next("title card")?;
    let control = cards.next("control card")?;
    let c = |a, b, f| control.count(a, b, f);
    let n_nodes = c(1, 5, "number of nodal points")?;
    let n_elements = c(6, 10, "number of elements")?;
    let n_materials = c(11, 15, "number of materials")?;
    let norm = control.int(16, 20, "NORM")?;
    let n_pressures = c(21, 25, "number of pressure cards")?;
    for (v, f, a, min) in [
        (n_nodes, "number of nodal points", 1, 3),
        (n_elements, "number of elements", 6, 1),
        (n_materials, "number of materials", 11, 1),
    ] {
        if v < min {
            return Err(control.error(a, a + 4, f, &v.to_string(), "too few for a mesh"));
        }
    }
    if norm != 0 {
        return Err(control.error(16, 20, "NORM", &norm.to_string(), "only NORM = 0 (E in psi, no normalisation) is supported: the report says to use NORM = 0"));
    }
    let t_ref = match appendix {
        Appendix::B => 0.0,
        Appendix::C => control.real(26, 35, 0, "reference temperature")?,
    };
    let materials = read_materials(&mut cards, n_materials, appendix)?;
    let nodes = read_nodes(&mut cards, n_nodes, appendix)?;
    let elements = read_elements(&mut cards, n_elements)?;
    let mut pressures = Vec::with_capacity(n_pressures.min(1 << 16));
    for _ in 0..n_pressures {
        let card = cards.next("pressure card")?;
        pressures.push(PressureCard {
            i: card.count(1, 5, "pressure card I")?,
            j: card.count(6, 10, "pressure card J")?,
            p: card.real(11, 20, 0, "pressure")?,
            line: card.line,
        });
    }
    if let Some(extra) = cards.rest().first() {
        return Err(DeckError::new(
            extra.line,
            "card after the last pressure card",
            extra.text.trim_end(),
            "an extra card: do the counts on the control card match the deck?",
        ));
    }
    let deck = Deck {
        appendix,
        title: title.columns(1, 72).trim_end().to_string(),
        line: title.line,
        norm,
        t_ref,
        materials,
        nodes,
        elements,
        pressures,
    };
    check(&deck)?;
    Ok(deck)
}

fn read_materials(
    cards: &mut Cards,
    n: usize,
    appendix: Appendix,
) -> Result<Vec<DeckMaterial>, DeckError> {
    let mut out: Vec<Option<DeckMaterial>> = vec![None; n];
    for _ in 0..n {
        let card = cards.next("material card")?;
        let id = card.count(1, 5, "material number")?;
        let (rows, sz, sr) = match appendix {
            Appendix::B => (
                1,
                card.real(6, 15, 0, "initial z stress")?,
                card.real(16, 25, 0, "initial r stress")?,
            ),
            Appendix::C => (
                card.count(6, 10, "number of temperatures")?,
                card.real(11, 20, 0, "initial z stress")?,
                card.real(21, 30, 0, "initial r stress")?,
            ),
        };
        if id == 0 || id > n {
            return Err(card.error(
                1,
                5,
                "material number",
                &id.to_string(),
                "must lie between 1 and the number of materials",
            ));
        }
        if out[id - 1].is_some() {
            return Err(card.error(
                1,
                5,
                "material number",
                &id.to_string(),
                "material given twice",
            ));
        }
        if rows == 0 {
            return Err(card.error(
                6,
                10,
                "number of temperatures",
                "0",
                "a material needs at least one temperature card",
            ));
        }
        let mut table: Vec<[f64; 4]> = Vec::new();
        for _ in 0..rows {
            let p = cards.next("material property card")?;
            let row = match appendix {
                Appendix::B => [0.0, p.real(1, 10, 0, "E")?, p.real(11, 20, 0, "nu")?, 0.0],
                Appendix::C => [
                    p.real(1, 10, 0, "temperature")?,
                    p.real(11, 20, 0, "E")?,
                    p.real(21, 30, 0, "nu")?,
                    p.real(31, 40, 0, "alpha")?,
                ],
            };
            let (ce, cn) = match appendix {
                Appendix::B => ((1, 10), (11, 20)),
                Appendix::C => ((11, 20), (21, 30)),
            };
            if let Err(e) = Material::new(row[1], row[2]) {
                let (f, v, cols) = match e {
                    crate::error::InputError::PoissonRatio { .. } => ("nu", row[2], cn),
                    _ => ("E", row[1], ce),
                };
                return Err(p.error(cols.0, cols.1, f, &v.to_string(), &e.to_string()));
            }
            if table.last().is_some_and(|last| row[0] <= last[0]) {
                return Err(p.error(
                    1,
                    10,
                    "temperature",
                    &row[0].to_string(),
                    "the temperatures of a material must increase card by card",
                ));
            }
            table.push(row);
        }
        out[id - 1] = Some(DeckMaterial {
            id,
            sigma_z0: sz,
            sigma_r0: sr,
            table,
            line: card.line,
        });
    }
    Ok(out.into_iter().flatten().collect())
}

fn read_code(card: &Card) -> Result<Code, DeckError> {
    let v = card.real(6, 10, 0, "CODE")?;
    Ok(match v {
        0.0 => Code::Free,
        1.0 => Code::R,
        2.0 => Code::Z,
        3.0 => Code::Both,
        a if (-180.0..=-0.001).contains(&a) => Code::Skew(a),
        _ => {
            return Err(card.error(
                6,
                10,
                "CODE",
                &v.to_string(),
                "must be 0, 1, 2, 3 or a skew angle in degrees between -180 and -0.001",
            ));
        }
    })
}

/// The listing's sequence rules for nodal and element cards: numbers increase, the first card
/// is number 1 (generation needs a card before the gap), none exceeds the control card's count.
fn in_sequence(
    card: &Card,
    field: &str,
    number: usize,
    last: usize,
    count: usize,
) -> Result<(), DeckError> {
    let reason = if number <= last {
        "cards must be in numerical sequence"
    } else if number > count {
        "exceeds the count on the control card"
    } else if last == 0 && number != 1 {
        "the first card must be number 1 (omitted cards are generated from the one before)"
    } else {
        return Ok(());
    };
    Err(DeckError::new(card.line, field, &number.to_string(), reason).at_columns(1, 5))
}

fn read_nodes(cards: &mut Cards, n: usize, appendix: Appendix) -> Result<Vec<DeckNode>, DeckError> {
    let mut nodes: Vec<DeckNode> = Vec::new();
    while nodes.len() < n {
        let card = cards.next("nodal point card")?;
        let number = card.count(1, 5, "node number")?;
        let node = DeckNode {
            n: number,
            code: read_code(&card)?,
            r: card.real(11, 20, 0, "r")?,
            z: card.real(21, 30, 0, "z")?,
            xr: card.real(31, 40, 0, "XR")?,
            xz: card.real(41, 50, 0, "XZ")?,
            t: match appendix {
                Appendix::B => 0.0,
                Appendix::C => card.real(51, 60, 0, "temperature")?,
            },
            line: card.line,
            generated: false,
        };
        let last = nodes.len();
        in_sequence(&card, "node number", number, last, n)?;
        if node.r < 0.0 {
            return Err(card.error(
                11,
                20,
                "r",
                &node.r.to_string(),
                "a radius must not be negative",
            ));
        }
        if let Some(prev) = nodes.last().cloned() {
            let gap = (number - prev.n) as f64;
            for k in prev.n + 1..number {
                let s = (k - prev.n) as f64 / gap;
                let lerp = |a: f64, b: f64| a + s * (b - a);
                nodes.push(DeckNode {
                    n: k,
                    code: Code::Free,
                    r: lerp(prev.r, node.r),
                    z: lerp(prev.z, node.z),
                    xr: 0.0,
                    xz: 0.0,
                    t: lerp(prev.t, node.t),
                    line: card.line,
                    generated: true,
                });
            }
        }
        nodes.push(node);
    }
    Ok(nodes)
}

fn read_elements(cards: &mut Cards, n: usize) -> Result<Vec<DeckElement>, DeckError> {
    let mut out: Vec<DeckElement> = Vec::new();
    while out.len() < n {
        let card = cards.next("element card")?;
        let number = card.count(1, 5, "element number")?;
        let mut nodes = [0; 4];
        for (k, (v, f)) in nodes.iter_mut().zip(["I", "J", "K", "L"]).enumerate() {
            *v = card.count(6 + 5 * k, 10 + 5 * k, &format!("element node {f}"))?;
        }
        let material = card.count(26, 30, "material number")?;
        let last = out.len();
        in_sequence(&card, "element number", number, last, n)?;
        if let Some(prev) = out.last().cloned() {
            for k in 1..number - prev.n {
                out.push(DeckElement {
                    n: prev.n + k,
                    nodes: prev.nodes.map(|v| v + k),
                    material: prev.material,
                    line: card.line,
                    generated: true,
                });
            }
        }
        out.push(DeckElement {
            n: number,
            nodes,
            material,
            line: card.line,
            generated: false,
        });
    }
    Ok(out)
}
