//! Sweeps: `[sweep]` maps dotted keys (`"load.outer_radius"`, `"plates[1].thickness"`) to
//! lists; every combination of the lists (their product, the first key varying slowest) is a
//! scene of its own, checked like the file and solved in parallel (rayon). Tests:
//! `tests/scene/errors.rs` (`sweep_prints_results_and_csv`), `tests/scene/examples.rs`
//! (the M8 sweep, point by point against the Hankel route). Cost: the points' divided by the
//! cores.
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
pub struct Point {
    /// (dotted key, value) of each swept key.
    pub values: Vec<(String, toml::Value)>,
    /// The scene at this point (no `[sweep]`).
    pub scene: Scene,
}

/// Parses a sweep key: `load.outer_radius`, `plates[1].thickness` or `plates.1.thickness`.
fn parse_key(key: &str) -> Option<Vec<Seg>> {
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
pub fn points(text: &str) -> Result<Vec<Point>, SceneError> {
    let base = Scene::parse(text)?;
    if base.sweep.is_empty() {
        return Ok(vec![Point {
            values: Vec::new(),
            scene: base,
        }]);
    }
    if let Some(p) = &base.outputs.interface_pressure {
        let path = [
            Seg::Key("outputs".into()),
            Seg::Key("interface_pressure".into()),
        ];
        return Err(SceneError::Invalid {
            key: path_name(&path),
            line: line_of(text, &path).unwrap_or(1),
            reason: format!(
                "{}: one file cannot hold every sweep point's curve; drop it or the [sweep]",
                p.display()
            ),
        });
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
    let mut root: toml::Value = toml::from_str(text).map_err(|e| bad(&keys[0].0, e.to_string()))?;
    if let toml::Value::Table(t) = &mut root {
        t.remove("sweep");
    }
    let mut out = Vec::with_capacity(total);
    for n in 0..total {
        let mut rem = n;
        let mut values = Vec::new();
        let mut doc = root.clone();
        for (key, path, list) in keys.iter().rev() {
            let v = list[rem % list.len()].clone();
            rem /= list.len();
            if !set(&mut doc, path, v.clone()) {
                return Err(bad(key, "names no value of the scene".into()));
            }
            values.push((key.clone(), v));
        }
        values.reverse();
        let shown = |v: &[(String, toml::Value)]| {
            v.iter()
                .map(|(k, x)| format!("{k} = {x}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let scene: Scene = serde_path_to_error::deserialize(doc).map_err(|e| {
            let key = e.path().to_string();
            bad(
                &values
                    .iter()
                    .find(|(k, _)| key.starts_with(k.split('[').next().unwrap_or(k)))
                    .map_or(keys[0].0.clone(), |(k, _)| k.clone()),
                format!("at {}: {key}: {}", shown(&values), e.into_inner()),
            )
        })?;
        scene.check(text).map_err(|e| match e {
            SceneError::Invalid { key, reason, .. } => {
                let owner = values
                    .iter()
                    .find(|(k, _)| parse_key(k).is_some_and(|p| path_name(&p) == key))
                    .map_or(keys[0].0.clone(), |(k, _)| k.clone());
                bad(&owner, format!("at {}: {key} {reason}", shown(&values)))
            }
            other => other,
        })?;
        out.push(Point { values, scene });
    }
    Ok(out)
}

/// Solves every point in parallel; `tick` is called once per point finished (a progress bar).
pub fn solve_all(points: &[Point], tick: &(dyn Fn() + Sync)) -> Vec<Result<Solution, SceneError>> {
    points
        .par_iter()
        .map(|p| {
            let r = solve(&p.scene);
            tick();
            r
        })
        .collect()
}
