//! Keys of the `[temperature]` table: the error naming `temperature.KEY` with its line, and
//! "one entry for both plates or two (upper, lower)". Shared by [`super::temperature`],
//! [`super::temperature_table`] and [`super::from_heat`], below all three.
//!
//! ```
//! let e = boltzone::scene::temperature_keys::fail("[temperature]\nalpha = -1\n", "alpha", -1, "negative");
//! assert!(e.to_string().contains("line 2"));
//! ```
//!
//! # Accuracy
//!
//! No numerics: `tests/scene/temperature.rs` (`bad_temperature_tables_name_key_and_line`).
//!
//! # Cost
//!
//! None.

use super::error::SceneError;
use super::file::{line_of, path_name, Seg};

/// The error of `temperature.KEY` = `value`, located in `text`.
pub fn fail(text: &str, key: &str, value: impl std::fmt::Display, reason: &str) -> SceneError {
    let path = [Seg::Key("temperature".into()), Seg::Key(key.into())];
    SceneError::Invalid {
        key: path_name(&path),
        line: line_of(text, &path).unwrap_or(1),
        reason: format!("{value}: {reason}"),
    }
}

/// One or two entries → (upper, lower).
pub fn pair<T: Clone + std::fmt::Debug>(
    text: &str,
    key: &str,
    v: &[T],
) -> Result<[T; 2], SceneError> {
    match v {
        [a] => Ok([a.clone(), a.clone()]),
        [a, b] => Ok([a.clone(), b.clone()]),
        _ => Err(fail(
            text,
            key,
            format!("{v:?}"),
            "give one entry (both plates) or two (upper, lower)",
        )),
    }
}
