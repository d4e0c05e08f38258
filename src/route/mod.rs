//! The route layer: one place decides how a question is answered. A question names the joint,
//! the load, the interface, the outputs wanted beyond R_o, a [`Method`] (`fem`, `hankel`, or
//! `auto`, the default) and a tolerance; the layer says which route answers it ([`Route`]), why,
//! and — where the semi-analytic routes cannot — which input keeps them from it. Every front end
//! (the `boltzone` commands, scene files, the comparisons of Tables 1 and 2 and the design map,
//! the teaching page, the Python package) translates its own input into a question here and the
//! answer back into its own words; none of them states a route's reach or makes the `auto` choice.
//!
//! - [`method`]: [`Method`] (asked) and [`Route`] (answered), the one spelling of both;
//! - [`two_plate`]: the two-plate model's routes: [`two_plate::hankel_blocker`] (the reach of the
//!   semi-analytic routes), [`two_plate::plan`] (the choice), [`two_plate::fall_back`] (when
//!   `auto` hands a declined joint to the finite elements);
//! - [`single_plate`]: the single-plate substitute's routes and the semi-analytic route's knobs
//!   for a tolerance;
//! - [`joint`]: the bolted-joint engineer's questions: how k_P is computed, what a catalogue
//!   bolt puts into the joint, the preload, δ_S, Φ and the bearing pressures, the stiffness
//!   rules beside k_P;
//! - [`rules_beside`]: the rules of thumb beside every answer, each with its error against R_o
//!   (or the reason it was left out);
//! - [`sanity`]: warnings for magnitudes that look like a unit slip.
//!
//! `auto` is the cheapest route that can meet the tolerance and serve the outputs: for two
//! plates the tables (`table`) wherever their bar meets the tolerance, else the semi-analytic
//! routes within their reach below [`two_plate::AUTO_BELOW`] (where the finite elements'
//! estimate, which carries 2e-5 of R_o, cannot claim the tolerance), the finite elements
//! otherwise; for the single plate the Hankel route (milliseconds) unless the field, a
//! rigid nut or temperatures ask for the finite elements.
//!
//! # Accuracy
//!
//! No numerics of its own: the routes' (their modules' Accuracy sections).
//!
//! # Cost
//!
//! Microseconds per choice.
//!
//! ```
//! use boltzone::route::{two_plate, Method};
//! use boltzone::{Joint, Material};
//! let joint = Joint::symmetric(0.1, 0.31, 0.1, Material::new(3e7, 0.3)?)?;
//! let q = two_plate::Question { method: Method::Hankel, ..two_plate::Question::new(&joint, 1e-6) };
//! assert!(two_plate::hankel_blocker(&q).is_none());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod joint;
pub mod method;
pub mod reach;
pub mod rules_beside;
pub mod sanity;
pub mod single_plate;
pub mod two_plate;

pub use method::{Method, Route};
