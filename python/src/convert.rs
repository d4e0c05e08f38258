//! Python objects to TOML values (a scene given as a dict) and JSON values to Python objects
//! (a result), walked directly: no JSON or TOML text in between.
//!
//! Python → TOML: `bool` → boolean, `int` → integer, `float` (and numpy floats, anything with
//! `__float__` that is not an int) → float, `str` and `os.PathLike` → string, `list`/`tuple` →
//! array, `dict` → table; `None` leaves the key out (a key absent from the file). Anything else
//! is an error naming the key path. JSON → Python: null → `None`, numbers → `int`/`float`
//! (the f64 unchanged), strings, lists, dicts (key order kept).
//!
//! # Accuracy
//!
//! Exact (an f64 goes through as the same 64 bits): `python/tests/test_cli_identity.py`.
//!
//! # Cost
//!
//! Linear in the object.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// Deepest nesting accepted from Python (a scene is 4 levels deep; this stops a cycle).
const MAX_DEPTH: usize = 32;

/// `obj` as a TOML value; `Ok(None)` for Python `None`. `at` is the key path, for messages.
pub fn to_toml(obj: &Bound<'_, PyAny>, at: &str, depth: usize) -> PyResult<Option<toml::Value>> {
    let bad = |what: String| PyErr::new::<PyTypeError, _>(format!("key `{at}`: {what}"));
    if depth > MAX_DEPTH {
        return Err(bad(format!("nested deeper than {MAX_DEPTH} levels")));
    }
    if obj.is_none() {
        return Ok(None);
    }
    if obj.is_instance_of::<PyBool>() {
        return Ok(Some(toml::Value::Boolean(obj.extract()?)));
    }
    if obj.is_instance_of::<PyInt>() {
        return match obj.extract::<i64>() {
            Ok(i) => Ok(Some(toml::Value::Integer(i))),
            Err(_) => Err(bad(format!("{obj}: an integer beyond 64 bits"))),
        };
    }
    if obj.is_instance_of::<PyFloat>() {
        return Ok(Some(toml::Value::Float(obj.extract()?)));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Some(toml::Value::String(s.extract::<String>()?)));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        return Ok(Some(toml::Value::Table(table(d, at, depth)?)));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let mut out = Vec::new();
        for (i, item) in obj.try_iter()?.enumerate() {
            let here = format!("{at}[{i}]");
            match to_toml(&item?, &here, depth + 1)? {
                Some(v) => out.push(v),
                None => return Err(bad(format!("item {i} is None"))),
            }
        }
        return Ok(Some(toml::Value::Array(out)));
    }
    let py = obj.py();
    let os = py.import("os")?;
    if obj.is_instance(&os.getattr("PathLike")?)? {
        let p = os.getattr("fspath")?.call1((obj,))?;
        return to_toml(&p, at, depth + 1);
    }
    // numpy scalars (float64 is a float already): by their dtype's kind
    let kind = obj
        .getattr("dtype")
        .and_then(|d| d.getattr("kind"))
        .and_then(|k| k.extract::<String>());
    match kind.as_deref() {
        Ok("b") => return Ok(Some(toml::Value::Boolean(obj.is_truthy()?))),
        Ok("i" | "u") => return to_toml(&obj.call_method0("__index__")?, at, depth + 1),
        Ok("f") => {
            let x: f64 = obj.call_method0("__float__")?.extract()?;
            return Ok(Some(toml::Value::Float(x)));
        }
        _ => {}
    }
    let ty = obj.get_type().name()?;
    Err(bad(format!(
        "a {ty} is not a scene value (number, string, bool, list or dict)"
    )))
}

/// The dict `d` as a TOML table (keys must be strings; `None` values are left out).
pub fn table(d: &Bound<'_, PyDict>, at: &str, depth: usize) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let Ok(key) = k.extract::<String>() else {
            return Err(PyErr::new::<PyTypeError, _>(format!(
                "key `{at}`: a key {k} that is not a string"
            )));
        };
        let here = if at.is_empty() {
            key.clone()
        } else {
            format!("{at}.{key}")
        };
        if let Some(value) = to_toml(&v, &here, depth + 1)? {
            t.insert(key, value);
        }
    }
    Ok(t)
}

/// The JSON value `v` as a Python object.
pub fn to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64(), n.as_f64()) {
            (Some(i), _, _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u), _) => u.into_pyobject(py)?.into_any(),
            (None, None, Some(x)) => PyFloat::new(py, x).into_any(),
            _ => py.None().into_bound(py),
        },
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(a) => {
            let items: Vec<Bound<'py, PyAny>> =
                a.iter().map(|x| to_py(py, x)).collect::<PyResult<_>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(m) => {
            let d = PyDict::new(py);
            for (k, x) in m {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// The TOML value `v` as a Python object (a scene read from a file, as a dict).
pub fn toml_to_py<'py>(py: Python<'py>, v: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        toml::Value::String(s) => PyString::new(py, s).into_any(),
        toml::Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        toml::Value::Float(x) => PyFloat::new(py, *x).into_any(),
        toml::Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        toml::Value::Datetime(d) => PyString::new(py, &d.to_string()).into_any(),
        toml::Value::Array(a) => {
            let items: Vec<Bound<'py, PyAny>> = a
                .iter()
                .map(|x| toml_to_py(py, x))
                .collect::<PyResult<_>>()?;
            PyList::new(py, items)?.into_any()
        }
        toml::Value::Table(t) => {
            let d = PyDict::new(py);
            for (k, x) in t {
                d.set_item(k, toml_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}
