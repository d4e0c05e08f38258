//! Sweeps: `[sweep]` maps dotted keys (`"load.outer_radius"`, `"plates[1].thickness"`) to
//! lists; every combination of the lists (their product, the first key varying slowest) is a
//! scene of its own, checked like the file and solved in parallel (rayon).
//!
//! # Accuracy
//!
//! Each point equals the single call it stands for: `tests/scene/examples.rs`
//! (`m8_sweep_points_equal_the_hankel_route`); the output: `tests/scene/errors.rs`
//! (`sweep_prints_results_and_csv`).
//!
//! # Cost
//!
//! The points' costs divided by the cores (rayon).
//!
//! ```
//! let text = "model = \"slab\"\n[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\n\
//!             pressure = 1.0\n[[plates]]\nthickness = 0.1\n\
//!             [sweep]\n\"plates[0].thickness\" = [0.1, 0.2, 0.3]\n";
//! let pts = boltzone::scene::sweep::points(text)?;
//! assert_eq!(pts.len(), 3);
//! assert_eq!(pts[2].scene.plates[0].thickness, 0.3);
//! # Ok::<(), boltzone::scene::SceneError>(())
//! ```

use super::error::SceneError;
use super::file::{line_of, path_name, Scene, Seg};
use super::run::{solve, Solution};
use rayon::prelude::*;

/// Most points a sweep may have.
pub const MAX_POINTS: usize = 100_000;

/// One point of a sweep: the swept values and the scene they make.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPoint {
    /// (dotted key, value) of each swept key.
    pub values: Vec<(String, toml::Value)>,
    /// The scene at this point (no `[sweep]`).
    pub scene: Scene,
}

/// Parses a sweep key: `load.outer_radius`, `plates[1].thickness` or `plates.1.thickness` (None
/// when it is not one). Also the dotted columns of the Python `solve_many`.
pub fn parse_key(key: &str) -> Option<Vec<Seg>> {
    let mut out = Vec::new();
    for part in key.split('.') {
        let (name, rest) = part.split_once('[').unwrap_or((part, ""));
        if let Ok(i) = name.parse::<usize>() {
            out.push(Seg::Index(i));
        } else if name.is_empty() {
            return None;
        } else {
            out.push(Seg::Key(name.to_string()));
        }
        if !rest.is_empty() {
            out.push(Seg::Index(rest.strip_suffix(']')?.parse().ok()?));
        }
    }
    Some(out)
}

/// Sets `path` in `root` to `value` (tables are created as needed; arrays must hold the index).
fn set(root: &mut toml::Value, path: &[Seg], value: toml::Value) -> bool {
    let Some((last, head)) = path.split_last() else {
        return false;
    };
    let mut at = root;
    for seg in head {
        at = match (seg, at) {
            (Seg::Key(k), toml::Value::Table(t)) => t
                .entry(k.clone())
                .or_insert_with(|| toml::Value::Table(toml::Table::new())),
            (Seg::Index(i), toml::Value::Array(a)) => match a.get_mut(*i) {
                Some(v) => v,
                None => return false,
            },
            _ => return false,
        };
    }
    match (last, at) {
        (Seg::Key(k), toml::Value::Table(t)) => {
            t.insert(k.clone(), value);
            true
        }
        (Seg::Index(i), toml::Value::Array(a)) if *i < a.len() => {
            a[*i] = value;
            true
        }
        _ => false,
    }
}

/// The points of the scene in `text` (one point, the scene itself, without a sweep).
pub fn points(text: &str) -> Result<Vec<SweepPoint>, SceneError> {
    let base = Scene::parse(text)?;
    if base.sweep.is_empty() {
        return Ok(vec![SweepPoint {
            values: Vec::new(),
            scene: base,
        }]);
    }
    let locate =
        |key: &str| line_of(text, &[Seg::Key("sweep".into()), Seg::Key(key.into())]).unwrap_or(1);
    let bad = |key: &str, reason: String| SceneError::Invalid {
        key: path_name(&[Seg::Key("sweep".into()), Seg::Key(key.into())]),
        line: locate(key),
        reason,
    };
    let mut keys = Vec::new();
    let mut total: usize = 1;
    for (key, list) in &base.sweep {
        let path = parse_key(key).ok_or_else(|| bad(key, "not a dotted key".into()))?;
        if matches!(path.first(), Some(Seg::Key(k)) if k == "sweep") {
            return Err(bad(key, "a sweep cannot sweep itself".into()));
        }
        if list.is_empty() {
            return Err(bad(key, "[]: the list of values is empty".into()));
        }
        total = total.saturating_mul(list.len());
        keys.push((key.clone(), path, list.clone()));
    }
    if total > MAX_POINTS {
        let first = &keys[0].0;
        return Err(bad(first, format!("{total} points: at most {MAX_POINTS}")));
    }
    let root = without_sweep(text).map_err(|e| bad(&keys[0].0, e))?;
    let mut out = Vec::with_capacity(total);
    for n in 0..total {
        let mut rem = n;
        let mut assigned = Vec::new();
        for (key, path, list) in keys.iter().rev() {
            assigned.push((key.clone(), path.clone(), list[rem % list.len()].clone()));
            rem /= list.len();
        }
        assigned.reverse();
        out.push(point(text, &root, assigned, &bad)?);
    }
    Ok(out)
}

/// The document of `text` without its `[sweep]`.
fn without_sweep(text: &str) -> Result<toml::Value, String> {
    let mut root: toml::Value = toml::from_str(text).map_err(|e| e.to_string())?;
    if let toml::Value::Table(t) = &mut root {
        t.remove("sweep");
    }
    Ok(root)
}

/// The point of `root` with each (key, path, value) of `assigned` set; errors go through
/// `bad(key, reason)` (located where the value was given).
fn point(
    text: &str,
    root: &toml::Value,
    assigned: Vec<(String, Vec<Seg>, toml::Value)>,
    bad: &dyn Fn(&str, String) -> SceneError,
) -> Result<SweepPoint, SceneError> {
    let mut doc = root.clone();
    for (key, path, v) in &assigned {
        if !set(&mut doc, path, v.clone()) {
            return Err(bad(key, "names no value of the scene".into()));
        }
    }
    let values: Vec<(String, toml::Value)> = assigned.into_iter().map(|(k, _, v)| (k, v)).collect();
    let first = values.first().map_or(String::new(), |(k, _)| k.clone());
    let shown = values
        .iter()
        .map(|(k, x)| format!("{k} = {x}"))
        .collect::<Vec<_>>()
        .join(", ");
    let mut scene: Scene = serde_path_to_error::deserialize(doc).map_err(|e| {
        let key = e.path().to_string();
        let owner = values
            .iter()
            .find(|(k, _)| key.starts_with(k.split('[').next().unwrap_or(k)))
            .map_or(first.clone(), |(k, _)| k.clone());
        bad(&owner, format!("at {shown}: {key}: {}", e.into_inner()))
    })?;
    super::bolt_spec::resolve(&mut scene, text)?;
    scene.check(text).map_err(|e| match e {
        SceneError::Invalid { key, reason, .. } => {
            let owner = values
                .iter()
                .find(|(k, _)| parse_key(k).is_some_and(|p| path_name(&p) == key))
                .map_or(first.clone(), |(k, _)| k.clone());
            bad(&owner, format!("at {shown}: {key} {reason}"))
        }
        other => other,
    })?;
    Ok(SweepPoint { values, scene })
}

/// A CSV cell as a TOML value: a number, a boolean, or else a string (quotes stripped).
fn cell(field: &str) -> toml::Value {
    let f = field.trim();
    if let Ok(x) = f.parse::<f64>() {
        toml::Value::Float(x)
    } else if let Ok(b) = f.parse::<bool>() {
        toml::Value::Boolean(b)
    } else {
        toml::Value::String(f.trim_matches('"').to_string())
    }
}

/// The points of a CSV of geometries applied to the scene in `text`: the header (its first
/// line that is neither blank nor a `#` comment) names dotted scene keys, each further row is
/// one point. Errors name the CSV line and column.
pub fn rows(text: &str, csv: &str) -> Result<Vec<SweepPoint>, SceneError> {
    let base = Scene::parse(text)?;
    let at = |line: usize, key: &str, reason: String| SceneError::Geometry {
        key: key.to_string(),
        line,
        reason,
    };
    if !base.sweep.is_empty() {
        return Err(at(
            1,
            "(file)",
            "the scene has a [sweep]: give one or the other".into(),
        ));
    }
    let mut lines = csv
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((header_line, header)) = lines.next() else {
        return Err(at(1, "(header)", "no header row naming scene keys".into()));
    };
    let keys: Vec<(String, Vec<Seg>)> = header
        .split(',')
        .map(|k| {
            let k = k.trim().trim_matches('"');
            parse_key(k)
                .map(|p| (k.to_string(), p))
                .ok_or_else(|| at(header_line, k, "not a dotted scene key".into()))
        })
        .collect::<Result<_, _>>()?;
    let root = without_sweep(text).map_err(|e| at(1, "(scene)", e))?;
    let mut out = Vec::new();
    for (line, row) in lines {
        let fields: Vec<&str> = row.split(',').collect();
        if fields.len() != keys.len() {
            return Err(at(
                line,
                "(row)",
                format!("{} values for {} columns", fields.len(), keys.len()),
            ));
        }
        if out.len() >= MAX_POINTS {
            return Err(at(line, "(row)", format!("more than {MAX_POINTS} rows")));
        }
        let assigned = keys
            .iter()
            .zip(&fields)
            .map(|((k, p), f)| (k.clone(), p.clone(), cell(f)))
            .collect();
        out.push(point(text, &root, assigned, &|k, r| at(line, k, r))?);
    }
    if out.is_empty() {
        return Err(at(
            header_line,
            "(rows)",
            "no geometry row after the header".into(),
        ));
    }
    Ok(out)
}

/// Solves every point in parallel; `tick` is called once per point finished (a progress bar).
pub fn solve_all(
    points: &[SweepPoint],
    tick: &(dyn Fn() + Sync),
) -> Vec<Result<Solution, SceneError>> {
    points
        .par_iter()
        .map(|p| {
            let r = solve(&p.scene);
            tick();
            r
        })
        .collect()
}
