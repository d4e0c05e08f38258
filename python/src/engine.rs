//! Every call of the binding into the `boltzone` library, in one file: a scene from a TOML
//! table (dotted keys allowed at the top), its answer as the JSON value of `boltzone solve
//! --json`, the report's tables as the JSON of `boltzone table1 --json` / `table2 --json`, the
//! material library and the report's printed tables. Nothing here knows Python.
//!
//! Method: the scene deserialises from a [`toml::Value`] with the same serde derive as a file
//! ([`boltzone::scene::Scene`], unknown keys rejected) and is checked by
//! [`boltzone::scene::Scene::check`]; the answer is [`boltzone::solve`]'s [`Solution`]
//! serialized with `serde_json::to_value`, stamped with `command` and `seconds` as the CLI
//! stamps it.
//!
//! # Accuracy
//!
//! No numerics of its own: `python/tests/test_cli_identity.py` finds every key bit-identical
//! to the CLI's on Table 1, Table 2, the example scenes and 50 random scenes.
//!
//! # Cost
//!
//! The solver's, plus microseconds for the conversion (`docs/python.md`, Speed).

use boltzone::compare::{table1, table2, CompareParams};
use boltzone::contact::two_plate::InterfaceModel;
use boltzone::io::vtu::Grid;
use boltzone::scene::file::Seg;
use boltzone::scene::{Scene, SceneError, Solution};
use std::time::Instant;

/// What `command` says in the result of a call from Python (the CLI's is its command line).
pub const COMMAND: &str = "boltzone.solve (Python)";

/// Why a scene could not be built or answered.
#[derive(Debug, Clone)]
pub enum Failure {
    /// Bad input: the key path (as in a scene file) and what is wrong.
    Input {
        /// `plates[0].thickness`, or `(scene)` when no key is to blame.
        key: String,
        /// What is wrong, with the value.
        reason: String,
    },
    /// A solver failed on valid input.
    Solver(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Input { key, reason } => write!(f, "key `{key}`: {reason}"),
            Self::Solver(m) => f.write_str(m),
        }
    }
}

impl From<SceneError> for Failure {
    fn from(e: SceneError) -> Self {
        match e {
            SceneError::Invalid { key, reason, .. }
            | SceneError::Key { key, reason }
            | SceneError::Geometry { key, reason, .. } => Self::Input { key, reason },
            e if e.is_input() => Self::Input {
                key: "(scene)".into(),
                reason: e.to_string(),
            },
            e => Self::Solver(e.to_string()),
        }
    }
}

/// The answer to a scene: the library's [`Solution`] and the call's wall time; its JSON
/// object (that of `boltzone solve --json`) is built on first use.
pub struct Answer {
    /// What [`boltzone::solve`] returned (curves and field included).
    pub solution: Solution,
    /// Wall time of the call, seconds.
    pub seconds: f64,
    /// The length and stress symbols of the scene's units (`in`, `psi`).
    pub symbols: (&'static str, &'static str),
    json: std::sync::OnceLock<serde_json::Value>,
}

impl Answer {
    /// The object of `solve --json` (with `command` = [`COMMAND`] and `seconds`).
    pub fn json(&self) -> &serde_json::Value {
        self.json.get_or_init(|| {
            // Solution holds plain numbers, strings and the scene: serialising cannot fail
            let mut v = serde_json::to_value(&self.solution).unwrap_or_default();
            drop_nulls(&mut v);
            if let serde_json::Value::Object(m) = &mut v {
                m.insert("command".into(), COMMAND.into());
                m.insert("seconds".into(), self.seconds.into());
            }
            v
        })
    }

    /// One key of [`Answer::json`]; the scalars read first without building the object (the
    /// same values: serialising a scalar field is what [`Answer::json`] does to it).
    pub fn key(&self, key: &str) -> Option<serde_json::Value> {
        let s = &self.solution;
        let scalar = |v: Result<serde_json::Value, serde_json::Error>| v.ok();
        match key {
            "r_o" => Some(s.r_o.into()),
            "r_o_error" => Some(s.r_o_error.into()),
            "converged" => Some(s.converged.into()),
            "length_unit" => Some(s.length_unit.into()),
            "seconds" => Some(self.seconds.into()),
            "version" => Some(s.version.into()),
            "units" => scalar(serde_json::to_value(s.units)),
            "model" => scalar(serde_json::to_value(s.model)),
            "method" => scalar(serde_json::to_value(s.method)),
            "full_contact" => s.full_contact.map(Into::into),
            "nut_deflection" => s.nut_deflection.map(Into::into),
            "joint_conductance" => s.joint_conductance.map(Into::into),
            "conductance_unit" => s.conductance_unit.map(Into::into),
            "heat_passes" => s.heat_passes.map(Into::into),
            "heat_flow" => s.heat_flow.map(Into::into),
            "heat_flow_unit" => s.heat_flow_unit.map(Into::into),
            _ => self.json().get(key).cloned(),
        }
    }
}

/// Parses a dotted key as `[sweep]` and `--geometries` do (`plates[1].thickness`).
fn dotted(key: &str) -> Option<Vec<Seg>> {
    boltzone::scene::sweep::parse_key(key)
}

/// Sets `path` in `t` to `value`, creating tables, and growing an array by one table when the
/// index is its length (so `plates[0].thickness` works on a scene without `plates`).
fn insert(t: &mut toml::Table, path: &[Seg], value: toml::Value) -> bool {
    let Some((Seg::Key(first), rest)) = path.split_first() else {
        return false;
    };
    let Some(next) = rest.first() else {
        t.insert(first.clone(), value);
        return true;
    };
    let empty = match next {
        Seg::Key(_) => toml::Value::Table(toml::Table::new()),
        Seg::Index(_) => toml::Value::Array(Vec::new()),
    };
    let mut at = t.entry(first.clone()).or_insert(empty);
    for (i, seg) in rest.iter().enumerate() {
        let last = i + 1 == rest.len();
        at = match (seg, at) {
            (Seg::Key(k), toml::Value::Table(t)) if last => {
                t.insert(k.clone(), value);
                return true;
            }
            (Seg::Key(k), toml::Value::Table(t)) => t
                .entry(k.clone())
                .or_insert_with(|| toml::Value::Table(toml::Table::new())),
            (Seg::Index(n), toml::Value::Array(a)) if *n <= a.len() => {
                if *n == a.len() {
                    a.push(toml::Value::Table(toml::Table::new()));
                }
                if last {
                    a[*n] = value;
                    return true;
                }
                &mut a[*n]
            }
            _ => return false,
        };
    }
    false
}

/// The scene of `table` (top-level keys with a `.` or `[` are dotted paths, set after the
/// others in the order given), deserialised and checked as a scene file is.
pub fn scene(table: toml::Table) -> Result<Scene, Failure> {
    let (paths, plain): (Vec<_>, Vec<_>) = table
        .into_iter()
        .partition(|(k, _)| k.contains('.') || k.contains('['));
    let mut t: toml::Table = plain.into_iter().collect();
    for (key, value) in paths {
        let ok = dotted(&key).is_some_and(|p| insert(&mut t, &p, value));
        if !ok {
            return Err(Failure::Input {
                key,
                reason: "not a dotted scene key that can be set (an array index may be at most \
                         the array's length)"
                    .into(),
            });
        }
    }
    let mut scene: Scene =
        serde_path_to_error::deserialize(toml::Value::Table(t)).map_err(|e| {
            // serde_path_to_error writes `plates[0].thickness`, and `.` for the top level
            let path = e.path().to_string();
            let path = if path == "." { String::new() } else { path };
            let reason = e.into_inner().message().trim().to_string();
            Failure::Input {
                key: with_unknown(path, &reason),
                reason,
            }
        })?;
    // [bolt] and [preload] fill the hole, the bearing face and the force as in a scene file
    boltzone::scene::bolt_spec::resolve(&mut scene, "")?;
    scene.check("")?;
    Ok(scene)
}

/// `key` extended by the unknown field that `reason` names (serde's "unknown field `x`").
fn with_unknown(key: String, reason: &str) -> String {
    let field = reason
        .strip_prefix("unknown field `")
        .and_then(|r| r.split('`').next());
    match field {
        Some(f) if !key.ends_with(f) && key.is_empty() => f.to_string(),
        Some(f) if !key.ends_with(f) => format!("{key}.{f}"),
        _ if key.is_empty() => "(scene)".into(),
        _ => key,
    }
}

/// The TOML text of a scene file as a table, after [`Scene::parse`] accepted it (its errors
/// name the key and the line).
pub fn scene_file(text: &str) -> Result<toml::Table, Failure> {
    Scene::parse(text).map_err(|e| match e {
        SceneError::Invalid { key, line, reason } => Failure::Input {
            key,
            reason: format!("(line {line}) {reason}"),
        },
        e => e.into(),
    })?;
    toml::from_str(text).map_err(|e| Failure::Input {
        key: "(file)".into(),
        reason: e.to_string(),
    })
}

/// The scene as understood, defaults filled in (what `inputs` of the JSON shows).
pub fn understood(scene: &Scene) -> serde_json::Value {
    serde_json::to_value(scene.understood()).unwrap_or_default()
}

/// The scene's `[sweep]` is answered by `solve_many`, not here.
fn no_sweep(scene: &Scene) -> Result<(), Failure> {
    match scene.sweep.keys().next() {
        None => Ok(()),
        Some(k) => Err(Failure::Input {
            key: format!("sweep.{k}"),
            reason: "a [sweep] is for `boltzone solve`; from Python give solve_many a DataFrame with one \
                     column per swept key".into(),
        }),
    }
}

/// Answers `scene` ([`boltzone::solve`]); `start` is when the call began (for `seconds`).
pub fn solve(scene: &Scene, start: Instant) -> Result<Answer, Failure> {
    no_sweep(scene)?;
    let solution: Solution = boltzone::solve(scene)?;
    let (l, st, _) = scene.units.symbols();
    Ok(Answer {
        solution,
        seconds: start.elapsed().as_secs_f64(),
        symbols: (l, st),
        json: std::sync::OnceLock::new(),
    })
}

/// The field as VTU text (the CLI's layout), with a note naming the scene's units.
pub fn vtu(grid: &Grid, (l, st): (&str, &str)) -> String {
    let note = format!(
        "boltzone.solve (Python): finest mesh; coordinates, displacements and gap in {l}, \
         stresses and contact_pressure in {st} (compression negative; contact_pressure > 0 in \
         compression)"
    );
    grid.to_vtu(&note)
}

/// Writes `text` to `path` whole or not at all.
pub fn write(path: &std::path::Path, text: &str) -> std::io::Result<()> {
    boltzone::fsutil::write_atomic(path, text.as_bytes())
}

/// The Table 1 rows as `boltzone table1 --json` prints them (in-psi-lbf, a `units` key per
/// row), at relative tolerance `tol` per R_o, with or without the Hankel single-plate column.
pub fn table1_json(tol: f64, hankel: bool) -> Result<serde_json::Value, Failure> {
    check_tolerance(tol)?;
    let params = CompareParams {
        tolerance: tol,
        hankel_check: hankel,
        ..Default::default()
    };
    let rows = table1::compute(&params, &|| ()).map_err(|e| Failure::Solver(e.to_string()))?;
    rows_json(&rows)
}

/// The Table 2 rows as `boltzone table2 --json` prints them (`welded` or `frictionless`).
pub fn table2_json(tol: f64, welded: bool) -> Result<serde_json::Value, Failure> {
    check_tolerance(tol)?;
    let model = if welded {
        InterfaceModel::Welded
    } else {
        InterfaceModel::Frictionless
    };
    let rows = table2::compute(model, tol, &|| ()).map_err(|e| Failure::Solver(e.to_string()))?;
    rows_json(&rows)
}

/// The tables' `tol` check (the CLI's `--tol`).
fn check_tolerance(tol: f64) -> Result<(), Failure> {
    if tol > 0.0 && tol <= 0.5 {
        return Ok(());
    }
    Err(Failure::Input {
        key: "tol".into(),
        reason: format!(
            "{tol}: a relative tolerance on R_o must lie in (0, 0.5] (e.g. 5e-4 = 0.05 %)"
        ),
    })
}

/// `v` without its null object members, at every depth: absent optional values, as the CLI's
/// `print_json` leaves them out.
fn drop_nulls(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(m) => {
            m.retain(|_, x| !x.is_null());
            m.values_mut().for_each(drop_nulls);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(drop_nulls),
        _ => {}
    }
}

/// Rows serialized, each with `units = "in-psi-lbf"` (the tables' lengths are in inches).
fn rows_json(rows: &impl serde::Serialize) -> Result<serde_json::Value, Failure> {
    let mut v = serde_json::to_value(rows).map_err(|e| Failure::Solver(e.to_string()))?;
    drop_nulls(&mut v);
    if let serde_json::Value::Array(rows) = &mut v {
        for row in rows.iter_mut() {
            if let serde_json::Value::Object(m) = row {
                m.insert(
                    "units".into(),
                    boltzone::scene::UnitSystem::default().name().into(),
                );
            }
        }
    }
    Ok(v)
}

/// The material library: name, E (Pa), ν, expansion (1/K), conductivity (W/(m·K)), HB, source.
pub fn materials() -> serde_json::Value {
    let rows: Vec<serde_json::Value> = boltzone::scene::materials::LIBRARY
        .iter()
        .map(|m| {
            serde_json::json!({
                "name": m.name,
                "E [Pa]": m.youngs_modulus,
                "nu": m.poisson_ratio,
                "expansion [1/K]": m.expansion,
                "conductivity [W/(m K)]": m.conductivity,
                "hardness [HB]": m.hardness_hb,
                "source": m.source,
            })
        })
        .collect();
    rows.into()
}

/// The report's printed Tables 1 and 2 ([`boltzone::reference`]).
pub fn reference() -> serde_json::Value {
    serde_json::json!({
        "table1": boltzone::reference::table1(),
        "table2": boltzone::reference::table2(),
    })
}
