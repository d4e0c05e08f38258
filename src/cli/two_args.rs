//! Arguments of `boltzone two` and their value types, apart from the command so that both of
//! its routes ([`super::two`] for the finite elements, [`super::two_hankel`] for the
//! semi-analytic one) read them without importing each other.
//!
//! # Accuracy
//!
//! No numerics: the values are checked by `two` before any work; `tests/contact/cli.rs`
//! (`bad_input_is_reported_not_panicked`).
//!
//! # Cost
//!
//! Argument parsing only; the solves are timed by `cargo bench --bench contact`.

use super::args::{Element, Geometry, OutputFiles, Units};
use clap::ValueEnum;
use std::path::PathBuf;

/// Which solver computes R_o: the route layer's one method enum.
pub use boltzone::route::Method;

/// Interface model between unequal or dissimilar plates.
#[derive(Debug, Clone, Copy, ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Interface {
    /// u and w tied inside the contact zone (the report's model).
    Welded,
    /// Only w tied, unilaterally; no shear.
    Frictionless,
    /// Unilateral contact with Coulomb friction of coefficient --mu.
    Friction,
}

/// Shape of the bearing pressure under head and nut.
#[derive(Debug, Clone, Copy, ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Shape {
    /// Uniform pressure on A..B.
    Uniform,
    /// Triangular, peak at A (report Fig. 20(a)).
    PeakA,
    /// Triangular, peak at B (report Fig. 20(b)).
    PeakB,
}

/// Arguments of `boltzone two`.
#[derive(Debug, clap::Args, serde::Serialize)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// A, B, D, ν as given (A and B may be left to --bolt).
    #[command(flatten)]
    #[serde(skip)]
    pub(super) given: super::two_bolt_args::GivenGeometry,
    /// A, B, D (the upper plate's thickness; the lower plate's too unless --d2 is given), ν:
    /// the flags', with --bolt's hole and bearing radii where --a, --b are omitted
    /// ([`super::two_bolt::resolve`]).
    #[arg(skip)]
    #[serde(flatten)]
    pub(super) geom: Geometry,
    /// The nut's bearing radius B2 when it differs from B (--b2, or --bolt's nut; None: B).
    #[arg(skip)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) b2: Option<f64>,
    /// The catalogue bolt, its preload and the member stiffness.
    #[command(flatten)]
    #[serde(flatten)]
    pub(super) bolt: super::two_bolt_args::BoltArgs,
    /// Lengths, stresses, moduli and forces in (every flag and every printed number).
    #[command(flatten)]
    #[serde(flatten)]
    pub(super) units: Units,
    /// Thickness of the lower plate (in, or the --units length).
    #[arg(long)]
    pub(super) d2: Option<f64>,
    /// Outer radius C of the plates (in, or the --units length); infinite if omitted.
    #[arg(long)]
    pub(super) c: Option<f64>,
    /// Young's modulus E (psi, or the --units stress; default 28e6 psi, 304 steel, converted).
    #[arg(long)]
    pub(super) e: Option<f64>,
    /// Material of the plates by name (`boltzone materials` lists them): sets --e and --nu from
    /// the library (converted to the --units stress); the lower plate's too unless --material2,
    /// --e2 or --nu2 is given.
    #[arg(long, conflicts_with_all = ["e", "nu"])]
    pub(super) material: Option<String>,
    /// Material of the lower plate by name: sets --e2 and --nu2 from the library.
    #[arg(long, conflicts_with_all = ["e2", "nu2"])]
    pub(super) material2: Option<String>,
    /// Poisson's ratio of the lower plate (default: --nu).
    #[arg(long)]
    pub(super) nu2: Option<f64>,
    /// Young's modulus of the lower plate (default: --e).
    #[arg(long)]
    pub(super) e2: Option<f64>,
    /// Mean bearing pressure P (psi, or the --units stress).
    #[arg(long, default_value_t = 1.0, conflicts_with = "force")]
    pub(super) p: f64,
    /// Bolt force (lbf, or the --units force): sets P = force / (π(B² − A²)).
    #[arg(long)]
    pub(super) force: Option<f64>,
    /// Pressure profile under head and nut.
    #[arg(long, value_enum, default_value_t = Shape::Uniform)]
    pub(super) load: Shape,
    /// Instead of a pressure, a uniform displacement (in, or the --units length) of each face under the nut (Fig. 21).
    #[arg(long)]
    pub(super) nut_displacement: Option<f64>,
    /// Fix the outer edge r = C (Fig. 20(c)).
    #[arg(long)]
    pub(super) fixed_edge: bool,
    /// Interface model for unequal or dissimilar plates (equal plates are exact either way);
    /// frictionless by default, as the library (welded: the report's model, ill-posed for
    /// dissimilar materials).
    #[arg(long, value_enum, default_value_t = Interface::Frictionless)]
    pub(super) interface: Interface,
    /// Coulomb friction coefficient μ ≥ 0 (with --interface friction only).
    #[arg(long)]
    pub(super) mu: Option<f64>,
    /// Element type (q9: the only one whose R_o error estimate is reliable; the linear ones are
    /// cheaper but can miss the tolerance by a factor of three).
    #[arg(long, value_enum, default_value_t = Element::Q9)]
    pub(super) element: Element,
    /// Wanted relative error of R_o.
    #[arg(long, default_value_t = 5e-4)]
    pub(super) tol: f64,
    /// Solver: fem, hankel (R_o and the interface pressure: equal plates with a hole, seconds
    /// not milliseconds; or, with --a 0, any two plates in frictionless contact, milliseconds)
    /// table (equal infinite plates, uniform pressure: the tables built by the 1e-8 route,
    /// microseconds, refused outside them) or auto (the default: the tables wherever their bar
    /// meets --tol, else hankel where it applies and --tol is below 3e-5, else fem; fem also
    /// where the Hankel route declines the joint, with the reason in JSON `fallback`).
    #[arg(long, value_enum, default_value_t = Method::Auto)]
    pub(super) method: Method,
    /// Curve, field and figure files.
    #[command(flatten)]
    #[serde(flatten)]
    pub(super) out: OutputFiles,
    /// The joint's interface conductance and its heat flags.
    #[command(flatten)]
    #[serde(flatten)]
    pub(super) heat: super::two_heat::HeatArgs,
    /// Write a calculation report (inputs, units, version, method, results, rules of thumb,
    /// figures) to this file: Markdown linking the --plot files, or with the extension .html a
    /// self-contained page with the figures inlined as SVG.
    #[arg(long)]
    pub(super) report: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    pub(super) json: bool,
    /// With an answer from the tables: also run one solve by the semi-analytic route at --tol
    /// and print both, with their difference against the summed bars.
    #[arg(long)]
    pub(super) verify: bool,
    /// Treat a plausibility warning (a modulus or pressure that looks like a unit slip, a
    /// deflection beyond 1 % of the plate) as bad input: exit 2 instead of a warning on stderr.
    #[arg(long)]
    pub(super) strict: bool,
}
