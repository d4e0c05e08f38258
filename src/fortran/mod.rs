//! The 1970 programs' punched cards: fixed-column FORTRAN fields read under one blank policy,
//! and the one error type of every card deck (report Appendices B, C and D).
//!
//! **What is read.** A card is one line of a deck, columns counted from 1; a line shorter than a
//! field is padded with blanks, columns past the last field (73–80 held sequence numbers) are
//! never read. The edit descriptors of the listings: `Iw`, an optionally signed integer;
//! `Fw.d` / `Ew.d`, a real with or without a decimal point (without one, the last d digits are
//! the fraction: an implied decimal point; a punched point overrides d) and an optional exponent
//! written `E±n`, `D±n` or just `±n`; `Aw`, text as it stands. No units: a deck's numbers are in
//! its own units.
//!
//! **The blank policy.** ANSI X3.9-1966 (FORTRAN 66), numeric input conversion: leading blanks
//! are not significant and all other blanks are zeros, so a blank field is zero and a
//! left-justified `1` in an `I3` field is 100. A deck that ran in 1970 was punched for that rule;
//! a deck typed today is often left-justified. boltzone reads a numeric field so that it never
//! silently takes a value different from either reading:
//! - an all-blank field, or a field missing because the line ends before it, is 0;
//! - leading blanks are ignored;
//! - every other blank is read both ways, as a zero (the 1970 program) and as nothing (the
//!   author's text); when the two values are equal the field is accepted (`"1.5   "` in F10.0 is
//!   1.5 either way: blanks after the last digit of a fraction), when they differ it is an error
//!   that names the line, the columns, the field and what the 1970 program would have read
//!   (`"1  "` in I3: "read as 100"; `"1.5E2  "`: "read as 1.5E200");
//! - tabs are errors (they hide the column count).
//!
//! **Errors.** [`DeckError`] is the error of every deck reader (`io::deck` for Appendices B and
//! C, `heat::deck` for Appendix D): line, columns when one field is at fault, the field in the
//! report's words, the value found and what is wrong.
//!
//! **Method.** [`Card`] cuts the columns; the field text goes through the policy above
//! ([`field`]) and is converted by Rust's correctly rounded decimal parser. [`Cards`] walks a
//! deck's cards and names the card expected when the deck ends early.
//!
//! # Accuracy
//!
//! `tests/io/fields.rs` checks every rule above on hand-made fields against the values
//! FORTRAN 66 and the written text give (both computed by hand in the test), and that every
//! error names line, columns and field; the mutated-deck tests (`tests/io/mutants.rs`,
//! `tests/heat/deck.rs`) feed seeded edits of valid decks and require an error naming a line
//! and a field, never a panic. Numbers are exact to the correctly rounded double.
//!
//! # Cost
//!
//! Linear in the field width; `tests/io/mutants.rs`'s ignored test reads (and, where valid,
//! runs) 100 000 mutated decks and prints the time.
//!
//! ```
//! use boltzone::fortran::Card;
//! let card = Card::new(3, "   12   -1    1.5E-3        25   1.5    1  ");
//! assert_eq!(card.int(1, 5, "N")?, 12);
//! assert_eq!(card.int(6, 10, "CODE")?, -1);
//! assert_eq!(card.real(11, 20, 0, "r")?, 1.5e-3);
//! assert_eq!(card.real(21, 30, 2, "z")?, 0.25); // implied decimal point, F10.2
//! assert_eq!(card.real(31, 40, 0, "x")?, 1.5); // blanks after a fraction change nothing
//! let e = card.int(41, 43, "K").unwrap_err(); // "1  " in I3: FORTRAN 66 read 100
//! assert!(e.to_string().starts_with("line 3, columns 41-43 (K = \"1  \")"));
//! assert!(e.to_string().contains("read as 100"));
//! # Ok::<(), boltzone::fortran::DeckError>(())
//! ```

mod card;
mod error;
pub mod field;

pub use card::{Card, Cards};
pub use error::DeckError;
