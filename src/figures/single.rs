//! Figs. 12–17: Table 1's twelve joints (A = 0.1 in, C = 1.54 in, ν = 0.3; D = 0.1, 0.1333,
//! 0.2 in, B = 0.31, 0.22, 0.16, 0.13 in), uniform bearing pressure P = 1 psi.
//!
//! Figs. 12–14: the single plate 2D thick (Fernlund's substitution, report Fig. 3(f)), midplane
//! σ_z(r) (compression negative) from the finest level of [`crate::fem::single`]'s study, with
//! its R_o; the report's single-plate R_o of Table 1 as points. Figs. 15–17: the two-plate
//! interface pressure p(r) of [`crate::contact::two_plate`] for the same joints, with the
//! report's two-plate R_o of Table 1.
//!
//! # Accuracy
//!
//! `tests/figures/markers.rs`: `figs12_to_17_are_table1` (the report's markers against `reference/`
//! read independently); `tests/figures/gallery.rs`: `fig12_single_plate_r_o_match_the_hankel_route`
//! (the single plate's R_o
//! against the semi-analytic route) and `every_curve_separates_at_its_r_o` (each curve changes sign
//! at its R_o within node spacing and error bar).
//!
//! # Cost
//!
//! The single-plate level study (`cargo bench --bench fem`, `Q9/levels…`) and the two-plate solve
//! (`cargo bench --bench contact`) per joint; `boltzone figures` prints each figure's time; the
//! whole set is timed by `every_curve_separates_at_its_r_o` (tests/figures/gallery.rs, which runs
//! the whole set once, about 6 s).
//!
//! ```
//! use boltzone::figures::{single::table1_figure, FigureError, FiguresParams};
//! // Figs. 12–17 only: any other id is refused without computing
//! let e = table1_figure("fig18", &FiguresParams::default());
//! assert!(matches!(e, Err(FigureError::Unknown(_))));
//! ```

use super::{
    clip, short, CurveKind, DataPoint, DataSeries, FigCurve, FigureData, FigureError,
    FiguresParams, Source,
};
use crate::compare::Geometry;
use crate::contact::two_plate::{solve, TwoPlateParams};
use crate::fem::single::{midplane_of, solve_with_field, SingleParams};
use crate::reference;
use rayon::prelude::*;

/// Figs. 12–17 (`id` = `fig12` … `fig17`).
pub fn table1_figure(id: &str, params: &FiguresParams) -> Result<FigureData, FigureError> {
    let (number, two) = match id {
        "fig12" => (0, false),
        "fig13" => (1, false),
        "fig14" => (2, false),
        "fig15" => (0, true),
        "fig16" => (1, true),
        "fig17" => (2, true),
        _ => return Err(FigureError::Unknown(id.to_string())),
    };
    let a_over_d = [1.0, 0.75, 0.5][number];
    let rows: Vec<(Geometry, reference::Table1Row)> = Geometry::table1()
        .into_iter()
        .zip(reference::table1())
        .filter(|(_, r)| r.a_over_d == a_over_d)
        .collect();
    let d = rows.first().map_or(0.1, |(g, _)| g.d);
    let curves = rows
        .par_iter()
        .map(|(g, _)| {
            let (kind, xy, r_o) = if two {
                pressure_curve(id, g, params)?
            } else {
                sigma_z_curve(id, g, params)?
            };
            let what = format!("B = {} in", short(g.b));
            Ok::<_, FigureError>(FigCurve::with_r_o(
                &what,
                kind,
                xy,
                g.b,
                r_o,
                params.tolerance,
            ))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let x_max = 1.3
        * curves
            .iter()
            .filter_map(|c| c.r_o.map(|v| v.value))
            .fold(0.0, f64::max);
    let curves = curves
        .into_iter()
        .map(|mut c| {
            (c.x, c.y) = clip(&c.x, &c.y, x_max);
            c
        })
        .collect();
    let report = |r: &reference::Table1Row| {
        let a = reference::TABLE1_HOLE_RADIUS;
        DataPoint::at(a * if two { r.two } else { r.single }, 0.0)
    };
    let which = if two { "two-plate" } else { "single-plate" };
    let (title, y_label) = if two {
        (
            format!(
                "Fig. {}: interface pressure distribution in a bolted joint (D = {d:.4} in)",
                15 + number
            ),
            "p [psi] (P = 1 psi)",
        )
    } else {
        (
            format!(
                "Fig. {}: single plate analysis, midplane σz stress distribution (D = {d:.4} in)",
                12 + number
            ),
            "σz [psi] (P = 1 psi)",
        )
    };
    Ok(FigureData {
        id: id.to_string(),
        title,
        note: format!(
            "Table 1's joints with D = {d:.4} in (A = 0.1 in, C = 1.54 in, ν = 0.3), uniform \
             bearing pressure P = 1 psi on A ≤ r ≤ B; {}; triangles: the report's {which} R_o \
             (Table 1, R_o/A × A, printed to 0.1 A).",
            if two {
                "two plates D thick in frictionless contact, finite elements (boltzone::contact)"
            } else {
                "one plate 2D thick, midplane σz by finite elements (boltzone::fem::single)"
            }
        ),
        x_label: "r [in]".into(),
        y_label: y_label.into(),
        curves,
        points: vec![DataSeries {
            label: format!("report, Table 1: {which} R_o"),
            source: Source::Report,
            points: rows.iter().map(|(_, r)| report(r)).collect(),
        }],
        values: vec![],
        report_values: format!(
            "Table 1 (reference/table1_separation_radius.csv): the {which} R_o/A of the rows \
             A/D = {a_over_d}, times A = 0.1 in."
        ),
        seconds: 0.0,
    })
}

/// A curve's kind, points and (R_o, error).
type Computed = (CurveKind, (Vec<f64>, Vec<f64>), (f64, f64));

/// The single plate's midplane σ_z of joint `g` (P = 1 psi) with its R_o.
fn sigma_z_curve(
    figure: &str,
    g: &Geometry,
    params: &FiguresParams,
) -> Result<Computed, FigureError> {
    let plate = g.single_plate(g.outer_radius())?;
    let sp = SingleParams {
        tolerance: params.tolerance,
        levels: crate::fem::single::MAX_LEVELS,
        ..SingleParams::default()
    };
    let fem = |source| FigureError::Fem {
        figure: figure.to_string(),
        source,
    };
    let (s, h) = solve_with_field(&plate, &sp).map_err(fem)?;
    let m = midplane_of(&plate, &h).map_err(fem)?;
    Ok((CurveKind::SigmaZ, (m.r, m.sigma_z), (s.r_o, s.r_o_error)))
}

/// The two-plate interface pressure of joint `g` (P = 1 psi) with its R_o.
fn pressure_curve(
    figure: &str,
    g: &Geometry,
    params: &FiguresParams,
) -> Result<Computed, FigureError> {
    let tp = TwoPlateParams {
        tolerance: params.tolerance,
        ..Default::default()
    };
    let s = solve(&g.joint()?, &tp).map_err(|source| FigureError::Contact {
        figure: figure.to_string(),
        source,
    })?;
    Ok((
        CurveKind::Pressure,
        (s.radius, s.pressure),
        (s.r_o, s.r_o_error),
    ))
}
