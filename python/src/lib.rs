//! `boltzone._boltzone`: the compiled half of the Python package `boltzone` (PyO3, one abi3
//! wheel for CPython ≥ 3.8). The Python half (`python/boltzone/__init__.py`) builds the
//! DataFrames and meshes; this module turns dicts into scenes, answers them with the library
//! ([`engine`], the one file that calls `boltzone`), solves batches in parallel ([`batch`]) and
//! converts the answers into Python objects ([`convert`]) without any JSON text.
//!
//! Every entry point runs the library under `catch_unwind`: a panic becomes
//! `boltzone.SolverError`, never a Rust panic in Python. Bad input raises `boltzone.InputError`
//! with `.key` (the scene key path, `plates[0].thickness`) and the message naming the value.
//!
//! # Accuracy
//!
//! `python/tests/` (pytest): bit-identity with the CLI, batches, bad input, fuzz.
//!
//! # Cost
//!
//! The library's; keys are converted when read (microseconds per joint).

mod batch;
mod columns;
mod convert;
mod engine;

use engine::Failure;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::sync::Arc;
use std::time::Instant;

pyo3::create_exception!(
    _boltzone,
    InputError,
    PyValueError,
    "Bad input: `.key` names the scene key (or argument), the message the value and why."
);
pyo3::create_exception!(
    _boltzone,
    SolverError,
    pyo3::exceptions::PyRuntimeError,
    "A solver failed on valid input (or an internal error of boltzone)."
);

/// The Python exception of `f` (InputError carries `.key`).
fn raise(py: Python<'_>, f: Failure) -> PyErr {
    match f {
        Failure::Input { key, reason } => {
            let e = InputError::new_err(format!("key `{key}`: {reason}"));
            if let Err(bad) = e.value(py).setattr("key", key) {
                return bad;
            }
            e
        }
        Failure::Solver(m) => SolverError::new_err(m),
    }
}

/// A TypeError from converting a dict becomes an InputError naming the key it mentions.
fn as_input(py: Python<'_>, e: PyErr) -> PyErr {
    if !e.is_instance_of::<PyTypeError>(py) {
        return e;
    }
    let msg = e.value(py).to_string();
    let key = msg
        .strip_prefix("key `")
        .and_then(|r| r.split('`').next())
        .unwrap_or("(scene)")
        .to_string();
    let reason = msg.split_once("`: ").map_or(msg.clone(), |(_, r)| r.into());
    raise(py, Failure::Input { key, reason })
}

/// The scene of the dict `d` (dotted keys allowed at its top level).
fn scene_of(d: &Bound<'_, PyDict>) -> PyResult<Result<boltzone::scene::Scene, Failure>> {
    let py = d.py();
    let table = convert::table(d, "", 0).map_err(|e| as_input(py, e))?;
    Ok(batch::guarded(|| engine::scene(table)))
}

/// A checked scene, held in Rust so that `solve` needs no conversion (built by
/// `check_scene`).
#[pyclass(frozen, module = "boltzone._boltzone")]
struct CoreScene(Arc<boltzone::scene::Scene>);

/// Checks the scene dict as a scene file is checked; returns the scene held in Rust and the
/// scene as understood (defaults filled in, materials of every plate written out). Raises
/// InputError naming the key.
#[pyfunction]
fn check_scene<'py>(d: &Bound<'py, PyDict>) -> PyResult<(CoreScene, Bound<'py, PyAny>)> {
    let py = d.py();
    let scene = scene_of(d)?.map_err(|f| raise(py, f))?;
    let understood = convert::to_py(py, &engine::understood(&scene))?;
    Ok((CoreScene(Arc::new(scene)), understood))
}

/// Parses the TOML text of a scene file (errors name the key and the line) and returns it as a
/// dict of the file's keys.
#[pyfunction]
fn scene_file<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    let table = batch::guarded(|| engine::scene_file(text)).map_err(|f| raise(py, f))?;
    convert::toml_to_py(py, &toml::Value::Table(table))
}

/// The answer to a scene, held in Rust; its keys are converted to Python when asked.
#[pyclass(frozen, module = "boltzone._boltzone")]
struct Answer(engine::Answer);

#[pymethods]
impl Answer {
    /// The value of one key of `solve --json` (KeyError when the answer has none).
    fn get<'py>(&self, py: Python<'py>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        match self.0.key(key) {
            Some(v) => convert::to_py(py, &v),
            None => Err(pyo3::exceptions::PyKeyError::new_err(key.to_string())),
        }
    }

    /// The keys of `solve --json` this answer has.
    fn keys(&self) -> Vec<String> {
        self.0
            .json()
            .as_object()
            .map_or(Vec::new(), |m| m.keys().cloned().collect())
    }

    /// Every key of `solve --json`, as a new dict.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        convert::to_py(py, self.0.json())
    }

    /// The length and stress symbols of the scene's units (`in`, `psi`).
    fn symbols(&self) -> (&'static str, &'static str) {
        self.0.symbols
    }

    /// The interface curve: `radius`, `pressure`, `gap`, `shear` and with friction `slip`,
    /// `state` (None unless asked).
    fn interface<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(c) = &self.0.solution.interface else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("radius", &c.radius)?;
        d.set_item("pressure", &c.pressure)?;
        d.set_item("gap", &c.gap)?;
        d.set_item("shear", &c.shear)?;
        if !c.slip.is_empty() {
            d.set_item("slip", &c.slip)?;
            d.set_item("state", &c.state)?;
        }
        Ok(Some(d))
    }

    /// The field: `points`, `cells`, `plate`, `displacement`, `scalars` (None unless asked).
    fn field<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(g) = &self.0.solution.field else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("points", &g.points)?;
        d.set_item("cells", &g.cells)?;
        d.set_item("plate", &g.plate)?;
        d.set_item("displacement", &g.displacement)?;
        let scalars = PyDict::new(py);
        for (name, v) in &g.scalars {
            scalars.set_item(name, v)?;
        }
        d.set_item("scalars", scalars)?;
        Ok(Some(d))
    }

    /// The midplane stress: `radius`, `sigma_z`, `error` (None unless asked).
    fn midplane<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(m) = &self.0.solution.midplane else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("radius", &m.radius)?;
        d.set_item("sigma_z", &m.sigma_z)?;
        d.set_item("error", &m.error)?;
        Ok(Some(d))
    }
}

/// Answers a checked scene with the library, the GIL released. The field's VTU is written to
/// `[outputs] field` when the scene names it.
#[pyfunction]
fn solve(py: Python<'_>, scene: &CoreScene) -> PyResult<Answer> {
    let start = Instant::now();
    let scene = &scene.0;
    let answer = py
        .detach(|| batch::guarded(|| engine::solve(scene, start)))
        .map_err(|f| raise(py, f))?;
    if let (Some(path), Some(grid)) = (&scene.outputs.field, &answer.solution.field) {
        let text = engine::vtu(grid, answer.symbols);
        engine::write(path, &text).map_err(|e| {
            pyo3::exceptions::PyOSError::new_err(format!("{}: {e}", path.display()))
        })?;
    }
    Ok(Answer(answer))
}

/// Solves the scene dicts in parallel on `threads` threads (0: all cores), the GIL released.
/// `keys` are `(key, dtype)` pairs of the `solve --json` keys wanted. Returns the columns
/// (a dict key → the `float64`/`bool` columns as bytes for `numpy.frombuffer`, the others as
/// lists; [`columns`]), one state byte per joint (0 not finished, 1 answered, 2 failed), each
/// joint's error message (None where it has none) and the exception that stopped the batch
/// early (KeyboardInterrupt: the finished rows are kept).
#[pyfunction]
#[pyo3(signature = (scenes, keys, threads=0, progress=None))]
fn solve_many<'py>(
    scenes: &Bound<'py, PyList>,
    keys: Vec<(String, String)>,
    threads: usize,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let py = scenes.py();
    let mut items = Vec::with_capacity(scenes.len());
    for (i, s) in scenes.iter().enumerate() {
        if let Ok(held) = s.cast::<CoreScene>() {
            items.push(Ok(Arc::clone(&held.get().0)));
            continue;
        }
        let d = s.cast::<PyDict>().map_err(|_| {
            raise(
                py,
                Failure::Input {
                    key: format!("scenes[{i}]"),
                    reason: "not a scene dict".into(),
                },
            )
        })?;
        items.push(match scene_of(d) {
            Ok(scene) => scene.map(Arc::new),
            Err(e) if e.is_instance_of::<InputError>(py) => Err(Failure::Input {
                key: e
                    .value(py)
                    .getattr("key")
                    .and_then(|k| k.extract())
                    .unwrap_or_default(),
                reason: e.value(py).to_string(),
            }),
            Err(e) => return Err(e),
        });
    }
    let names: Vec<String> = keys.iter().map(|(k, _)| k.clone()).collect();
    let kinds: Vec<(String, columns::Kind)> = keys
        .iter()
        .map(|(k, d)| (k.clone(), columns::Kind::of_dtype(d)))
        .collect();
    let outcome = batch::run(py, items, names, threads, progress)?;
    let answered: Vec<Option<&[columns::Cell]>> = outcome
        .rows
        .iter()
        .map(|r| match r {
            Some(Ok(cells)) => Some(cells.as_slice()),
            _ => None,
        })
        .collect();
    let state: Vec<u8> = outcome
        .rows
        .iter()
        .map(|r| match r {
            None => 0,
            Some(Ok(_)) => 1,
            Some(Err(_)) => 2,
        })
        .collect();
    let errors = PyList::empty(py);
    for row in &outcome.rows {
        match row {
            Some(Err(f)) => errors.append(match f {
                Failure::Input { reason, .. } if reason.starts_with("key `") => reason.clone(),
                f => f.to_string(),
            })?,
            _ => errors.append(py.None())?,
        }
    }
    let stopped = match outcome.stopped {
        Some(e) => e.into_value(py).into_bound(py).into_any(),
        None => py.None().into_bound(py),
    };
    let columns = columns::to_py(py, &answered, &kinds)?;
    let state = pyo3::types::PyBytes::new(py, &state);
    Ok((columns, state, errors, stopped)
        .into_pyobject(py)?
        .into_any())
}

/// The report's Table 1 recomputed, rows as `boltzone table1 --json` prints them (lengths in
/// inches).
#[pyfunction]
fn table1(py: Python<'_>, tol: f64, hankel: bool) -> PyResult<Bound<'_, PyAny>> {
    let v = py
        .detach(|| batch::guarded(|| engine::table1_json(tol, hankel)))
        .map_err(|f| raise(py, f))?;
    convert::to_py(py, &v)
}

/// The report's Table 2 recomputed, rows as `boltzone table2 --json` prints them (lengths in
/// inches).
#[pyfunction]
fn table2(py: Python<'_>, tol: f64, welded: bool) -> PyResult<Bound<'_, PyAny>> {
    let v = py
        .detach(|| batch::guarded(|| engine::table2_json(tol, welded)))
        .map_err(|f| raise(py, f))?;
    convert::to_py(py, &v)
}

/// The scene material library (E in Pa, expansion in 1/K, conductivity in W/(m K), HB).
#[pyfunction]
fn materials(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    convert::to_py(py, &engine::materials())
}

/// The report's printed Tables 1 and 2 (lengths in inches).
#[pyfunction]
fn reference(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    convert::to_py(py, &engine::reference())
}

/// The module `boltzone._boltzone`.
#[pymodule]
fn _boltzone(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("SolverError", py.get_type::<SolverError>())?;
    m.add("COMMAND", engine::COMMAND)?;
    m.add("POLL_SECONDS", batch::POLL.as_secs_f64())?;
    m.add_class::<CoreScene>()?;
    m.add_class::<Answer>()?;
    m.add_function(wrap_pyfunction!(check_scene, m)?)?;
    m.add_function(wrap_pyfunction!(scene_file, m)?)?;
    m.add_function(wrap_pyfunction!(solve, m)?)?;
    m.add_function(wrap_pyfunction!(solve_many, m)?)?;
    m.add_function(wrap_pyfunction!(table1, m)?)?;
    m.add_function(wrap_pyfunction!(table2, m)?)?;
    m.add_function(wrap_pyfunction!(materials, m)?)?;
    m.add_function(wrap_pyfunction!(reference, m)?)?;
    Ok(())
}
