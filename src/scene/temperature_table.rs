//! The `[temperature]` table's materials: a constant α per plate (`alpha`, E and ν the plates'
//! own) or one table of rows (T, E, ν, α) for both plates (`table`), read between rows as the
//! 1970 listing reads Appendix C's (linearly: [`crate::fem::thermal::interpolate`], the deck
//! runner's). E in the scene's stress unit, α per degree, T in the degrees of the table.
//!
//! ```toml
//! [temperature]
//! reference = 70.0
//! plates = [150.0]
//! table = [[100.0, 2.0e7, 0.3, 1.0e-5], [200.0, 1.0e7, 0.2, 2.0e-5]]   # T, E, nu, alpha
//! ```
//!
//! Every temperature of `plates` or `gradient` must lie inside the table (a one-row table holds
//! at every temperature); errors name the key, the value and the line.
//!
//! # Accuracy
//!
//! `tests/io/thermal_vtu.rs` (`table_rows_are_read_between_as_the_listing_does`): a scene at a
//! temperature between two rows equals, by superposition, the free expansion α(T) ΔT r of the
//! interpolated α on the plate of the interpolated E and ν.
//!
//! # Cost
//!
//! Parsing and checks only.
//!
//! ```
//! let scene = boltzone::scene::Scene::parse(
//!     "model = \"single-plate\"\n[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\n\
//!      pressure = 1000.0\n[[plates]]\nthickness = 0.1\nmaterial = { E = 1e7, nu = 0.3 }\n\
//!      [joint]\nouter_radius = 1.0\n[temperature]\nreference = 70.0\nplates = [250.0]\n\
//!      table = [[100.0, 2e7, 0.3, 1e-5], [200.0, 1e7, 0.2, 2e-5]]\n",
//! );
//! assert!(scene.unwrap_err().to_string().contains("temperature.plates")); // 250 is off the table
//! ```

use super::error::SceneError;
use super::temperature_keys::{fail, pair};
use super::temperature_spec::TemperatureSpec;
use crate::fem::thermal::ThermalMaterial;
use crate::material::Material;

/// Checks `alpha` or `table` of a `[temperature]` table (`text` for the lines).
pub(super) fn check(t: &TemperatureSpec, text: &str) -> Result<(), SceneError> {
    let Some(rows) = &t.table else {
        for a in pair(text, "alpha", &t.alpha)? {
            if !a.is_finite() {
                return Err(fail(text, "alpha", a, "must be a finite number"));
            }
        }
        return Ok(());
    };
    if !t.alpha.is_empty() {
        return Err(fail(
            text,
            "alpha",
            format!("{:?}", t.alpha),
            "give alpha or table, not both (the table holds alpha)",
        ));
    }
    ThermalMaterial::table(rows.clone())
        .map_err(|e| fail(text, "table", format!("{rows:?}"), &e.to_string()))?;
    let (lo, hi) = match rows.as_slice() {
        [_] => return Ok(()),
        [first, .., last] => (first[0], last[0]),
        [] => return Ok(()),
    };
    let given = t.plates.iter().flatten().map(|v| ("plates", *v));
    let given = given.chain(
        t.gradient
            .iter()
            .flatten()
            .flatten()
            .map(|v| ("gradient", *v)),
    );
    let given = given.chain(t.faces.iter().flatten().map(|v| ("faces", *v)));
    for (key, v) in given {
        if !(v >= lo && v <= hi) {
            return Err(fail(
                text,
                key,
                v,
                &format!("outside the table's temperatures {lo}..{hi}"),
            ));
        }
    }
    Ok(())
}

/// The two plates' E(T), ν(T), α(T) in SI (`stress` the scene's stress unit in Pa): the table
/// for both, or each plate's own material `own` with its α.
pub(super) fn materials(
    t: &TemperatureSpec,
    stress: f64,
    own: [Material; 2],
) -> Result<[ThermalMaterial; 2], SceneError> {
    if let Some(rows) = &t.table {
        let si = rows.iter().map(|r| [r[0], r[1] * stress, r[2], r[3]]);
        let table = ThermalMaterial::table(si.collect())?;
        return Ok([table.clone(), table]);
    }
    let [a, b] = pair("", "alpha", &t.alpha)?;
    Ok([
        ThermalMaterial::constant(own[0], a)?,
        ThermalMaterial::constant(own[1], b)?,
    ])
}
