//! `solve_many`'s result by column: each joint's asked keys read on the worker into cells,
//! then one column per key handed to Python at once — the float and bool columns as raw
//! little-endian bytes that numpy views without a per-value Python object, the others as lists.
//!
//! Method: [`cells`] reads a key from the [`Answer`] through [`Answer::key`] (the scalars
//! directly, the rest from the JSON object); [`to_py`] walks the rows once per
//! column. A missing value (a failed or unfinished joint, or a key the answer lacks) is NaN in a
//! float column, false in a bool column and `None` in a list.
//!
//! # Accuracy
//!
//! Exact: an f64 crosses as its 8 bytes (`python/tests/test_many.py` finds every row equal to
//! the single call's).
//!
//! # Cost
//!
//! One pass over the rows per column; no dict per row (`docs/python.md`, Speed).

use crate::convert;
use crate::engine::Answer;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

/// One key of one joint's answer: its JSON value, None where the answer lacks the key.
pub type Cell = Option<serde_json::Value>;

/// The `keys` of `answer`, in order.
pub fn cells(answer: &Answer, keys: &[String]) -> Vec<Cell> {
    keys.iter().map(|k| answer.key(k)).collect()
}

/// How a column crosses to Python.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// f64 bytes (`numpy.frombuffer(b, "<f8")`), NaN where missing.
    Float,
    /// One byte per row, 0 or 1 (`numpy.frombuffer(b, bool)`), 0 where missing.
    Flag,
    /// A list of Python objects, `None` where missing.
    Objects,
}

impl Kind {
    /// The kind of a pandas dtype name: `float64` and `bool` by bytes, the rest as objects.
    pub fn of_dtype(dtype: &str) -> Self {
        match dtype {
            "float64" => Self::Float,
            "bool" => Self::Flag,
            _ => Self::Objects,
        }
    }
}

/// The columns of `rows` (None: no answer) as a dict key → bytes or list.
pub fn to_py<'py, 'r>(
    py: Python<'py>,
    rows: &[Option<&'r [Cell]>],
    keys: &[(String, Kind)],
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for (j, (key, kind)) in keys.iter().enumerate() {
        let cell = |r: &Option<&'r [Cell]>| -> Option<&'r serde_json::Value> {
            r.and_then(|c| c[j].as_ref())
        };
        let column = match kind {
            Kind::Float => {
                let bytes: Vec<u8> = rows
                    .iter()
                    .flat_map(|r| {
                        let x = cell(r).and_then(serde_json::Value::as_f64);
                        x.unwrap_or(f64::NAN).to_le_bytes()
                    })
                    .collect();
                PyBytes::new(py, &bytes).into_any()
            }
            Kind::Flag => {
                let bytes: Vec<u8> = rows
                    .iter()
                    .map(|r| u8::from(cell(r).and_then(serde_json::Value::as_bool) == Some(true)))
                    .collect();
                PyBytes::new(py, &bytes).into_any()
            }
            Kind::Objects => {
                // a column mostly repeats one value (the units, the method): the previous
                // row's object is reused when the value is the same
                let list = PyList::empty(py);
                let mut last: Option<(&serde_json::Value, Bound<'py, PyAny>)> = None;
                for r in rows {
                    let object = match (cell(r), &last) {
                        (None, _) => py.None().into_bound(py),
                        (Some(v), Some((w, o))) if v == *w => o.clone(),
                        (Some(v), _) => {
                            let o = convert::to_py(py, v)?;
                            last = Some((v, o.clone()));
                            o
                        }
                    };
                    list.append(object)?;
                }
                list.into_any()
            }
        };
        out.set_item(key, column)?;
    }
    Ok(out)
}
