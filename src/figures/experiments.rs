//! Fig. 28: our two-plate 2R_o of Table 2's seven joints (welded interface, the specimens'
//! thicknesses, as `boltzone table2`) against the report's computed 2R_o and the rubbing and
//! autoradiographic tests' ranges (average, bars min–max), with the line measured = computed.
//!
//! # Accuracy
//!
//! The seven R_o are those of `boltzone table2`: `tests/compare/tables.rs` (`table2_end_to_end`);
//! the drawing is checked by `tests/figures/gallery.rs` (`files_and_gallery_are_complete`).
//!
//! # Cost
//!
//! Seven two-plate solves (`cargo bench --bench contact`; example 04 times Table 2); `boltzone
//! figures` prints each figure's time; the whole set is timed by the ignored test
//! `every_curve_separates_at_its_r_o` (tests/figures/gallery.rs, which runs the whole set once,
//! about 6 s).
//!
//! ```no_run
//! use boltzone::figures::{experiments::fig28, FiguresParams};
//! let fig = fig28(&FiguresParams::default())?; // seven two-plate solves
//! assert_eq!(fig.values.len(), 7);
//! # Ok::<(), boltzone::figures::FigureError>(())
//! ```

use super::pairs::{case, run};
use super::{
    value, CurveKind, DataPoint, DataSeries, FigCurve, FigureData, FigureError, FiguresParams,
    Source,
};
use crate::reference;
use rayon::prelude::*;

/// Fig. 28: our two-plate 2R_o of Table 2's seven cases against the measured ranges.
pub fn fig28(params: &FiguresParams) -> Result<FigureData, FigureError> {
    let rows = reference::table2();
    let ours = rows
        .par_iter()
        .map(|r| run("fig28", &case(r.case), params.tolerance).map(|(s, _)| s))
        .collect::<Result<Vec<_>, _>>()?;
    let two: Vec<f64> = ours.iter().map(|s| 2.0 * s.r_o).collect();
    let bar = |x: f64, m: &reference::Measurement| DataPoint {
        x,
        y: m.average,
        x_bar: (x, x),
        y_bar: (m.min, m.max),
    };
    let lo = 0.3;
    let hi = 1.3;
    let computed = ours
        .iter()
        .map(|s| DataPoint {
            x: 2.0 * s.r_o,
            y: 2.0 * s.r_o,
            x_bar: (2.0 * (s.r_o - s.r_o_error), 2.0 * (s.r_o + s.r_o_error)),
            y_bar: (2.0 * s.r_o, 2.0 * s.r_o),
        })
        .collect();
    let line = FigCurve {
        label: "measured = computed".into(),
        kind: CurveKind::Other,
        x: vec![lo, hi],
        y: vec![lo, hi],
        b: 0.0,
        r_o: None,
    };
    Ok(FigureData {
        id: "fig28".into(),
        title: "Fig. 28: comparison between tested and computed separation radii".into(),
        note: "Table 2's seven joints: x = our two-plate 2R_o (welded interface, as `boltzone \
               table2`); the rubbing and autoradiographic tests' 2R_o (average, bars min–max) and \
               the report's computed 2R_o against it."
            .into(),
        x_label: "computed 2R_o (this program) [in]".into(),
        y_label: "2R_o [in]".into(),
        curves: vec![line],
        points: vec![
            DataSeries {
                label: "this program (bars: error estimate)".into(),
                source: Source::Computed,
                points: computed,
            },
            DataSeries {
                label: "report: computed 2R_o (Table 2)".into(),
                source: Source::Report,
                points: rows
                    .iter()
                    .zip(&two)
                    .map(|(r, x)| DataPoint::at(*x, r.computed))
                    .collect(),
            },
            DataSeries {
                label: "Table 2: rubbing tests".into(),
                source: Source::Measured,
                points: rows
                    .iter()
                    .zip(&two)
                    .map(|(r, x)| bar(*x, &r.rubbing))
                    .collect(),
            },
            DataSeries {
                label: "Table 2: autoradiographic tests".into(),
                source: Source::Measured,
                points: rows
                    .iter()
                    .zip(&two)
                    .filter_map(|(r, x)| Some(bar(*x, r.autoradiographic.as_ref()?)))
                    .collect(),
            },
        ],
        values: ours
            .iter()
            .map(|s| value(2.0 * s.r_o, 2.0 * s.r_o_error, params.tolerance))
            .collect(),
        report_values: "Table 2 (reference/table2_experiments.csv): the report's computed 2R_o \
                        and the rubbing and autoradiographic tests' 2R_o (average, min–max)."
            .into(),
        seconds: 0.0,
    })
}
