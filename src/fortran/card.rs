//! A card (one line of a deck) and a walk through a deck's cards.
//!
//! # Accuracy
//!
//! `tests/io/fields.rs` (every error names line, columns and field; columns past the line's end
//! read as blanks).
//!
//! # Cost
//!
//! Linear in the columns read.

use super::field;
use super::DeckError;

/// One card (line) of a deck.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Card<'a> {
    /// Line number in the file (from 1).
    pub line: usize,
    /// The text of the line, without its end-of-line.
    pub text: &'a str,
}

impl<'a> Card<'a> {
    /// The card `text` on `line`.
    pub fn new(line: usize, text: &'a str) -> Self {
        Self { line, text }
    }

    /// Every line of `text` as a card, numbered from 1, without `\r`.
    pub fn lines(text: &'a str) -> Vec<Self> {
        text.lines()
            .enumerate()
            .map(|(i, l)| Self::new(i + 1, l.strip_suffix('\r').unwrap_or(l)))
            .collect()
    }

    /// An error about the field in columns `first..=last` holding `value`.
    pub fn error(
        &self,
        first: usize,
        last: usize,
        field: &str,
        value: &str,
        reason: &str,
    ) -> DeckError {
        DeckError::new(self.line, field, value, reason).at_columns(first, last)
    }

    /// The error of a refused field: quoted with its blanks when they are the reason, else
    /// without them.
    fn refused(
        &self,
        first: usize,
        last: usize,
        field: &str,
        raw: &str,
        e: field::Refusal,
    ) -> DeckError {
        let value = if e.blanks { raw } else { raw.trim_matches(' ') };
        self.error(first, last, field, value, &e.reason)
    }

    /// Columns `first..=last` as text (shorter if the line ends first).
    pub fn columns(&self, first: usize, last: usize) -> &'a str {
        let at = |col: usize| {
            self.text
                .char_indices()
                .nth(col)
                .map_or(self.text.len(), |(i, _)| i)
        };
        let (start, end) = (at(first.saturating_sub(1)), at(last));
        &self.text[start..end.max(start)]
    }

    /// An `Iw` field in columns `first..=last`.
    pub fn int(&self, first: usize, last: usize, field: &str) -> Result<i64, DeckError> {
        let raw = self.columns(first, last);
        field::read_integer(raw).map_err(|e| self.refused(first, last, field, raw, e))
    }

    /// A non-negative count or number (`Iw`).
    pub fn count(&self, first: usize, last: usize, field: &str) -> Result<usize, DeckError> {
        let v = self.int(first, last, field)?;
        usize::try_from(v)
            .map_err(|_| self.error(first, last, field, &v.to_string(), "must not be negative"))
    }

    /// An `Fw.d` (or `Ew.d`) field in columns `first..=last` with `d` implied decimals.
    pub fn real(&self, first: usize, last: usize, d: u32, field: &str) -> Result<f64, DeckError> {
        let raw = self.columns(first, last);
        field::read_real(raw, d).map_err(|e| self.refused(first, last, field, raw, e))
    }
}

/// A deck's cards read one after another; running out names the card that was expected.
#[derive(Debug, Clone)]
pub struct Cards<'a> {
    cards: Vec<Card<'a>>,
    pos: usize,
    end: usize,
}

impl<'a> Cards<'a> {
    /// The cards, and the line that follows the last of them (where "the deck ends" is said).
    pub fn new(cards: Vec<Card<'a>>, end: usize) -> Self {
        Self { cards, pos: 0, end }
    }

    /// The next card, or an error naming `expected` at the line after the last card.
    pub fn next(&mut self, expected: &str) -> Result<Card<'a>, DeckError> {
        let c = self.cards.get(self.pos).copied().ok_or_else(|| {
            DeckError::new(self.end, expected, "", "the deck ends before this card")
        })?;
        self.pos += 1;
        Ok(c)
    }

    /// The cards not read yet.
    pub fn rest(&self) -> &[Card<'a>] {
        self.cards.get(self.pos..).unwrap_or(&[])
    }
}
