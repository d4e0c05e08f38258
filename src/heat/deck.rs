//! Appendix D card decks: the input of the report's steady-state heat transfer program, read as
//! its FORTRAN listing reads them, into [`Network`]s.
//!
//! Per deck (statements SSHT0005–0030):
//! 1. identification cards `(I1,12A4)` until one with 1 in column 1 (that card's text counts too;
//!    the text is columns 2–49, the title is the non-blank texts joined by new lines);
//! 2. one card `(I7)`: the number of nodes N; one card `(I1)` (the listing reads and ignores it);
//! 3. conductance cards `(I1,3(2I3,E15.8))`: up to three groups i, j, g_ij (columns 2–4, 5–7, 8–22;
//!    23–25, 26–28, 29–43; 44–46, 47–49, 50–64) until a card with 1 in column 1;
//! 4. ground conductances, then ground temperatures, then internal powers, each
//!    `(I1,3(I6,E15.8))` cards (node in columns 2–7, 23–28, 44–49, value in 8–22, 29–43, 50–64)
//!    until a card with 1 in column 1.
//!
//! Blank groups (node numbers 0 and value 0) are ignored; fields are read by
//! [`crate::fortran::Card`] (implied decimals, E/D exponents; a blank field is 0, and a blank
//! that FORTRAN 66 read as a zero and that changes the value is an error). The program then
//! looped back for another deck, so a file may hold several; blank cards after the last deck are ignored. Where the listing
//! would silently lose a value, this reader stops with an error instead: a conductance punched
//! from the higher node to the lower (the listing overwrote it with the symmetric entry), one
//! from a node to itself (the listing zeroed the diagonal), a pair or a ground given twice (the
//! listing kept the last), a value without node numbers. The listing held 50 nodes; this reader
//! takes up to [`MAX_NODES`].
//!
//! Errors ([`DeckError`], the one deck error type) give the line, the columns, the field and
//! the text found there.
//!
//! # Accuracy
//!
//! `tests/heat/deck.rs` solves a deck written by hand against the same network built through
//! the API and against its closed form (`hand_written_deck_equals_the_api_network`), and feeds
//! hundreds of seeded mutations of it (10⁴ in an ignored test) without a panic, every error
//! naming a line and a field (`mutated_decks_never_panic_and_errors_name_line_and_field`).
//!
//! # Cost
//!
//! Linear in the deck's length (example 15 writes and reads the Chapter V network as a deck).
//!
//! ```
//! use boltzone::heat::deck::parse_network_decks;
//! let deck = "\
//! 1TWO NODES IN SERIES
//!       2
//! 1
//! 1  1  2 1.00000000E+00
//! 1     1 1.00000000E+00     2 1.00000000E+00
//! 1     1 1.00000000E+02
//! 1
//! ";
//! let decks = parse_network_decks(deck)?;
//! let s = decks[0].solve()?;
//! assert_eq!(s.title, "TWO NODES IN SERIES");
//! assert!((s.solution.nodes[1].t - 100.0 / 3.0).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::network::{Network, NetworkError, NetworkSolution};
use crate::fortran::{Card, Cards, DeckError};
use serde::Serialize;
use std::fmt;

/// The largest N accepted (the 1970 program held 50).
pub const MAX_NODES: usize = 100_000;

/// One deck: its title, the line it starts on and the network it describes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NetworkDeck {
    /// The identification text.
    pub title: String,
    /// Line of its first card.
    pub line: usize,
    /// The network.
    pub network: Network,
}

/// A solved deck; serializes as `{"title": …, "nodes": [{"n": 1, "t": …, …}], "residual": …}`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NetworkDeckSolution {
    /// The deck's title.
    pub title: String,
    /// Nodes and residual.
    #[serde(flatten)]
    pub solution: NetworkSolution,
}

impl NetworkDeck {
    /// Solves the deck's network.
    pub fn solve(&self) -> Result<NetworkDeckSolution, NetworkError> {
        Ok(NetworkDeckSolution {
            title: self.title.clone(),
            solution: self.network.solve()?,
        })
    }
}

impl fmt::Display for NetworkDeckSolution {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{}", self.title)?;
        write!(f, "{}", self.solution)
    }
}

/// Reads every deck of `text` (module docs).
pub fn parse_network_decks(text: &str) -> Result<Vec<NetworkDeck>, DeckError> {
    let lines = Card::lines(text);
    let end = lines.len() + 1;
    let mut cards = Cards::new(lines, end);
    let mut decks = Vec::new();
    while let Some(deck) = read_deck(&mut cards, decks.len() + 1)? {
        decks.push(deck);
    }
    Ok(decks)
}

/// The next card of deck number `deck`, or an error naming `what` and the deck.
fn next<'a>(cards: &mut Cards<'a>, deck: usize, what: &str) -> Result<Card<'a>, DeckError> {
    cards.next(&format!("{what} of deck {deck}"))
}

/// An error about columns `first..=last` of `card`, quoting them.
fn at(card: &Card, first: usize, last: usize, field: &str, reason: &str) -> DeckError {
    card.error(first, last, field, card.columns(first, last), reason)
}

/// An `E15.8` field starting in column `first`.
fn e15(card: &Card, first: usize, field: &str) -> Result<f64, DeckError> {
    card.real(first, first + 14, 8, field)
}

/// A node number in 1..=n (0 allowed: a blank group) in `width` columns from `first`.
fn node(
    card: &Card,
    first: usize,
    width: usize,
    n: usize,
    field: &str,
) -> Result<usize, DeckError> {
    let last = first + width - 1;
    let v = card.int(first, last, field)?;
    usize::try_from(v).ok().filter(|&v| v <= n).ok_or_else(|| {
        at(
            card,
            first,
            last,
            field,
            &format!("not a node number in 1..={n}"),
        )
    })
}

/// A group whose node numbers (columns c..c+5) are blank must have no value either.
fn blank_group(card: &Card, c: usize, v: f64, field: &str) -> Result<(), DeckError> {
    if v == 0.0 {
        Ok(())
    } else {
        Err(at(
            card,
            c,
            c + 5,
            field,
            "blank, but the group has a value",
        ))
    }
}

/// Whether column 1 (I1) holds the 1 that ends a group of cards.
fn last(card: &Card, what: &str) -> Result<bool, DeckError> {
    Ok(card.int(1, 1, &format!("{what}, column 1 (I1): 1 ends the group"))? == 1)
}

/// The first column of group g (0, 1, 2) of a `3(…,E15.8)` card: each group is 21 columns.
fn group_start(g: usize) -> usize {
    2 + 21 * g
}

fn read_deck(cards: &mut Cards, deck: usize) -> Result<Option<NetworkDeck>, DeckError> {
    // 1. Identification cards until 1 in column 1; blank cards at the end of the file end it.
    let mut title: Vec<String> = Vec::new();
    let mut first_line = None;
    loop {
        if cards.rest().is_empty() && title.is_empty() {
            return Ok(None);
        }
        let card = next(cards, deck, "the identification cards (I1,12A4)")?;
        let text = card.columns(2, 49).trim().to_string();
        let done = last(&card, "identification card")?;
        if !text.is_empty() {
            title.push(text);
        }
        if first_line.is_none() && (done || !title.is_empty()) {
            first_line = Some(card.line);
        }
        if done {
            break;
        }
    }
    // 2. N, then the (I1) card.
    let card = next(cards, deck, "the dimension card (I7)")?;
    let n = card.int(1, 7, "dimension N (I7)")?;
    let n = usize::try_from(n)
        .ok()
        .filter(|n| (1..=MAX_NODES).contains(n))
        .ok_or_else(|| {
            at(
                &card,
                1,
                7,
                "dimension N (I7)",
                &format!("must be a number of nodes in 1..={MAX_NODES}"),
            )
        })?;
    let card = next(cards, deck, "the card (I1) after the dimension")?;
    card.int(1, 1, "card after the dimension, column 1 (I1)")?;
    let mut network =
        Network::new(n).map_err(|e| at(&card, 1, 1, "dimension N", &e.to_string()))?;
    // 3. Conductances.
    let mut seen = std::collections::HashSet::new();
    loop {
        let card = next(cards, deck, "the conductance cards (I1,3(2I3,E15.8))")?;
        for g in 0..3 {
            let c = group_start(g);
            let name = |what: &str| format!("conductance group {}, {what}", g + 1);
            let i = node(&card, c, 3, n, &name("node i (I3)"))?;
            let j = node(&card, c + 3, 3, n, &name("node j (I3)"))?;
            let v = e15(&card, c + 6, &name("conductance (E15.8)"))?;
            if i == 0 && j == 0 {
                blank_group(&card, c, v, &name("nodes i, j (2I3)"))?;
                continue;
            }
            let fail = |reason: &str| at(&card, c, c + 5, &name("nodes i, j (2I3)"), reason);
            if i == 0 || j == 0 {
                return Err(fail("need both node numbers"));
            }
            if i == j {
                return Err(fail("join a node to itself (the program zeroes the diagonal: the value would be lost)"));
            }
            if i > j {
                return Err(fail("must be punched lower node first (the program overwrites AA(i,j) for i > j with AA(j,i): the value would be lost)"));
            }
            if !seen.insert((i, j)) {
                return Err(fail(
                    "are given twice (the program keeps only the last value)",
                ));
            }
            network.connect(i, j, v).map_err(|e| {
                at(
                    &card,
                    c + 6,
                    c + 20,
                    &name("conductance (E15.8)"),
                    &e.to_string(),
                )
            })?;
        }
        if last(&card, "conductance card")? {
            break;
        }
    }
    // 4. Ground conductances, ground temperatures, internal powers.
    let names = ["ground conductance", "ground temperature", "internal power"];
    let mut values: [Vec<Option<(f64, Card, usize)>>; 3] =
        [vec![None; n], vec![None; n], vec![None; n]];
    for (k, what) in names.iter().enumerate() {
        loop {
            let card = next(cards, deck, "the ground and power cards (I1,3(I6,E15.8))")?;
            for g in 0..3 {
                let c = group_start(g);
                let name = |f: &str| format!("{what} group {}, {f}", g + 1);
                let i = node(&card, c, 6, n, &name("node (I6)"))?;
                let v = e15(&card, c + 6, &name("value (E15.8)"))?;
                if i == 0 {
                    blank_group(&card, c, v, &name("node (I6)"))?;
                    continue;
                }
                if values[k][i - 1].replace((v, card, c)).is_some() {
                    return Err(at(
                        &card,
                        c,
                        c + 5,
                        &name("node (I6)"),
                        &format!("has its {what} given twice (the program keeps only the last)"),
                    ));
                }
                if k == 0 && v < 0.0 {
                    return Err(at(
                        &card,
                        c + 6,
                        c + 20,
                        &name("value (E15.8)"),
                        "must not be negative",
                    ));
                }
            }
            if last(&card, what)? {
                break;
            }
        }
    }
    let [grounds, temperatures, powers] = &values;
    for (i, ((g, t), q)) in grounds.iter().zip(temperatures).zip(powers).enumerate() {
        if g.is_some() || t.is_some() {
            let (gv, tv) = (g.map_or(0.0, |v| v.0), t.map_or(0.0, |v| v.0));
            network
                .ground(i + 1, gv, tv)
                .map_err(|e| value_error(g.or(*t), "ground", e))?;
        }
        if let Some((qv, _, _)) = q {
            network
                .power(i + 1, *qv)
                .map_err(|e| value_error(*q, "internal power", e))?;
        }
    }
    Ok(Some(NetworkDeck {
        title: title.join("\n"),
        line: first_line.unwrap_or(1),
        network,
    }))
}

/// The error of a group (node and value, columns c..c+20 of its card) the network refused.
fn value_error(at: Option<(f64, Card, usize)>, what: &str, e: NetworkError) -> DeckError {
    let field = format!("{what} (I6,E15.8)");
    match at {
        Some((_, card, c)) => {
            card.error(c, c + 20, &field, card.columns(c, c + 20), &e.to_string())
        }
        None => DeckError::new(0, &field, "", &e.to_string()),
    }
}
