//! The report's tables as data: Table 1 (single- vs two-plate R_o/A), Table 2 (experiments and the
//! report's computed 2R_o), the Chapter V interface table and the numbers the text prints about
//! its figures ([`text_value`]). The CSV files live in `reference/`
//! with their provenance in the header comment; they are compiled into the library so the
//! command-line tool needs no data path.
//!
//! These values are data to compare with, never targets: no solver reads them.
//!
//! # Accuracy
//!
//! The stored values against the report's own arithmetic: `tests/compare/reference.rs`
//! (`table1_discrepancies_follow_from_the_radii`, `table2_discrepancies_follow_from_the_diameters`,
//! `chapter5_conductances_follow_from_the_areas`); the text's numbers as printed:
//! `tests/figures/markers.rs`.
//!
//! # Cost
//!
//! None (constants).
//!
//! ```
//! let t1 = boltzone::reference::table1();
//! assert_eq!(t1.len(), 12);
//! assert_eq!(t1[0].b_over_a, 3.1);
//! let t2 = boltzone::reference::table2();
//! assert_eq!(t2[4].d2, 0.257); // the unmatched pair of case 5
//! ```

use serde::Serialize;

/// Hole radius A of Table 1's plates, inches (Chapter IV.A).
pub const TABLE1_HOLE_RADIUS: f64 = 0.1;
/// Outer radius C of Table 1's single plates, inches (Chapter IV.A).
pub const TABLE1_OUTER_RADIUS: f64 = 1.54;
/// Poisson's ratio of Table 1 (Chapter IV.A).
pub const TABLE1_POISSON: f64 = 0.3;
/// Hole radius A of the test plates, inches: 0.257 in diameter (Chapter III).
pub const TABLE2_HOLE_RADIUS: f64 = 0.1285;
/// Outer radius C of the test plates, inches: 4 in diameter (Chapter III).
pub const TABLE2_OUTER_RADIUS: f64 = 2.0;

const TABLE1_CSV: &str = include_str!("../reference/table1_separation_radius.csv");
const TABLE2_CSV: &str = include_str!("../reference/table2_experiments.csv");
const CHAPTER5_CSV: &str = include_str!("../reference/chapter5_interface.csv");
const TEXT_CSV: &str = include_str!("../reference/text_values.csv");

/// One row of Table 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Table1Row {
    /// A/D (printed "A/B" by OCR).
    pub a_over_d: f64,
    /// B/A.
    pub b_over_a: f64,
    /// R_o/A of the single-plate model (the report's FE).
    pub single: f64,
    /// R_o/A of the two-plate model (the report's FE).
    pub two: f64,
    /// Printed percent discrepancy (single − two)/two·100.
    pub discrepancy_percent: f64,
}

impl Table1Row {
    /// Plate thickness D in inches (A = 0.1 in).
    pub fn d(&self) -> f64 {
        TABLE1_HOLE_RADIUS / self.a_over_d
    }

    /// Load outer radius B in inches.
    pub fn b(&self) -> f64 {
        TABLE1_HOLE_RADIUS * self.b_over_a
    }
}

/// A measured range and average of the separation diameter 2R_o, inches.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Measurement {
    /// Smallest reading.
    pub min: f64,
    /// Largest reading.
    pub max: f64,
    /// Average of the readings.
    pub average: f64,
}

/// One case of Table 2.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table2Row {
    /// Case number 1–7.
    pub case: u32,
    /// Thickness of the first plate, in.
    pub d1: f64,
    /// Thickness of the second plate, in.
    pub d2: f64,
    /// Thickness printed in the table's "D in." column.
    pub d_table: f64,
    /// Bearing-face diameter 2B, in.
    pub two_b: f64,
    /// "Rubbing test" 2R_o.
    pub rubbing: Measurement,
    /// Autoradiographic 2R_o, where done.
    pub autoradiographic: Option<Measurement>,
    /// The report's computed two-plate 2R_o, in.
    pub computed: f64,
    /// Printed |computed − rubbing|/computed·100.
    pub discrepancy_rubbing_percent: f64,
    /// Printed |computed − autoradiographic|/computed·100.
    pub discrepancy_autoradiographic_percent: Option<f64>,
    /// Footnote marker ("*", "**" or "").
    pub footnote: String,
}

/// One annular increment of the Chapter V table.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InterfaceRow {
    /// Outer radius of the increment, in.
    pub r_outer: f64,
    /// Inner radius of the increment, in.
    pub r_inner: f64,
    /// Interface stress (compressive), psi.
    pub sigma_z_psi: f64,
    /// Contact conductance, Btu/hr-°F-ft².
    pub h_c: f64,
    /// Quarter-annulus area times h_c, Btu/hr-°F.
    pub area_h_c: f64,
}

/// A number the report's text prints about its figures (`reference/text_values.csv`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TextValue {
    /// Key, e.g. `single_r_over_a`.
    pub key: String,
    /// The value as printed.
    pub value: f64,
    /// Its unit as the file names it (`r/A`, `in`, `uin`).
    pub unit: String,
    /// The radius it is printed at, in (None where none).
    pub r: Option<f64>,
}

/// The text's value `key` (None if the file has no such key).
pub fn text_value(key: &str) -> Option<TextValue> {
    rows(TEXT_CSV).find(|f| f[0] == key).map(|f| TextValue {
        key: f[0].to_string(),
        value: num(f[2]),
        unit: f[3].to_string(),
        r: opt(f[4]),
    })
}

/// Data rows of a CSV with `#` comments and one header line, split into fields.
fn rows(csv: &str) -> impl Iterator<Item = Vec<&str>> {
    csv.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .skip(1)
        .map(|l| l.split(',').map(str::trim).collect())
}

fn num(field: &str) -> f64 {
    field
        .parse()
        .unwrap_or_else(|_| panic!("reference CSV: '{field}' is not a number"))
}

fn opt(field: &str) -> Option<f64> {
    (!field.is_empty()).then(|| num(field))
}

/// Table 1, 12 rows in the printed order.
pub fn table1() -> Vec<Table1Row> {
    rows(TABLE1_CSV)
        .map(|f| Table1Row {
            a_over_d: num(f[0]),
            b_over_a: num(f[1]),
            single: num(f[2]),
            two: num(f[3]),
            discrepancy_percent: num(f[4]),
        })
        .collect()
}

/// Table 2, 7 cases.
pub fn table2() -> Vec<Table2Row> {
    rows(TABLE2_CSV)
        .map(|f| {
            let rad = match (opt(f[8]), opt(f[9]), opt(f[10])) {
                (Some(min), Some(max), Some(average)) => Some(Measurement { min, max, average }),
                _ => None,
            };
            Table2Row {
                case: f[0].parse().expect("case number"),
                d1: num(f[1]),
                d2: num(f[2]),
                d_table: num(f[3]),
                two_b: num(f[4]),
                rubbing: Measurement {
                    min: num(f[5]),
                    max: num(f[6]),
                    average: num(f[7]),
                },
                autoradiographic: rad,
                computed: num(f[11]),
                discrepancy_rubbing_percent: num(f[12]),
                discrepancy_autoradiographic_percent: opt(f[13]),
                footnote: f.get(14).unwrap_or(&"").to_string(),
            }
        })
        .collect()
}

/// The Chapter V interface table, 3 rows.
pub fn chapter5_interface() -> Vec<InterfaceRow> {
    rows(CHAPTER5_CSV)
        .map(|f| InterfaceRow {
            r_outer: num(f[0]),
            r_inner: num(f[1]),
            sigma_z_psi: num(f[2]),
            h_c: num(f[3]),
            area_h_c: num(f[4]),
        })
        .collect()
}
