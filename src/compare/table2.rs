//! The report's Table 2 recomputed: the two-plate separation diameter 2R_o of the test joints
//! (type 304 steel, A = 0.1285 in, C = 2.0 in, B = 0.211 in under 1/4-20 nuts or 0.5 in under
//! washers; plate thicknesses d1 (under the head) and d2 from the specimen list), beside the
//! report's computed 2R_o and the measured ranges and averages ("rubbing" and autoradiographic
//! tests). Our discrepancy against a test average is computed the report's way:
//! |computed − tested|/computed·100.
//!
//! Equal plates use the symmetric model (one plate on a rigid frictionless plane; exact for any
//! interface). Unequal pairs (every case with d1 ≠ d2: case 5's 0.124/0.257 in, and the
//! nominally equal pairs whose measured thicknesses differ by a few thousandths) mesh both plates
//! with the chosen [`InterfaceModel`]: welded inside the contact zone is the report's model.
//!
//! # Accuracy
//!
//! Two-plate R_o to the tolerance by its own estimate; the discrepancy function reproduces the
//! report's printed percentages from its own numbers (`tests/compare/tables.rs`,
//! `table2_end_to_end`).
//!
//! # Cost
//!
//! Seven two-plate runs in parallel.
//!
//! ```no_run
//! use boltzone::compare::table2;
//! use boltzone::contact::two_plate::InterfaceModel;
//! let rows = table2::compute(InterfaceModel::Welded, 5e-4, &|| ())?;
//! print!("{}", table2::text(&rows));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{show, CompareError};
use crate::contact::two_plate::{solve, InterfaceModel};
use crate::error::positive;
use crate::joint::{Joint, OuterRadius, Plate};
use crate::load::FaceLoad;
use crate::material::Material;
use crate::reference::{self, Table2Row, TABLE2_HOLE_RADIUS, TABLE2_OUTER_RADIUS};
use crate::route::two_plate::Question;
use crate::units::UnitSystem;
use crate::units::{as_entered, INCH};
use crate::value::Value;
use rayon::prelude::*;
use serde::Serialize;

/// One case: ours and the report's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// Our two-plate 2R_o, inches, with its error estimate.
    pub two_r_o: Value,
    /// The model that ran ("symmetric …", "welded", "frictionless").
    pub model: &'static str,
    /// |ours − rubbing average|/ours·100.
    pub discrepancy_rubbing_percent: f64,
    /// |ours − autoradiographic average|/ours·100, where tested.
    pub discrepancy_autoradiographic_percent: Option<f64>,
    /// Seconds of the two-plate solve.
    pub seconds: f64,
    /// The report's row (geometry, tests, its computed 2R_o and discrepancies).
    pub report: Table2Row,
}

/// The test joint of one case (unit pressure: R_o does not depend on the bolt force).
pub fn joint(case: &Table2Row) -> Result<Joint, CompareError> {
    let steel = Material::steel_304_psi();
    let a = TABLE2_HOLE_RADIUS;
    Ok(Joint::new(
        a,
        OuterRadius::Finite(TABLE2_OUTER_RADIUS),
        Plate::new(case.d1, steel)?,
        Plate::new(case.d2, steel)?,
        FaceLoad::uniform(a, case.two_b / 2.0, 1.0)?,
    )?)
}

/// |computed − tested|/computed·100 (the report's definition).
pub fn discrepancy(computed: f64, tested: f64) -> f64 {
    (computed - tested).abs() / computed * 100.0
}

/// Computes the seven cases in parallel with relative tolerance `tolerance` on R_o.
pub fn compute(
    interface: InterfaceModel,
    tolerance: f64,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<Row>, CompareError> {
    positive("comparison tolerance", tolerance)?;
    reference::table2()
        .into_par_iter()
        .map(|case| {
            let joint = joint(&case)?;
            let params = Question {
                interface,
                ..Question::new(&joint, tolerance)
            }
            .fem_params();
            let s = solve(&joint, &params).map_err(|source| CompareError::Two {
                geometry: format!(
                    "Table 2 case {} (d1 = {}, d2 = {})",
                    case.case, case.d1, case.d2
                ),
                source,
            })?;
            tick();
            let two = 2.0 * s.r_o;
            Ok(Row {
                two_r_o: Value {
                    value: two,
                    error: 2.0 * s.r_o_error,
                    converged: s.converged,
                },
                model: s.info.model,
                discrepancy_rubbing_percent: discrepancy(two, case.rubbing.average),
                discrepancy_autoradiographic_percent: case
                    .autoradiographic
                    .map(|m| discrepancy(two, m.average)),
                seconds: s.info.seconds,
                report: case,
            })
        })
        .collect()
}

/// The table as text, in inches (the report's units).
pub fn text(rows: &[Row]) -> String {
    text_in(rows, UnitSystem::InPsiLbf)
}

/// Decimals that show `x` to `digits` significant digits.
fn decimals(x: f64, digits: i32) -> usize {
    (digits - 1 - x.abs().log10().floor() as i32).max(0) as usize
}

/// A length given in inches, in the length unit of `units`, to `digits` significant digits
/// for a table (inches print as the report wrote them).
fn length_text(inches: f64, units: UnitSystem, digits: i32) -> String {
    if units == UnitSystem::InPsiLbf {
        return format!("{inches}");
    }
    let x = inches * (INCH / units.length());
    format!("{x:.*}", decimals(x, digits))
}

/// The table as text with every length in the length unit of `units` (percentages are
/// ratios, the same in every system).
pub fn text_in(rows: &[Row], units: UnitSystem) -> String {
    let k = INCH / units.length();
    let (l, _, _) = units.symbols();
    let len = |x: f64| length_text(x, units, 4);
    let mut s = format!(
        "Table 2 recomputed (Gould & Mikic 1970): separation diameter 2R_o [{l}]\n\
         304 steel, A = {} {l}, C = {} {l}; ours ± error estimate; report's computed value;\n\
         tests min-max (average); discrepancy |computed - tested|/computed in %, ours [report's]\n\n",
        len(TABLE2_HOLE_RADIUS),
        len(TABLE2_OUTER_RADIUS),
    );
    s += &format!(
        "{:>4} {:>11} {:>5}  {:>16} {:>7}  {:>17} {:>17}  {:>13} {:>13}  {}\n",
        "case",
        "d1/d2",
        "2B",
        "ours 2R_o",
        "report",
        "rubbing",
        "autoradiogr.",
        "disc. rub %",
        "disc. rad %",
        "model"
    );
    // the tests' ranges to 0.01 in, three digits in other units
    let range = |m: reference::Measurement| {
        let d = match units {
            UnitSystem::InPsiLbf => 2,
            _ => decimals(m.max * k, 3),
        };
        format!(
            "{:.d$}-{:.d$} ({:.d$})",
            m.min * k,
            m.max * k,
            m.average * k
        )
    };
    // ours and the report's computed 2R_o to four significant digits (0.4740 in)
    let d4 = decimals(0.5 * k, 4);
    for r in rows {
        let c = &r.report;
        let rad = c.autoradiographic.map(range).unwrap_or_else(|| "-".into());
        let drad = match (
            r.discrepancy_autoradiographic_percent,
            c.discrepancy_autoradiographic_percent,
        ) {
            (Some(o), Some(p)) => format!("{o:.1} [{p:.1}]"),
            _ => "-".into(),
        };
        s += &format!(
            "{:>4} {:>5}/{:<5} {:>5}  {:>16} {:>7}  {:>17} {:>17}  {:>13} {:>13}  {}\n",
            c.case,
            len(c.d1),
            len(c.d2),
            len(c.two_b),
            show(r.two_r_o.scaled(k), d4),
            format!("{:.*}", d4 - 1, c.computed * k),
            range(c.rubbing),
            rad,
            format!(
                "{:.1} [{:.1}]",
                r.discrepancy_rubbing_percent, c.discrepancy_rubbing_percent
            ),
            drad,
            r.model
        );
    }
    s
}

/// The table as CSV in inches (the report's units).
pub fn csv(rows: &[Row]) -> String {
    csv_in(rows, UnitSystem::InPsiLbf)
}

/// The table as CSV, every column named with its unit: lengths in the length unit of `units`,
/// discrepancies in %; the report's numbers as entered ([`as_entered`]), ours in full (shortest
/// round-trip form).
pub fn csv_in(rows: &[Row], units: UnitSystem) -> String {
    let k = INCH / units.length();
    let (l, _, _) = units.symbols();
    let mut s = format!(
        "case,d1 [{l}],d2 [{l}],two_b [{l}],two_r_o [{l}],two_r_o_error [{l}],model,\
         report_computed [{l}],rub_min [{l}],rub_max [{l}],rub_avg [{l}],rad_min [{l}],\
         rad_max [{l}],rad_avg [{l}],disc_rub_percent [%],disc_rad_percent [%],\
         report_disc_rub_percent [%],report_disc_rad_percent [%]\n",
    );
    let o = |x: Option<f64>| x.map(|v| format!("{v}")).unwrap_or_default();
    // the report's lengths (inputs and its printed results) as entered, in `units`
    let e = |v: f64| as_entered(v * k);
    let oe = |x: Option<f64>| o(x.map(e));
    for r in rows {
        let c = &r.report;
        let m = c.autoradiographic;
        s += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            c.case,
            e(c.d1),
            e(c.d2),
            e(c.two_b),
            r.two_r_o.value * k,
            r.two_r_o.error * k,
            r.model,
            e(c.computed),
            e(c.rubbing.min),
            e(c.rubbing.max),
            e(c.rubbing.average),
            oe(m.map(|m| m.min)),
            oe(m.map(|m| m.max)),
            oe(m.map(|m| m.average)),
            r.discrepancy_rubbing_percent,
            o(r.discrepancy_autoradiographic_percent),
            c.discrepancy_rubbing_percent,
            o(c.discrepancy_autoradiographic_percent),
        );
    }
    s
}
