//! The one method enum of the library ([`Method`]: what a question asks for) and the route that
//! answered ([`Route`]); the command line, scene files and the comparisons all take these.
//!
//! # Accuracy
//!
//! No numerics.
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::route::{Method, Route};
//! assert_eq!(Method::default(), Method::Auto);
//! assert_eq!(Route::Hankel.as_str(), "hankel");
//! ```

use serde::{Deserialize, Serialize};

/// Which method a question asks for.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, clap::ValueEnum, Hash,
)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Axisymmetric finite elements.
    Fem,
    /// The semi-analytic Hankel-transform routes; a question beyond their reach is refused,
    /// naming the input that blocks it.
    Hankel,
    /// The tables built offline by the semi-analytic routes (`boltzone::table`: equal infinite
    /// plates with a hole, frictionless, or the infinite single plate; a uniform pressure):
    /// R_o in microseconds with its bar; a question outside the tables is refused, naming the
    /// input that blocks them.
    Table,
    /// The cheapest route that can meet the tolerance and serve the outputs asked (the
    /// default): the route layer's choice, with its reason.
    #[default]
    Auto,
}

impl Method {
    /// "fem", "hankel", "table" or "auto" (the spelling of flags, scene files and JSON).
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Fem => "fem",
            Self::Hankel => "hankel",
            Self::Table => "table",
            Self::Auto => "auto",
        }
    }
}

/// The route that produced a value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Hash)]
#[serde(rename_all = "kebab-case")]
pub enum Route {
    /// Finite elements.
    Fem,
    /// A semi-analytic Hankel-transform route.
    Hankel,
    /// The tables built offline by the semi-analytic route (`boltzone::table`).
    Table,
}

impl Route {
    /// "fem", "hankel" or "table" (the spelling of JSON and CSV).
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Fem => "fem",
            Self::Hankel => "hankel",
            Self::Table => "table",
        }
    }

    /// The method that asks for exactly this route.
    pub fn method(self) -> Method {
        match self {
            Self::Fem => Method::Fem,
            Self::Hankel => Method::Hankel,
            Self::Table => Method::Table,
        }
    }
}
