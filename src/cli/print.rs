//! How results leave the program: JSON without nulls (an absent quantity is left out, a
//! non-finite number is an error), progress bars on stderr, files written whole through a
//! temporary file.
//!
//! # Accuracy
//!
//! No numerics: `tests/io/json_out.rs` (no null where a number is due) and `tests/cli/` (files whole or not at all).
//!
//! # Cost
//!
//! Linear in the output.

use indicatif::{ProgressBar, ProgressStyle};
use std::path::Path;

/// A progress bar on stderr (indicatif draws nothing when stderr is not a terminal).
pub fn progress(len: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::new(len);
    if let Ok(style) =
        ProgressStyle::with_template("{msg} {bar:40} {pos}/{len} [{elapsed} < {eta}]")
    {
        bar.set_style(style);
    }
    bar.set_message(what.to_string());
    bar
}

/// Keys whose value may be absent (printed as nothing rather than null).
const OPTIONAL_KEYS: [&str; 8] = [
    "cut",
    "observed_order",
    "r_o_over_a",
    "single_hankel",
    "autoradiographic",
    "discrepancy_autoradiographic_percent",
    "outer_radius",
    "hole_history",
];

/// `value` as a JSON value without its null entries, a null under any key but the optional ones
/// being an error naming its `path` (serde_json makes a non-finite number null).
pub fn checked_json<T: serde::Serialize>(
    value: &T,
    path: &str,
) -> anyhow::Result<serde_json::Value> {
    let mut v = serde_json::to_value(value)?;
    strip(&mut v, path)?;
    Ok(v)
}

/// Prints `value` as pretty JSON without its null entries: an absent quantity (no observed rate,
/// no hole) is left out rather than printed as null. serde_json prints a non-finite number as
/// null too: a null under any other key is therefore an error (exit 1), never a silent null.
pub fn print_json<T: serde::Serialize>(value: &T) -> anyhow::Result<()> {
    let v = checked_json(value, "result")?;
    println!("{}", serde_json::to_string_pretty(&v)?);
    Ok(())
}

/// Prints `{"results": [row(0), …, row(n − 1)], …head}` as [`print_json`] would print it whole,
/// but building and checking one row at a time: only the text is held, not every row's value
/// (10⁵ rows: the values took gigabytes). Nothing is printed when a row fails its check.
pub fn print_json_results(
    head: &serde_json::Map<String, serde_json::Value>,
    n: usize,
    row: &dyn Fn(usize) -> anyhow::Result<serde_json::Value>,
) -> anyhow::Result<()> {
    struct Rows<'a>(
        usize,
        &'a dyn Fn(usize) -> anyhow::Result<serde_json::Value>,
    );
    impl serde::Serialize for Rows<'_> {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            use serde::ser::{Error, SerializeSeq};
            let mut seq = s.serialize_seq(Some(self.0))?;
            for i in 0..self.0 {
                let v = (self.1)(i).map_err(|e| S::Error::custom(format!("{e:#}")))?;
                seq.serialize_element(&v)?;
            }
            seq.end()
        }
    }
    struct Whole<'a>(&'a serde_json::Map<String, serde_json::Value>, Rows<'a>);
    impl serde::Serialize for Whole<'_> {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            use serde::ser::SerializeMap;
            // the keys in serde_json's order (sorted), "results" among them
            let mut m = s.serialize_map(Some(self.0.len() + 1))?;
            let mut rows_done = false;
            for (k, v) in self.0 {
                if !rows_done && k.as_str() > "results" {
                    m.serialize_entry("results", &self.1)?;
                    rows_done = true;
                }
                m.serialize_entry(k, v)?;
            }
            if !rows_done {
                m.serialize_entry("results", &self.1)?;
            }
            m.end()
        }
    }
    let text = serde_json::to_string_pretty(&Whole(head, Rows(n, row)))
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    println!("{text}");
    Ok(())
}

fn strip(v: &mut serde_json::Value, path: &str) -> anyhow::Result<()> {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m.iter() {
                if x.is_null() && !OPTIONAL_KEYS.contains(&k.as_str()) {
                    anyhow::bail!("{path}.{k} is not a finite number (NaN or infinite)");
                }
            }
            m.retain(|_, x| !x.is_null());
            for (k, x) in m.iter_mut() {
                strip(x, &format!("{path}.{k}"))?;
            }
        }
        serde_json::Value::Array(a) => {
            for (i, x) in a.iter_mut().enumerate() {
                if x.is_null() {
                    anyhow::bail!("{path}[{i}] is not a finite number (NaN or infinite)");
                }
                strip(x, &format!("{path}[{i}]"))?;
            }
        }
        _ => {}
    }
    Ok(())
}

/// Writes `text` to `path` through a temporary file renamed into place.
pub fn write_output(path: &Path, text: &str) -> anyhow::Result<()> {
    boltzone::plot::write_atomic(path, text.as_bytes())?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// The rules of thumb beside an R_o as one text line: each rule's radius in the length unit `l`
/// and its error against R_o in percent, then the rules left out with the reason.
pub fn rules_line(r: &boltzone::route::rules_beside::Rules, l: &str) -> String {
    let applied = r.rules.iter().map(|x| {
        let name = match x.name {
            "cone" => format!("{:.0}° cone", x.half_angle_degrees),
            other => other.to_string(),
        };
        format!(
            "{name} {} {l} ({:+.1} ± {:.1} %)",
            super::exit::sig(x.radius, 5),
            x.error_percent.value,
            x.error_percent.error
        )
    });
    let left = r
        .left_out
        .iter()
        .map(|x| format!("{} left out: {}", x.name, x.reason));
    format!(
        "rules: {}",
        applied.chain(left).collect::<Vec<_>>().join("; ")
    )
}
