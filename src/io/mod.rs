//! Input and output in the report's own formats: the 1970 card decks of Appendices B and C
//! ([`deck`]: read, run on boltzone's finite elements, print as the old program did, and write).
//!
//! ```
//! let decks = boltzone::io::deck::read_decks("demo\n    1    1    1    0    0\n")
//!     .unwrap_err(); // a deck cut short names the line and the card it expected
//! assert!(decks.to_string().contains("line 3"));
//! ```

pub mod deck;
