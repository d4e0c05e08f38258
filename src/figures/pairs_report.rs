//! The report's values drawn on Figs. 18–27 ([`super::pairs`]): Table 2's computed and measured
//! R_o of each case, the Chapter IV.B text on the 1/4 in pair's load variants and the single
//! plate, the prescribed 50 µin under the nut, Chapter VI's gap of the 1/4 in pair, and each
//! figure's note on which of them it carries. All from `reference/` (`table2_experiments.csv`,
//! `text_values.csv`): data, not targets.
//!
//! # Accuracy
//!
//! `tests/figures/markers.rs` checks each marker against `reference/` (`pair_figures_are_table2`,
//! `load_variants_are_the_chapter4_text`, `fig22_marker_is_the_nut_displacement`,
//! `fig25_markers_are_chapter6_gaps`).
//!
//! # Cost
//!
//! A few table look-ups per figure (`boltzone figures` prints each figure's time).
//!
//! ```
//! use boltzone::figures::{pairs::pair_figure, FiguresParams};
//! let fig = pair_figure("fig20", &FiguresParams::default())?; // profiles only: no solve
//! assert!(fig.report_values.contains("1100 lb"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{DataPoint, DataSeries, FigureError, Source};
use crate::reference::{self, Table2Row, TABLE2_HOLE_RADIUS as A};

/// Table 2's values for case `r` as R_o (half of the printed diameters) on the axis.
pub(super) fn table2_points(r: &Table2Row) -> Vec<DataSeries> {
    let range =
        |m: &reference::Measurement| DataPoint::range(m.average / 2.0, m.min / 2.0, m.max / 2.0);
    let mut out = vec![
        DataSeries {
            label: format!("report, Table 2 case {}: computed R_o", r.case),
            source: Source::Report,
            points: vec![DataPoint::at(r.computed / 2.0, 0.0)],
        },
        DataSeries {
            label: "Table 2: rubbing test R_o (min–avg–max)".into(),
            source: Source::Measured,
            points: vec![range(&r.rubbing)],
        },
    ];
    if let Some(m) = &r.autoradiographic {
        out.push(DataSeries {
            label: "Table 2: autoradiographic R_o (min–avg–max)".into(),
            source: Source::Measured,
            points: vec![range(m)],
        });
    }
    out
}

/// The report's text value `key` (`reference/text_values.csv`).
pub(super) fn text(key: &str) -> Result<f64, FigureError> {
    reference::text_value(key)
        .map(|t| t.value)
        .ok_or_else(|| FigureError::Unknown(format!("reference/text_values.csv key {key}")))
}

/// The Chapter IV text on the 1/4 in pair's load variants (Figs. 18, 19, 21): two-plate r/A
/// 2.73–2.93, single plate 3.5.
pub(super) fn variant_points() -> Result<Vec<DataSeries>, FigureError> {
    let (lo, hi) = (
        text("variants_two_r_over_a_min")?,
        text("variants_two_r_over_a_max")?,
    );
    let single = text("single_r_over_a")?;
    Ok(vec![
        DataSeries {
            label: format!("report (Ch. IV): two-plate variants, r/A = {lo}–{hi}"),
            source: Source::Report,
            points: vec![DataPoint::range((lo + hi) / 2.0 * A, lo * A, hi * A)],
        },
        DataSeries {
            label: format!("report (Ch. IV): single plate, r/A = {single}"),
            source: Source::Report,
            points: vec![DataPoint::at(single * A, 0.0)],
        },
    ])
}

/// Fig. 22: the report's 50 µin under each nut (Fig. 21's loading), as a bar A..B at −50 µin.
pub(super) fn nut_points(b: f64) -> Result<Vec<DataSeries>, FigureError> {
    let w = -text("nut_displacement")?;
    Ok(vec![DataSeries {
        label: format!("report (Ch. IV): {} µin under each nut (A ≤ r ≤ B)", -w),
        source: Source::Report,
        points: vec![DataPoint {
            x: (A + b) / 2.0,
            y: w,
            x_bar: (A, b),
            y_bar: (w, w),
        }],
    }])
}

/// Fig. 25: Chapter VI's gap of the 1/4 in pair (98.6 µin at r = 2 in, 3 µin 1/32 in beyond
/// its R_o = 0.35 in).
pub(super) fn gap_points() -> Result<Vec<DataSeries>, FigureError> {
    let at = |key: &str| -> Result<DataPoint, FigureError> {
        let t = reference::text_value(key)
            .ok_or_else(|| FigureError::Unknown(format!("reference/text_values.csv key {key}")))?;
        Ok(DataPoint::at(t.r.unwrap_or(0.0), t.value))
    };
    Ok(vec![
        DataSeries {
            label: "report (Ch. VI): gap of the 1/4 in pair".into(),
            source: Source::Report,
            points: vec![at("gap_near_separation")?, at("gap_outer_radius")?],
        },
        DataSeries {
            label: "report (Ch. VI): R_o of the 1/4 in pair".into(),
            source: Source::Report,
            points: vec![DataPoint::at(text("separation_radius_quarter")?, 0.0)],
        },
    ])
}

/// What the report prints for pair figure `id` (Table 2 case `n`).
pub(super) fn report_values(id: &str, n: u32) -> String {
    let table2 = format!(
        "Table 2 case {n} (reference/table2_experiments.csv): the report's computed 2R_o and \
         the tests' 2R_o ranges, halved to R_o"
    );
    let text = "the Chapter IV.B text (reference/text_values.csv): the two-plate separation of \
                the 1/4 in pair's load variants at r/A = 2.73–2.93 and the single plate's at 3.5";
    match id {
        "fig18" => format!("{table2}; {text}."),
        "fig19" | "fig21" => format!("From {text}; the report prints no pressure value."),
        "fig22" => "The Chapter IV.B text (reference/text_values.csv): the prescribed 50 µin \
                    under each nut of Fig. 21's loading; the report prints no other deflection."
            .into(),
        "fig25" => "The report prints no gap for Fig. 25's 1/8 in pair; Chapter VI \
                    (reference/text_values.csv) prints the 1/4 in pair's: 98.6 µin at r = 2 in \
                    and 3 µin 1/32 in beyond its R_o = 0.35 in, drawn with that pair's gap."
            .into(),
        _ => format!("{table2}."),
    }
}
