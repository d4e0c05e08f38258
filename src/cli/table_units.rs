//! `--units` on `table1` and `table2`: their JSON rows with every length in the length unit
//! asked and a `units` key per row (ratios and percentages are the same in every system). The
//! text and CSV are [`boltzone::compare::table1::text_in`], [`boltzone::compare::table2::csv_in`]
//! and their kin.
//!
//! # Accuracy
//!
//! One multiplication per length by the exact factor; `tests/compare/table_units.rs` reads the
//! same table in three systems and finds every length in metres equal to 1e-15 relative.
//!
//! # Cost
//!
//! A walk over the JSON rows.

use boltzone::scene::units::INCH;
use boltzone::scene::UnitSystem;
use serde_json::Value;

/// The rows as JSON with the lengths at `paths` (dot-separated keys, `*` for every element of
/// an array; absent or null entries are left alone) converted from inches to `units`, and a
/// `units` key added to every row.
pub(super) fn rows_json(
    rows: &impl serde::Serialize,
    units: UnitSystem,
    paths: &[&str],
) -> anyhow::Result<Value> {
    let mut v = serde_json::to_value(rows)?;
    let k = INCH / units.length();
    if let Value::Array(rows) = &mut v {
        for row in rows {
            for p in paths {
                let keys: Vec<&str> = p.split('.').collect();
                scale(row, &keys, k);
            }
            if let Value::Object(m) = row {
                m.insert("units".into(), units.name().into());
            }
        }
    }
    Ok(v)
}

/// Multiplies the numbers at `keys` under `v` by `k`.
fn scale(v: &mut Value, keys: &[&str], k: f64) {
    match (keys.split_first(), v) {
        (None, Value::Number(n)) => {
            if let Some(x) = n.as_f64().and_then(|x| serde_json::Number::from_f64(x * k)) {
                *n = x;
            }
        }
        (Some((&"*", rest)), Value::Array(items)) => {
            items.iter_mut().for_each(|item| scale(item, rest, k));
        }
        (Some((key, rest)), Value::Object(m)) => {
            if let Some(item) = m.get_mut(*key) {
                scale(item, rest, k);
            }
        }
        _ => {}
    }
}
