//! The catalogue's tables as text (`reference/bolts/*.csv`, each with its provenance header):
//! their data rows and cells, and the error of a name no table lists. Shared by the threads
//! ([`super::thread`]) and the holes, heads and washers ([`super::catalogue`]).
//!
//! # Accuracy
//!
//! No numerics: a cell that does not parse is NaN, which the constructors refuse.
//!
//! # Cost
//!
//! A pass over a table of tens of rows per look-up.

/// The data rows of a catalogue table (the header and `#` comments skipped), split at commas.
pub(super) fn rows(table: &str) -> impl Iterator<Item = Vec<&str>> {
    table
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with("# ") && !l.trim().is_empty())
        .map(|l| l.split(',').map(str::trim).collect())
}

/// A number of a catalogue table (NaN where a cell does not parse: the constructors refuse it).
pub(super) fn cell(s: &str) -> f64 {
    s.parse::<f64>().unwrap_or(f64::NAN)
}

/// A name the catalogue does not list, with the names it does.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("\"{name}\" is not a catalogue {what} (known: {known})")]
pub struct NotInCatalogue {
    /// What was looked up ("thread", "ISO 273 clearance hole", …).
    pub what: String,
    /// The name given.
    pub name: String,
    /// The names known (or why the row was refused).
    pub known: String,
}

impl NotInCatalogue {
    /// The error for `name` looked up as `what`, `known` listing the names known.
    pub fn new(what: &str, name: &str, known: &str) -> Self {
        Self {
            what: what.into(),
            name: name.into(),
            known: known.into(),
        }
    }
}
