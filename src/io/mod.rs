//! Input and output in the report's own formats: the 1970 card decks of Appendices B and C
//! ([`deck`]: read, run on boltzone's finite elements, print as the old program did, and write).
//!
//! # Accuracy
//!
//! Each file's Accuracy section; the test crate is `tests/io/`.
//!
//! # Cost
//!
//! Each file's Cost section.
//!
//! ```
//! // a deck cut short after its control card names the line and the card it expected
//! let err = boltzone::io::deck::read_decks("demo\n    3    1    1    0    0\n").unwrap_err();
//! assert!(err.to_string().starts_with("line 3 (material card"), "{err}");
//! ```

pub mod deck;
pub mod vtu;
