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
//! Blank groups (node numbers 0 and value 0) are ignored; fields follow [`super::fortran`]
//! (blank = 0, implied decimals, E/D exponents). The program then looped back for another deck,
//! so a file may hold several; blank cards after the last deck are ignored. Where the listing
//! would silently lose a value, this reader stops with an error instead: a conductance punched
//! from the higher node to the lower (the listing overwrote it with the symmetric entry), one
//! from a node to itself (the listing zeroed the diagonal), a pair or a ground given twice (the
//! listing kept the last), a value without node numbers. The listing held 50 nodes; this reader
//! takes up to [`MAX_NODES`].
//!
//! Errors ([`NetworkDeckError`]) give the line, the columns and the field, and the text found there.
//!
//! Accuracy and robustness: `tests/heat_deck.rs` solves a deck written by hand against the same
//! network built through the API, and feeds hundreds of seeded mutations of it (10⁴ in an ignored
//! test) without a panic, every error naming a line and a field.
//! Cost: linear in the deck's length (the example `examples/15_lap_joint_heat.rs` writes and
//! reads the Chapter V network as a deck).
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

use super::fortran::{columns, integer, real};
use super::network::{Network, NetworkError, NetworkSolution};
use serde::Serialize;
use std::fmt;
use thiserror::Error;

/// The largest N accepted (the 1970 program held 50).
pub const MAX_NODES: usize = 100_000;

/// A deck that cannot be read.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum NetworkDeckError {
    /// A field that cannot be read or holds an inadmissible value.
    #[error("line {line}, columns {first}-{last} ({field}): '{text}' {reason}")]
    Field {
        /// Line number (from 1).
        line: usize,
        /// First column of the field.
        first: usize,
        /// Last column of the field.
        last: usize,
        /// Which field.
        field: String,
        /// Its text.
        text: String,
        /// What is wrong.
        reason: String,
    },
    /// The file ends inside a deck.
    #[error("line {line}: end of file while reading {field} of deck {deck}")]
    End {
        /// The line after the last.
        line: usize,
        /// Deck number (from 1).
        deck: usize,
        /// The field or card expected.
        field: &'static str,
    },
}

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
pub struct DeckSolution {
    /// The deck's title.
    pub title: String,
    /// Nodes and residual.
    #[serde(flatten)]
    pub solution: NetworkSolution,
}

impl NetworkDeck {
    /// Solves the deck's network.
    pub fn solve(&self) -> Result<DeckSolution, NetworkError> {
        Ok(DeckSolution {
            title: self.title.clone(),
            solution: self.network.solve()?,
        })
    }
}

impl fmt::Display for DeckSolution {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{}", self.title)?;
        write!(f, "{}", self.solution)
    }
}

/// Reads every deck of `text` (module docs).
pub fn parse_network_decks(text: &str) -> Result<Vec<NetworkDeck>, NetworkDeckError> {
    let lines: Vec<Vec<char>> = text
        .lines()
        .map(|l| l.trim_end_matches('\r').chars().collect())
        .collect();
    let mut cards = Cards { lines, next: 0 };
    let mut decks = Vec::new();
    while let Some(deck) = read_deck(&mut cards, decks.len() + 1)? {
        decks.push(deck);
    }
    Ok(decks)
}

struct Cards {
    lines: Vec<Vec<char>>,
    next: usize,
}

/// A card being read: its line number and text.
struct Card<'a> {
    line: usize,
    text: &'a [char],
}

impl Cards {
    fn card(&mut self, deck: usize, field: &'static str) -> Result<Card<'_>, NetworkDeckError> {
        let i = self.next;
        match self.lines.get(i) {
            Some(text) => {
                self.next += 1;
                Ok(Card { line: i + 1, text })
            }
            None => Err(NetworkDeckError::End {
                line: i + 1,
                deck,
                field,
            }),
        }
    }
}

impl Card<'_> {
    fn error(&self, first: usize, last: usize, field: String, reason: String) -> NetworkDeckError {
        NetworkDeckError::Field {
            line: self.line,
            first,
            last,
            field,
            text: columns(self.text, first, last),
            reason,
        }
    }

    fn int(
        &self,
        first: usize,
        width: usize,
        field: &dyn Fn() -> String,
    ) -> Result<i64, NetworkDeckError> {
        let last = first + width - 1;
        integer(&columns(self.text, first, last)).map_err(|r| self.error(first, last, field(), r))
    }

    fn real(&self, first: usize, field: &dyn Fn() -> String) -> Result<f64, NetworkDeckError> {
        let last = first + 14;
        real(&columns(self.text, first, last), 8).map_err(|r| self.error(first, last, field(), r))
    }

    /// A node number in 1..=n (0 allowed: a blank group).
    fn node(
        &self,
        first: usize,
        width: usize,
        n: usize,
        field: &dyn Fn() -> String,
    ) -> Result<usize, NetworkDeckError> {
        let v = self.int(first, width, field)?;
        if v < 0 || v as u64 > n as u64 {
            return Err(self.error(
                first,
                first + width - 1,
                field(),
                format!("is not a node number in 1..={n}"),
            ));
        }
        Ok(v as usize)
    }

    /// A group whose node numbers (columns c..c+5) are blank must have no value either.
    fn blank_group(
        &self,
        c: usize,
        v: f64,
        field: &dyn Fn() -> String,
    ) -> Result<(), NetworkDeckError> {
        if v == 0.0 {
            Ok(())
        } else {
            Err(self.error(
                c,
                c + 5,
                field(),
                "is blank but the group has a value".into(),
            ))
        }
    }

    fn last(&self, what: &str) -> Result<bool, NetworkDeckError> {
        Ok(self.int(1, 1, &|| format!("{what}, column 1 (I1): 1 ends the group"))? == 1)
    }
}

/// The first column of group g (0, 1, 2) of a `3(…,E15.8)` card: each group is 21 columns.
fn group_start(g: usize) -> usize {
    2 + 21 * g
}

fn read_deck(cards: &mut Cards, deck: usize) -> Result<Option<NetworkDeck>, NetworkDeckError> {
    // 1. Identification cards until 1 in column 1; blank cards at the end of the file end it.
    let mut title: Vec<String> = Vec::new();
    let mut first_line = None;
    loop {
        if cards.next >= cards.lines.len() && title.is_empty() {
            return Ok(None);
        }
        let card = cards.card(deck, "the identification cards (I1,12A4)")?;
        let line = card.line;
        let text = columns(card.text, 2, 49).trim().to_string();
        let done = card.last("identification card")?;
        if !text.is_empty() {
            title.push(text);
        }
        if first_line.is_none() && (done || !title.is_empty()) {
            first_line = Some(line);
        }
        if done {
            break;
        }
    }
    // 2. N, then the (I1) card.
    let card = cards.card(deck, "the dimension card (I7)")?;
    let n = card.int(1, 7, &|| "dimension N (I7)".into())?;
    if n < 1 || n > MAX_NODES as i64 {
        return Err(card.error(
            1,
            7,
            "dimension N (I7)".into(),
            format!("must be a number of nodes in 1..={MAX_NODES}"),
        ));
    }
    let n = n as usize;
    let card = cards.card(deck, "the card (I1) after the dimension")?;
    card.int(1, 1, &|| "card after the dimension, column 1 (I1)".into())?;
    let mut network =
        Network::new(n).map_err(|e| card.error(1, 1, "dimension N".into(), e.to_string()))?;
    // 3. Conductances.
    let mut seen = std::collections::HashSet::new();
    loop {
        let card = cards.card(deck, "the conductance cards (I1,3(2I3,E15.8))")?;
        for g in 0..3 {
            let c = group_start(g);
            let name = |what: &str| format!("conductance group {}, {what}", g + 1);
            let i = card.node(c, 3, n, &|| name("node i (I3)"))?;
            let j = card.node(c + 3, 3, n, &|| name("node j (I3)"))?;
            let v = card.real(c + 6, &|| name("conductance (E15.8)"))?;
            if i == 0 && j == 0 {
                card.blank_group(c, v, &|| name("nodes i, j (2I3)"))?;
                continue;
            }
            let fail =
                |reason: &str| card.error(c, c + 5, name("nodes i, j (2I3)"), reason.to_string());
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
                card.error(c + 6, c + 20, name("conductance (E15.8)"), e.to_string())
            })?;
        }
        if card.last("conductance card")? {
            break;
        }
    }
    // 4. Ground conductances, ground temperatures, internal powers.
    let names = ["ground conductance", "ground temperature", "internal power"];
    let mut values = [vec![None; n], vec![None; n], vec![None; n]];
    for (k, what) in names.iter().enumerate() {
        loop {
            let card = cards.card(deck, "the ground and power cards (I1,3(I6,E15.8))")?;
            for g in 0..3 {
                let c = group_start(g);
                let name = |f: &str| format!("{what} group {}, {f}", g + 1);
                let i = card.node(c, 6, n, &|| name("node (I6)"))?;
                let v = card.real(c + 6, &|| name("value (E15.8)"))?;
                if i == 0 {
                    card.blank_group(c, v, &|| name("node (I6)"))?;
                    continue;
                }
                if values[k][i - 1].replace((v, card.line, c)).is_some() {
                    return Err(card.error(
                        c,
                        c + 5,
                        name("node (I6)"),
                        format!("has its {what} given twice (the program keeps only the last)"),
                    ));
                }
                if k == 0 && v < 0.0 {
                    return Err(card.error(
                        c + 6,
                        c + 20,
                        name("value (E15.8)"),
                        "must not be negative".into(),
                    ));
                }
            }
            if card.last(what)? {
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
                .map_err(|e| field_error(cards, g.or(*t), "ground", e))?;
        }
        if let Some((qv, _, _)) = q {
            network
                .power(i + 1, *qv)
                .map_err(|e| field_error(cards, *q, "internal power", e))?;
        }
    }
    Ok(Some(NetworkDeck {
        title: title.join("\n"),
        line: first_line.unwrap_or(1),
        network,
    }))
}

/// An error of a value read at (line, column).
fn field_error(
    cards: &Cards,
    at: Option<(f64, usize, usize)>,
    what: &str,
    e: NetworkError,
) -> NetworkDeckError {
    let (line, c) = at.map_or((0, 2), |a| (a.1, a.2));
    let text = cards
        .lines
        .get(line.wrapping_sub(1))
        .map_or(String::new(), |l| columns(l, c, c + 20));
    NetworkDeckError::Field {
        line,
        first: c,
        last: c + 20,
        field: format!("{what} (I6,E15.8)"),
        text,
        reason: e.to_string(),
    }
}
