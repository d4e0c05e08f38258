//! The report's Table 1 recomputed: R_o/A of the single-plate substitution and of the two-plate
//! model for its twelve geometries (A = 0.1 in, C = 1.54 in, ν = 0.3, D = A/(A/D),
//! B = A·(B/A)), the discrepancy (single − two)/two·100, the contact-area discrepancy and the
//! rules of thumb — every number computed by [`super::compare`]; the report's R_o/A and
//! discrepancy stand beside ours, read from [`crate::reference::table1`].
//!
//! # Accuracy
//!
//! Every R_o to the tolerance asked by its own estimate; the table end to end, the map at Table 1's
//! points equal to the table (`tests/compare/tables.rs`).
//!
//! # Cost
//!
//! `cargo bench --bench contact` (`table1_all_24_values_rayon`).
//!
//! ```no_run
//! use boltzone::compare::{table1, CompareParams};
//! let rows = table1::compute(&CompareParams::default(), &|| ())?;
//! print!("{}", table1::text(&rows));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{compare_all, show, CompareError, CompareParams, Comparison, Geometry};
use crate::reference::{self, Table1Row};
use crate::units::UnitSystem;
use crate::units::{as_entered, INCH};
use serde::Serialize;

/// One row: ours and the report's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// Our comparison.
    pub ours: Comparison,
    /// The report's printed row.
    pub report: Table1Row,
}

/// Computes all twelve rows in parallel (`tick` once per finished row).
pub fn compute(params: &CompareParams, tick: &(dyn Fn() + Sync)) -> Result<Vec<Row>, CompareError> {
    let geometries = Geometry::table1();
    compare_all(&geometries, params, tick)
        .into_iter()
        .zip(reference::table1())
        .map(|(ours, report)| {
            Ok(Row {
                ours: ours?,
                report,
            })
        })
        .collect()
}

/// The columns [`csv`] shares with the design map ([`super::map::DesignMap::csv`]): name and
/// unit (`1`: a ratio; the radii are R/A, the errors are R_o's error over A), each printed
/// `name [unit]`.
pub const COLUMNS: [(&str, &str); 20] = [
    ("a_over_d", "1"),
    ("b_over_a", "1"),
    ("single_r_o_over_a", "1"),
    ("single_error", "1"),
    ("single_hankel_r_o_over_a", "1"),
    ("single_hankel_error", "1"),
    ("two_r_o_over_a", "1"),
    ("two_error", "1"),
    ("discrepancy_percent", "%"),
    ("discrepancy_error", "%"),
    ("area_discrepancy_percent", "%"),
    ("area_discrepancy_error", "%"),
    ("roetscher_r_over_a", "1"),
    ("roetscher_error_percent", "%"),
    ("vdi_r_over_a", "1"),
    ("vdi_half_angle_deg", "deg"),
    ("vdi_error_percent", "%"),
    ("cone_r_over_a", "1"),
    ("cone_half_angle_deg", "deg"),
    ("cone_error_percent", "%"),
];

/// The report's columns of [`csv`] after [`COLUMNS`]: its single- and two-plate R_o/A and
/// its discrepancy.
const REPORT_COLUMNS: [(&str, &str); 3] = [
    ("report_single", "1"),
    ("report_two", "1"),
    ("report_discrepancy_percent", "%"),
];

/// `columns` as a CSV header (no newline): `name [unit]`, comma-separated.
pub fn header(columns: &[(&str, &str)]) -> String {
    columns
        .iter()
        .map(|(name, unit)| format!("{name} [{unit}]"))
        .collect::<Vec<_>>()
        .join(",")
}

/// The comparison's numbers as one CSV line (no newline) in the column order of [`COLUMNS`]:
/// the inputs A/D and B/A as entered ([`as_entered`]), every computed number in full (shortest
/// round-trip form), an empty field where a route did not run.
pub fn csv_fields(c: &Comparison) -> String {
    let a = c.geometry.a;
    let (s, t) = (c.over_a(c.single), c.over_a(c.two));
    let h = c.single_hankel.map(|v| c.over_a(v));
    let mut f = vec![
        as_entered(c.geometry.a_over_d()),
        as_entered(c.geometry.b_over_a()),
        s.value,
        s.error,
        h.map_or(f64::NAN, |v| v.value),
        h.map_or(f64::NAN, |v| v.error),
        t.value,
        t.error,
        c.discrepancy_percent.value,
        c.discrepancy_percent.error,
        c.area_discrepancy_percent.value,
        c.area_discrepancy_percent.error,
    ];
    for (k, r) in c.rules.iter().enumerate() {
        // an empty field where the rule does not apply (VDI 2230 without a rim)
        f.push(r.map_or(f64::NAN, |r| r.radius / a));
        if k > 0 {
            f.push(r.map_or(f64::NAN, |r| r.half_angle_degrees));
        }
        f.push(r.map_or(f64::NAN, |r| r.error_percent.value));
    }
    f.iter()
        .map(|x| {
            if x.is_nan() {
                String::new()
            } else {
                format!("{x}")
            }
        })
        .collect::<Vec<_>>()
        .join(",")
}

/// The table as CSV (header + 12 lines), lengths in inches.
pub fn csv(rows: &[Row]) -> String {
    csv_in(rows, UnitSystem::InPsiLbf)
}

/// The table as CSV: the columns of [`COLUMNS`] (ratios and percentages, the same in every
/// unit system) and the report's, then the geometry (as entered) and both R_o in the length
/// unit of `units`; every column named with its unit (`a_over_d [1]`, `a [mm]`, …).
pub fn csv_in(rows: &[Row], units: UnitSystem) -> String {
    let k = INCH / units.length();
    let l = units.symbols().0;
    let mut out = format!(
        "{},{},a [{l}],b [{l}],d [{l}],c [{l}],single_r_o [{l}],single_r_o_error [{l}],\
         two_r_o [{l}],two_r_o_error [{l}]\n",
        header(&COLUMNS),
        header(&REPORT_COLUMNS)
    );
    for r in rows {
        let c = &r.ours;
        let g = &c.geometry;
        let lengths = [
            g.a,
            g.b,
            g.d,
            g.c,
            c.single.value,
            c.single.error,
            c.two.value,
            c.two.error,
        ];
        let entered = |(i, x): (usize, &f64)| if i < 4 { as_entered(x * k) } else { x * k };
        let lengths: Vec<String> = lengths
            .iter()
            .enumerate()
            .map(|ix| format!("{}", entered(ix)))
            .collect();
        out += &format!(
            "{},{},{},{},{}\n",
            csv_fields(c),
            r.report.single,
            r.report.two,
            r.report.discrepancy_percent,
            lengths.join(",")
        );
    }
    out
}

/// The table as text in inches: ours ± error beside the report's, then the rules of thumb.
pub fn text(rows: &[Row]) -> String {
    text_in(rows, UnitSystem::InPsiLbf)
}

/// [`text`] with A and C in the length unit of `units` (every other number is a ratio or a
/// percentage, the same in every system).
pub fn text_in(rows: &[Row], units: UnitSystem) -> String {
    let (k, l) = (INCH / units.length(), units.symbols().0);
    let a = format!("{} {l}", reference::TABLE1_HOLE_RADIUS * k);
    let c = format!("{} {l}", reference::TABLE1_OUTER_RADIUS * k);
    let mut s = format!(
        "Table 1 recomputed (Gould & Mikic 1970): R_o/A, single-plate substitution vs two-plate model\n\
         A = {a}, C = {c}, nu = 0.3; single plate 2D thick (FE, finite C); two plates D thick each\n\
         (one on a frictionless rigid plane); ours ± error estimate [report's value];\n\
         R_o/A, A/D, B/A are ratios [-], discrepancies in %\n\n",
    );
    s += &format!(
        "{:>5} {:>5}  {:>24} {:>6}  {:>24} {:>6}  {:>19} {:>6}  {:>17}  {:>24}\n",
        "A/D",
        "B/A",
        "single R_o/A",
        "[rep.]",
        "two R_o/A",
        "[rep.]",
        "disc. %",
        "[rep.]",
        "area disc. %",
        "Hankel single (infinite C)"
    );
    for r in rows {
        let c = &r.ours;
        let (si, tw) = (c.over_a(c.single), c.over_a(c.two));
        let h = c
            .single_hankel
            .map(|v| show(c.over_a(v), 4))
            .unwrap_or_else(|| "-".into());
        s += &format!(
            "{:>5} {:>5}  {:>24} {:>6}  {:>24} {:>6}  {:>19} {:>6}  {:>17}  {:>24}\n",
            r.report.a_over_d,
            r.report.b_over_a,
            show(si, 4),
            format!("[{}]", r.report.single),
            show(tw, 4),
            format!("[{}]", r.report.two),
            show(c.discrepancy_percent, 2),
            format!("[{}]", r.report.discrepancy_percent),
            show(c.area_discrepancy_percent, 2),
            h
        );
    }
    s += "\nRules of thumb: R/A, and error against the two-plate R_o in % (cone half-angle)\n";
    s += &format!(
        "{:>5} {:>5}  {:>18}  {:>24}  {:>18}\n",
        "A/D", "B/A", "45° (Rötscher)", "VDI 2230 (D'_A = 2C)", "cone"
    );
    for r in rows {
        let c = &r.ours;
        let a = c.geometry.a;
        // Table 1's plates have their rim, so every rule applies
        let [Some(q), Some(v), Some(k)] = &c.rules else {
            continue;
        };
        s += &format!(
            "{:>5} {:>5}  {:>7.3} {:>+8.1}%  {:>7.3} {:>+8.1}% ({:>4.1}°)  {:>7.3} {:>+6.1}% ({:.0}°)\n",
            r.report.a_over_d,
            r.report.b_over_a,
            q.radius / a,
            q.error_percent.value,
            v.radius / a,
            v.error_percent.value,
            v.half_angle_degrees,
            k.radius / a,
            k.error_percent.value,
            k.half_angle_degrees
        );
    }
    s
}
