//! Fixed-column FORTRAN fields, read as the 1970 listing's READ statements read them.
//!
//! A card is one line of the deck, columns counted from 1 (columns 73–80 held sequence numbers
//! and are never read). The edit descriptors the listings use:
//! - `Iw`: an optional sign and digits;
//! - `Fw.d`: a real with or without a decimal point (without one, the last d digits are the
//!   fraction: an implied decimal point; the listings use d = 0), with an optional exponent
//!   written `E±n`, `D±n`, `±n` (FORTRAN's exponent without a letter) or `En`;
//! - `Aw`: text, kept as it stands.
//!
//! Blanks: a blank field, and a field missing because the line ends before it, read as zero.
//! Leading and trailing blanks are ignored. The 1970 compilers read every blank inside a
//! numeric field as a zero (a left-justified `1` in an I5 field was 10000); a deck that ran then
//! had right-justified integers, so the only fields on which the two readings differ are those
//! with a blank BETWEEN characters, and those are rejected rather than guessed. Tabs are rejected
//! (they hide the column count). Every error names the line, the columns and the field.
//!
//! ```
//! use boltzone::io::deck::field::Card;
//! let card = Card::new(3, "   12   -1   1.5E-3   25");
//! assert_eq!(card.int(1, 5, "N")?, 12);
//! assert_eq!(card.int(6, 10, "CODE")?, -1);
//! assert_eq!(card.real(11, 20, 0, "r")?, 1.5e-3);
//! assert_eq!(card.real(21, 30, 2, "z")?, 0.25); // implied decimal point, F10.2
//! assert!(card.int(11, 20, "K").unwrap_err().to_string().contains("line 3, columns 11-20"));
//! # Ok::<(), boltzone::io::deck::DeckError>(())
//! ```

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

    /// An error about the field in columns `first..=last` holding `text`.
    pub fn error(
        &self,
        first: usize,
        last: usize,
        field: &str,
        text: &str,
        reason: &str,
    ) -> DeckError {
        DeckError::new(self.line, field, text, reason).at_columns(first, last)
    }

    /// Columns `first..=last` as text (shorter if the line ends first).
    pub fn columns(&self, first: usize, last: usize) -> &'a str {
        let start = self
            .text
            .char_indices()
            .nth(first - 1)
            .map_or(self.text.len(), |(i, _)| i);
        let end = self
            .text
            .char_indices()
            .nth(last)
            .map_or(self.text.len(), |(i, _)| i);
        &self.text[start..end.max(start)]
    }

    /// The trimmed digits of a numeric field, or an error for tabs and embedded blanks.
    fn numeric(&self, first: usize, last: usize, field: &str) -> Result<&'a str, DeckError> {
        let raw = self.columns(first, last);
        if raw.contains('\t') {
            return Err(self.error(first, last, field, raw, "a tab hides the column count"));
        }
        let t = raw.trim_matches(' ');
        if t.contains(' ') {
            return Err(self.error(
                first,
                last,
                field,
                raw,
                "a blank inside a number (the 1970 compilers read it as 0; write the number without it)",
            ));
        }
        Ok(t)
    }

    /// An `Iw` field in columns `first..=last`.
    pub fn int(&self, first: usize, last: usize, field: &str) -> Result<i64, DeckError> {
        let t = self.numeric(first, last, field)?;
        if t.is_empty() {
            return Ok(0);
        }
        let digits = t.strip_prefix(['+', '-']).unwrap_or(t);
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(self.error(first, last, field, t, "not an integer (I format)"));
        }
        t.parse::<i64>()
            .map_err(|_| self.error(first, last, field, t, "integer out of range"))
    }

    /// A non-negative count or number (`Iw`) that must fit the deck's own ranges.
    pub fn count(&self, first: usize, last: usize, field: &str) -> Result<usize, DeckError> {
        let v = self.int(first, last, field)?;
        usize::try_from(v)
            .map_err(|_| self.error(first, last, field, &v.to_string(), "must not be negative"))
    }

    /// An `Fw.d` (or `Ew.d`) field in columns `first..=last` with `d` implied decimals.
    pub fn real(&self, first: usize, last: usize, d: u32, field: &str) -> Result<f64, DeckError> {
        let t = self.numeric(first, last, field)?;
        if t.is_empty() {
            return Ok(0.0);
        }
        parse_real(t, d)
            .filter(|v| v.is_finite())
            .ok_or_else(|| self.error(first, last, field, t, "not a real number (F/E format)"))
    }
}

/// FORTRAN real input: sign, digits with at most one point, optional exponent.
fn parse_real(t: &str, d: u32) -> Option<f64> {
    let b = t.as_bytes();
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let start = i;
    while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
        i += 1;
    }
    let mantissa = &t[start..i];
    let points = mantissa.matches('.').count();
    if points > 1 || !mantissa.bytes().any(|c| c.is_ascii_digit()) {
        return None;
    }
    let mut exponent: i32 = 0;
    if i < b.len() {
        let mut rest = &t[i..];
        if let Some(r) = rest.strip_prefix(['E', 'e', 'D', 'd']) {
            rest = r;
        } else if !rest.starts_with(['+', '-']) {
            return None;
        }
        let digits = rest.strip_prefix(['+', '-']).unwrap_or(rest);
        if digits.is_empty() || digits.len() > 4 || !digits.bytes().all(|c| c.is_ascii_digit()) {
            return None;
        }
        exponent = rest.parse().ok()?;
    }
    if points == 0 {
        exponent -= d as i32;
    }
    let sign = if t.starts_with('-') { "-" } else { "" };
    format!("{sign}{mantissa}e{exponent}").parse().ok()
}
