//! Exit codes of the `boltzone` command (a contract other tools rely on):
//!
//! | code | meaning |
//! |---|---|
//! | 0 | answered, and every value met its tolerance |
//! | 1 | anything else (an internal failure of a solver, an I/O error while writing) |
//! | 2 | bad input: the message names the flag or key and the value |
//! | 3 | computed but not converged to the tolerance: the result is printed, flagged |
//!
//! A command returns [`Status`] on success; its errors are classified by [`code_of`]: every
//! library error type says which of its variants are bad input (`is_input`), and the command's
//! own checks raise [`UsageError`].
//!
//! # Accuracy
//!
//! No numerics: the codes are checked by `tests/cli/regressions.rs` and `tests/cli/fuzz.rs` (every
//! command, random arguments, only the codes of the table).
//!
//! # Cost
//!
//! None.

use boltzone::compare::CompareError;
use boltzone::contact::ContactError;
use boltzone::fem::FemError;
use boltzone::hankel::receding::RecedingError;
use boltzone::hankel::separation::SeparationError;
use boltzone::InputError;

/// Whether every value a command printed met its tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Every value met its tolerance (exit 0).
    Converged,
    /// Some value did not (exit 3); the result was printed and flagged.
    NotConverged,
}

impl Status {
    /// `Converged` when `ok`, else `NotConverged`.
    pub fn from_converged(ok: bool) -> Self {
        if ok {
            Self::Converged
        } else {
            Self::NotConverged
        }
    }

    /// The exit code of this status (0 or 3).
    pub fn code(self) -> u8 {
        match self {
            Self::Converged => 0,
            Self::NotConverged => 3,
        }
    }
}

/// A rejected command-line value: the message names the flag and the value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct UsageError(pub String);

/// A number as a person would type it: plain where that is short, else in scientific notation.
pub fn num(x: f64) -> String {
    let plain = format!("{x}");
    if plain.len() <= 12 {
        plain
    } else {
        format!("{x:e}")
    }
}

/// `x` with `digits` significant digits (fixed notation between 1e-3 and 1e6, else scientific).
pub fn sig(x: f64, digits: usize) -> String {
    let m = x.abs();
    if m == 0.0 || (1e-3..1e6).contains(&m) {
        let decimals = (digits as i32 - 1 - m.log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.*e}", digits - 1)
    }
}

/// Returns a [`UsageError`] naming `flag`, `value` and what is wrong.
pub fn usage<T>(flag: &str, value: impl std::fmt::Display, reason: &str) -> anyhow::Result<T> {
    Err(UsageError(format!("{flag} = {value}: {reason}")).into())
}

/// A semi-analytic route could not answer this joint (no contact radius within its scan, a
/// singular system, a hole its modes leave unresolved under `--method auto`): a limit of the
/// method, not bad input. `--method hankel` reports it (exit 1); `--method auto` hands the
/// joint to the finite elements and says why (module `two`). Exit 1 ([`code_of`]).
#[derive(Debug)]
pub struct Declined(pub String);

impl std::fmt::Display for Declined {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "the Hankel route cannot treat this joint ({}); try --method fem",
            self.0
        )
    }
}

impl std::error::Error for Declined {}

/// `e` as the route's [`Declined`] error.
pub fn declined(e: impl std::fmt::Display) -> anyhow::Error {
    Declined(e.to_string()).into()
}

/// The exit code of a failed command: 2 for bad input, 1 otherwise.
pub fn code_of(e: &anyhow::Error) -> u8 {
    let input = e.chain().any(|c| {
        c.is::<UsageError>()
            || c.is::<InputError>()
            || c.downcast_ref::<FemError>().is_some_and(FemError::is_input)
            || c.downcast_ref::<ContactError>()
                .is_some_and(ContactError::is_input)
            || c.downcast_ref::<SeparationError>()
                .is_some_and(SeparationError::is_input)
            || c.downcast_ref::<RecedingError>()
                .is_some_and(RecedingError::is_input)
            || c.downcast_ref::<CompareError>()
                .is_some_and(CompareError::is_input)
            || c.is::<boltzone::fortran::DeckError>()
            || c.is::<boltzone::heat::network::NetworkError>()
    });
    if input {
        2
    } else {
        1
    }
}

/// `value` if finite, else an error (exit 1): a result must never print as NaN, infinity or null.
pub fn finite(what: &str, value: f64) -> anyhow::Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        anyhow::bail!("{what} = {value}: the solver gave no finite value")
    }
}
