//! Scenes: one TOML file describes a joint and the question, in the user's own units; the
//! engine runs only the route the question needs (`boltzone solve SCENE.toml`).
//!
//! **What is computed.** The separation radius R_o (and, for the two-plate model, the
//! interface pressure p(r) and gap g(r)) of the joint the scene describes, by the library's
//! routes: `two-plate` → [`crate::contact::two_plate::solve`] (report Chapter II.B, Figs. 4–5),
//! `single-plate` → the Hankel route [`crate::hankel::hole::single_plate_separation`] or the
//! finite elements [`crate::fem::single::solve`] (Fernlund's substitution, report Chapter
//! II.A), `slab` → [`crate::hankel::Slab::separation_radius`] (no hole, infinite). Sign
//! convention: compression negative in stresses, the interface pressure p > 0 in compression.
//! Optional outputs: the finest mesh's field (VTU) and the midplane σ_z (CSV) by [`field`];
//! the joint's interface conductance ∫ h_c(p) dA from a `[heat]` table by [`heat`] (report
//! Chapter V, eq. 1.1).
//!
//! **Units.** `units = "in-psi-lbf"` (default), `"mm-MPa-N"` or `"m-Pa-N"` ([`units`]); the
//! scene is solved in its own units, as `boltzone two` solves in its `--units`, so the same
//! joint gives the same bits from both; a scene with `[temperature]` is converted to SI (m, Pa,
//! N) on the way in and every result back to its own units ([`si`]).
//! Materials by name from [`materials`] or as `{ E, nu }` (E in the scene's stress unit).
//!
//! **Method.** [`mod@file`] parses the TOML (unknown keys are errors; each error names the key,
//! the value and the line), [`check`] checks every value before any work, [`run`] plans and
//! runs one route: `method = "auto"` picks the Hankel root search for R_o alone of a single
//! plate (milliseconds, no FE solve), the FE levels for the two-plate model (its interface
//! curve comes from the same levels, nothing is solved twice); [`sweep`] expands `[sweep]`
//! (or a CSV of geometries, `boltzone solve --geometries`) and solves the points in parallel.
//!
//! # Accuracy
//!
//! Each route's own (see its module); the wrapper adds only the unit conversion: `tests/scene/`
//! (`solve_equals_the_library_call`) checks R_o bit for bit against the library call on every
//! example scene, and `same_joint_in_three_unit_systems` to 1e-12 relative.
//!
//! # Cost
//!
//! The route's cost plus parsing (microseconds): `boltzone solve --explain` prints the time per
//! step; `examples/scenes/` holds the report's cases.
//!
//! ```
//! let scene = boltzone::scene::Scene::parse(
//!     "model = \"slab\"\n[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\npressure = 1.0\n\
//!      [[plates]]\nthickness = 0.1\n",
//! )?;
//! let s = boltzone::solve(&scene)?;
//! assert!(s.converged && s.r_o > 0.31 && s.r_o < 0.6, "R_o = {} in", s.r_o);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod bolt_keys;
pub mod bolt_spec;
pub mod builder;
pub mod check;
pub mod error;
pub mod field;
pub mod file;
pub mod from_heat;
pub mod heat;
pub mod materials;
pub mod run;
pub mod si;
pub mod solution;
pub mod sweep;
pub mod temperature;
pub mod temperature_keys;
mod temperature_spec;
pub mod temperature_table;
pub mod two_fem;
pub mod two_hankel;
pub use crate::units;

pub use builder::SceneBuilder;
pub use error::SceneError;
pub use file::{read, Method, Model, Scene};
pub use run::{solve, Solution, Step};
pub use units::UnitSystem;
