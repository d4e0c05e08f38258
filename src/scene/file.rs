//! The scene file: its TOML shape (the issue's contract), parsed with unknown keys rejected,
//! defaults filled in, every value checked, and every error located by key and line (the
//! `toml` parser's spans, `serde_path_to_error` for the key path). Tests: `tests/scene/errors.rs`
//! and the seeded mutations of `tests/scene/fuzz.rs` (10⁴ in its ignored test: 0 panics).
//!
//! # Accuracy
//!
//! Not numerical: `tests/scene/errors.rs` (every error located by key and line) and
//! `tests/scene/fuzz.rs` (`mutated_scenes_never_panic_and_every_error_is_located`).
//!
//! # Cost
//!
//! Linear in the file.
//!
//! ```
//! use boltzone::scene::{Scene, SceneError};
//! let e = Scene::parse("[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\npresure = 1.0\n")
//!     .unwrap_err();
//! assert!(matches!(e, SceneError::Invalid { line: 5, .. }), "{e}");
//! ```

use super::error::SceneError;
use super::materials;
use super::units::UnitSystem;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::PathBuf;
use toml::de::{DeTable, DeValue};

/// Which model answers the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Model {
    /// The report's two-plate model ([`crate::contact::two_plate`]).
    #[default]
    TwoPlate,
    /// The single-plate substitution: one plate 2D thick with the hole.
    SinglePlate,
    /// The infinite slab 2D thick without a hole ([`crate::hankel::Slab`]).
    Slab,
}

/// Which route computes the answer: the route layer's one method enum.
pub use crate::route::Method;

/// Shape of the bearing pressure under head and nut.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ProfileKind {
    /// Uniform over A..B.
    #[default]
    Uniform,
    /// Triangular, peak at A (report Fig. 20(a)).
    PeakA,
    /// Triangular, peak at B (report Fig. 20(b)).
    PeakB,
}

/// Interface model between the two plates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum InterfaceKind {
    /// Only w tied, unilaterally (the library's default).
    #[default]
    Frictionless,
    /// u and w tied inside the contact zone (the report's model).
    Welded,
    /// Coulomb friction with `joint.mu`.
    Friction,
}

/// `[hole]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HoleSpec {
    /// Hole radius A (length unit; 0 for no hole; omitted: `[bolt]`'s clearance hole).
    #[serde(default = "unset")]
    pub radius: f64,
}

/// A radius the scene leaves to `[bolt]` (filled by `bolt_spec::resolve` when the scene is parsed).
fn unset() -> f64 {
    f64::NAN
}

impl Default for HoleSpec {
    fn default() -> Self {
        Self { radius: unset() }
    }
}

/// `[load]`: exactly one of `force`, `pressure`, `nut_displacement`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// Outer radius B of the bearing face (length unit; omitted: `[bolt]`'s head or washer).
    #[serde(default = "unset")]
    pub outer_radius: f64,
    /// Outer radius B₂ of the nut's bearing face on the lower plate, carrying the same force
    /// (length unit; omitted: B, or with `[bolt]` and no `outer_radius` the nut's own d_w/2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nut_outer_radius: Option<f64>,
    /// Bolt force (force unit): mean pressure F / (π(B² − A²)).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<f64>,
    /// Mean bearing pressure (stress unit).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure: Option<f64>,
    /// Uniform displacement of each face under the nut (length unit; report Fig. 21).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nut_displacement: Option<f64>,
    /// Pressure profile.
    #[serde(default)]
    pub profile: ProfileKind,
}

impl Default for LoadSpec {
    fn default() -> Self {
        Self {
            outer_radius: unset(),
            nut_outer_radius: None,
            force: None,
            pressure: None,
            nut_displacement: None,
            profile: ProfileKind::Uniform,
        }
    }
}

/// Elastic constants given in the scene (stress unit for E).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Constants {
    /// Young's modulus (stress unit).
    #[serde(rename = "E")]
    pub e: f64,
    /// Poisson's ratio.
    pub nu: f64,
}

/// A plate's material: a library name or the constants.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum MaterialSpec {
    /// A name of [`materials::LIBRARY`].
    Name(String),
    /// `{ E = …, nu = … }`.
    Constants(Constants),
}

/// One `[[plates]]` entry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenePlate {
    /// Thickness D (length unit).
    pub thickness: f64,
    /// Material (omitted: the plate above's; the top plate's default is `steel-304`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<MaterialSpec>,
}

/// `[joint]`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointSpec {
    /// Outer radius C (length unit); omitted: infinite.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_radius: Option<f64>,
    /// Interface model (default frictionless).
    #[serde(default)]
    pub interface: InterfaceKind,
    /// Friction coefficient μ ≥ 0 (with `interface = "friction"` only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu: Option<f64>,
    /// Fix the outer edge r = C (report Fig. 20(c); default false).
    #[serde(default)]
    pub fixed_edge: bool,
}

/// `[outputs]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// The separation radius R_o (default true).
    #[serde(default = "yes")]
    pub r_o: bool,
    /// CSV of r, p, g at the interface (two-plate).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub interface_pressure: Option<PathBuf>,
    /// VTU of the finest mesh's field (two-plate; single-plate by finite elements).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub field: Option<PathBuf>,
    /// CSV of the midplane normal stress σ_z(r) (single-plate, slab).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub midplane: Option<PathBuf>,
    /// The joint's interface conductance from `[heat]` (two-plate; default false).
    #[serde(default)]
    pub conductance: bool,
    /// CSV of a sweep's results, one row per point.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub results: Option<PathBuf>,
    /// The member stiffness k_P and compliance δ_P, with the rules beside (two-plate; default
    /// false; [`crate::route::joint`]).
    #[serde(default)]
    pub stiffness: bool,
    /// SVG or PNG (by the extension) of the interface pressure against r with B, R_o and the
    /// rules' radii marked, as `two --plot` (two-plate; written by `boltzone solve`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// A calculation report, as `two --report`: Markdown (`.md`, linking the `plot` figures)
    /// or a self-contained HTML page (`.html`, the figures inlined) (two-plate; written by
    /// `boltzone solve`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub report: Option<PathBuf>,
}

impl OutputSpec {
    /// Whether the interface curve is needed: for its CSV, the plot or the report.
    pub fn wants_curve(&self) -> bool {
        self.interface_pressure.is_some() || self.plot.is_some() || self.report.is_some()
    }
}

fn yes() -> bool {
    true
}

impl Default for OutputSpec {
    fn default() -> Self {
        Self {
            r_o: true,
            interface_pressure: None,
            field: None,
            midplane: None,
            conductance: false,
            results: None,
            plot: None,
            report: None,
            stiffness: false,
        }
    }
}

/// The default relative tolerance (the two-plate model's, 0.05 %).
pub const DEFAULT_TOLERANCE: f64 = 5e-4;

fn default_tolerance() -> f64 {
    DEFAULT_TOLERANCE
}

/// A scene: the joint, the load, the model and method, and the outputs wanted (module docs of
/// [`crate::scene`]). Lengths, stresses and forces are in [`Scene::units`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Unit system of every number in the scene (default in-psi-lbf).
    #[serde(default)]
    pub units: UnitSystem,
    /// Model (default two-plate).
    #[serde(default)]
    pub model: Model,
    /// Method (default auto).
    #[serde(default)]
    pub method: Method,
    /// Relative tolerance on every value asked (default 5e-4).
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
    /// The hole (omitted: `[bolt]`'s clearance hole).
    #[serde(default)]
    pub hole: HoleSpec,
    /// The load (omitted with `[bolt]` and `[preload]`).
    #[serde(default)]
    pub load: LoadSpec,
    /// Plates under the head first; one entry = two equal plates.
    pub plates: Vec<ScenePlate>,
    /// The joint's outer radius and interface.
    #[serde(default)]
    pub joint: JointSpec,
    /// Outputs wanted.
    #[serde(default)]
    pub outputs: OutputSpec,
    /// The surfaces and contact conductance law ([`super::heat`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heat: Option<super::heat::HeatSpec>,
    /// Plate temperatures (two-plate model with thermal strains; [`super::temperature`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature: Option<super::temperature_spec::TemperatureSpec>,
    /// A catalogue bolt ([`super::bolt_spec`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bolt: Option<super::bolt_keys::BoltKeys>,
    /// A plain washer under head and nut.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub washer: Option<super::bolt_keys::WasherKeys>,
    /// The bolt's preload.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preload: Option<super::bolt_keys::PreloadKeys>,
    /// Dotted keys mapped to lists of values; the product of the lists is solved.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub sweep: BTreeMap<String, Vec<toml::Value>>,
}

/// One step of a key path (`plates[1].thickness` = Key, Index, Key).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Seg {
    /// A table key.
    Key(String),
    /// An array index.
    Index(usize),
}

/// A key path as written in messages: `plates[1].thickness`.
pub fn path_name(path: &[Seg]) -> String {
    let mut s = String::new();
    for seg in path {
        match seg {
            Seg::Key(k) if s.is_empty() => s += k,
            Seg::Key(k) if k.contains('.') => s += &format!(".\"{k}\""),
            Seg::Key(k) => s += &format!(".{k}"),
            Seg::Index(i) => s += &format!("[{i}]"),
        }
    }
    s
}

/// 1-based line of byte `offset` in `text`.
pub fn line_at(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// The line of the deepest part of `path` that `text` holds (None when the document does not
/// parse or holds none of it).
pub fn line_of(text: &str, path: &[Seg]) -> Option<usize> {
    let root = DeTable::parse(text).ok()?;
    let mut span = None;
    let mut table: Option<&DeTable> = Some(root.get_ref());
    let mut value: Option<&DeValue> = None;
    for seg in path {
        let next = match (seg, table, value) {
            (Seg::Key(k), Some(t), _) => t.get_key_value(k.as_str()).map(|(key, v)| {
                span = Some(key.span().start);
                v
            }),
            (Seg::Index(i), _, Some(DeValue::Array(a))) => a.get(*i).inspect(|v| {
                span = Some(v.span().start);
            }),
            _ => None,
        };
        let Some(next) = next else { break };
        value = Some(next.get_ref());
        table = match next.get_ref() {
            DeValue::Table(t) => Some(t),
            _ => None,
        };
    }
    span.map(|s| line_at(text, s))
}

/// The key a syntax error on `line` belongs to: the table header above it and the key on the
/// line itself (as written).
pub fn key_near(text: &str, line: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let upto = line.min(lines.len());
    let header = |l: &str| {
        let h = l
            .trim()
            .trim_matches(|c| c == '[' || c == ']')
            .trim()
            .to_string();
        (l.trim().starts_with('[') && !h.is_empty() && !h.contains('=')).then_some(h)
    };
    let here = lines.get(line.saturating_sub(1)).copied().unwrap_or("");
    let table = lines[..upto].iter().rev().find_map(|l| header(l));
    let own = here
        .split_once('=')
        .map(|(k, _)| k.trim().trim_matches('"').trim().to_string())
        .filter(|k| !k.is_empty() && !k.starts_with('['));
    match (table, own) {
        (Some(h), Some(k)) if header(here).is_none() => format!("{h}.{k}"),
        (_, Some(k)) => k,
        (Some(h), None) => h,
        (None, None) => "(top level)".into(),
    }
}

impl Scene {
    /// Reads a scene's keys as written: no `[bolt]` filled in, no value checked
    /// ([`Scene::parse`] does both).
    pub(super) fn parse_keys(text: &str) -> Result<Self, SceneError> {
        let de = toml::Deserializer::parse(text).map_err(|e| syntax(text, &e))?;
        let scene: Scene = serde_path_to_error::deserialize(de).map_err(|e| {
            let path: Vec<Seg> = e
                .path()
                .iter()
                .filter_map(|s| match s {
                    serde_path_to_error::Segment::Seq { index } => Some(Seg::Index(*index)),
                    serde_path_to_error::Segment::Map { key } => Some(Seg::Key(key.clone())),
                    _ => None,
                })
                .collect();
            let inner = e.into_inner();
            let line = inner
                .span()
                .map(|s| line_at(text, s.start))
                .or_else(|| line_of(text, &path))
                .unwrap_or(1);
            SceneError::Invalid {
                key: if path.is_empty() {
                    key_near(text, line)
                } else {
                    path_name(&path)
                },
                line,
                reason: inner.message().trim().to_string(),
            }
        })?;
        Ok(scene)
    }

    /// The material of plate `i` as written or inherited from the plate above.
    pub fn material_of(&self, i: usize) -> MaterialSpec {
        self.plates[..self.plates.len().min(i + 1)]
            .iter()
            .rev()
            .find_map(|p| p.material.clone())
            .unwrap_or_else(|| MaterialSpec::Name("steel-304".into()))
    }

    /// The scene with every default written out (what `inputs` in the JSON shows).
    pub fn understood(&self) -> Self {
        let mut s = self.clone();
        for i in 0..s.plates.len() {
            s.plates[i].material = Some(self.material_of(i));
        }
        s
    }
}

/// A TOML syntax error, located.
fn syntax(text: &str, e: &toml::de::Error) -> SceneError {
    let line = e.span().map(|s| line_at(text, s.start)).unwrap_or(1);
    SceneError::Invalid {
        key: key_near(text, line),
        line,
        reason: format!("TOML syntax: {}", e.message().trim()),
    }
}

/// The library names, for messages.
pub fn library_names() -> String {
    materials::names()
}

/// Reads the scene file at `path` as text (its errors name the path).
pub fn read(path: &std::path::Path) -> Result<String, SceneError> {
    std::fs::read_to_string(path).map_err(|source| SceneError::Read {
        path: path.display().to_string(),
        source,
    })
}
