//! The error of a bad deck: the line, the columns when a field is at fault, the field and the
//! value, and what is wrong.
//!
//! # Accuracy
//!
//! Not numerical: the message format is checked by `tests/io/fields.rs` and `tests/io/mutants.rs`.
//!
//! # Cost
//!
//! None.

use std::fmt;

/// A rejected deck. Its message reads `line 12, columns 6-10 (CODE = "x"): not an integer`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct DeckError {
    /// Line of the file (from 1) of the card at fault.
    pub line: usize,
    /// First and last column of the field, when one field is at fault.
    pub columns: Option<(usize, usize)>,
    /// The field, in the report's words (e.g. "CODE", "element node K", "pressure card J").
    pub field: String,
    /// The value found (as written, or as generated).
    pub value: String,
    /// What is wrong.
    pub reason: String,
}

impl DeckError {
    /// An error on `line` about `field` holding `value`.
    pub fn new(line: usize, field: &str, value: &str, reason: &str) -> Self {
        Self {
            line,
            columns: None,
            field: field.to_string(),
            value: value.to_string(),
            reason: reason.to_string(),
        }
    }

    /// The same error located at columns `first..=last`.
    pub fn at_columns(mut self, first: usize, last: usize) -> Self {
        self.columns = Some((first, last));
        self
    }
}

impl fmt::Display for DeckError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}", self.line)?;
        if let Some((a, b)) = self.columns {
            write!(f, ", columns {a}-{b}")?;
        }
        write!(f, " ({} = \"{}\"): {}", self.field, self.value, self.reason)
    }
}
