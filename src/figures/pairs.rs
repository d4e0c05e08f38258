//! Figs. 18–27: Table 2's steel pairs (304 steel, A = 0.1285 in, C = 2.0 in, B = 0.211 in
//! under the nuts, the specimens' thicknesses of Chapter III, the report's welded interface as
//! `boltzone table2`), under a bolt force of 1100 lb (Table 2's provenance; R_o does not depend
//! on it).
//!
//! | figure | case | curves |
//! |---|---|---|
//! | 18 | 4 (1/4 in) | interface pressure p(r); the single plate's midplane compression −σ_z |
//! | 19 | 4 | p(r) under triangular bearing pressure, peak at A and at B (same force) |
//! | 20 | 4 | the three bearing-pressure profiles (the report's load variants) |
//! | 21 | 4 | p(r) under a uniform displacement of 50 µin of each face under the nut |
//! | 22 | 4 | the loaded face's axial displacement w(r) under the nut, each loading |
//! | 23, 24, 26 | 3, 2, 1 | p(r); Fig. 24 with the outer edge free and fixed (Fig. 20(c)) |
//! | 25 | 2 (and 4) | the gap g(r) between the plates, outer edge free and fixed; the 1/4 in pair's (Ch. VI's values) |
//! | 27 | 5 (1/8 on 1/4 in) | p(r) |
//!
//! Points (each figure's [`FigureData::report_values`] says which): the report's computed R_o
//! (Table 2's 2R_o / 2), the rubbing and autoradiographic ranges (2R_o / 2, min…max around the
//! average); the Chapter IV text's r/A = 2.73–2.93 for the load variants and 3.5 for the single
//! plate (Figs. 18, 19, 21); the prescribed 50 µin under the nut (Fig. 22); Chapter VI's gap of
//! the 1/4 in pair (Fig. 25: the report prints none for the 1/8 in pair), all from
//! `reference/text_values.csv`.
//!
//! # Accuracy
//!
//! `tests/figures/markers.rs`: `pair_figures_are_table2`, `load_variants_are_the_chapter4_text`,
//! `fig22_marker_is_the_nut_displacement`, `fig25_markers_are_chapter6_gaps` (the report's values
//! against
//! `reference/`), `fig20_profiles_carry_the_bolt_force` (each bearing-pressure profile integrates
//! to 1100 lb) and `every_curve_separates_at_its_r_o`.
//!
//! # Cost
//!
//! One two-plate solve per curve (`cargo bench --bench contact`); `boltzone figures` prints each
//! figure's time; the whole set is timed by `every_curve_separates_at_its_r_o`
//! (tests/figures/gallery.rs, which runs the whole set once, about 6 s).
//!
//! ```
//! use boltzone::figures::pairs::{bearing_pressure, FORCE};
//! // the 1100 lb bolt force spread over the nut's annulus A = 0.1285 in ≤ r ≤ B = 0.211 in
//! let p = bearing_pressure(0.211);
//! let area = std::f64::consts::PI * (0.211f64.powi(2) - 0.1285f64.powi(2));
//! assert!((p * area - FORCE).abs() < 1e-9 * FORCE);
//! ```

use super::pairs_report::{gap_points, nut_points, report_values, table2_points, variant_points};
use super::{clip, stagger, CurveKind, FigCurve, FigureData, FigureError, FiguresParams};
use crate::compare::table2::joint as table2_joint;
use crate::contact::two_plate::{
    solve, solve_field, EdgeSupport, InterfaceModel, Loading, TwoPlateParams, TwoPlateSolution,
};
use crate::fem::single::{midplane_of, solve_with_field, SingleParams};
use crate::joint::{Joint, SinglePlate};
use crate::load::{FaceLoad, Peak};
use crate::reference::{self, Table2Row, TABLE2_HOLE_RADIUS as A};
use rayon::prelude::*;
use std::f64::consts::PI;

/// Bolt force of the tests (lb).
pub const FORCE: f64 = 1100.0;
/// The nut displacement of Fig. 21 (in): 50 µin.
pub const NUT_DISPLACEMENT: f64 = 50e-6;

/// One computed case of a figure.
#[derive(Clone, Copy)]
pub(super) struct Case {
    /// Table 2 case number.
    case: u32,
    /// Bearing-pressure profile: None uniform, Some(peak) triangular.
    peak: Option<Peak>,
    /// Loading by the nut's displacement instead of pressure.
    nut: bool,
    /// Outer edge fixed.
    fixed: bool,
}

pub(super) const fn case(case: u32) -> Case {
    Case {
        case,
        peak: None,
        nut: false,
        fixed: false,
    }
}

impl Case {
    fn label(&self) -> String {
        let mut s = match self.peak {
            None if self.nut => "50 µin under each nut".to_string(),
            None => "uniform pressure".to_string(),
            Some(Peak::AtA) => "triangular, peak at A".to_string(),
            Some(Peak::AtB) => "triangular, peak at B".to_string(),
        };
        if self.fixed {
            s.push_str(", outer edge fixed");
        }
        s
    }
}

fn row(n: u32) -> Result<Table2Row, FigureError> {
    reference::table2()
        .into_iter()
        .find(|r| r.case == n)
        .ok_or_else(|| FigureError::Unknown(format!("Table 2 case {n}")))
}

/// The mean bearing pressure of the bolt force on A ≤ r ≤ B (psi).
pub fn bearing_pressure(b: f64) -> f64 {
    FORCE / (PI * (b * b - A * A))
}

/// The bearing-pressure profile of case `c` with bearing radius `b`.
fn load(c: &Case, b: f64) -> Result<FaceLoad, FigureError> {
    let p = bearing_pressure(b);
    Ok(match c.peak {
        None => FaceLoad::uniform(A, b, p)?,
        Some(peak) => FaceLoad::triangular(A, b, p, peak)?,
    })
}

fn setup(c: &Case, tolerance: f64) -> Result<(Joint, TwoPlateParams, f64), FigureError> {
    let r = row(c.case)?;
    let b = r.two_b / 2.0;
    let joint = table2_joint(&r)
        .map_err(|e| FigureError::Unknown(e.to_string()))?
        .with_load(load(c, b)?)?;
    let params = TwoPlateParams {
        tolerance,
        interface: InterfaceModel::Welded,
        loading: if c.nut {
            Loading::NutDisplacement(NUT_DISPLACEMENT)
        } else {
            Loading::Pressure
        },
        edge: if c.fixed {
            EdgeSupport::Fixed
        } else {
            EdgeSupport::Free
        },
        ..Default::default()
    };
    Ok((joint, params, b))
}

fn contact_error(figure: &str) -> impl Fn(crate::contact::ContactError) -> FigureError + '_ {
    move |source| FigureError::Contact {
        figure: figure.to_string(),
        source,
    }
}

/// Solves case `c`: the solution and the bearing radius B.
pub(super) fn run(
    figure: &str,
    c: &Case,
    tolerance: f64,
) -> Result<(TwoPlateSolution, f64), FigureError> {
    let (joint, params, b) = setup(c, tolerance)?;
    Ok((solve(&joint, &params).map_err(contact_error(figure))?, b))
}

/// The pressure curve of case `c`.
fn pressure(figure: &str, c: &Case, tolerance: f64) -> Result<FigCurve, FigureError> {
    let (s, b) = run(figure, c, tolerance)?;
    let kind = CurveKind::Pressure;
    let r_o = (s.r_o, s.r_o_error);
    Ok(FigCurve::with_r_o(
        &c.label(),
        kind,
        (s.radius, s.pressure),
        b,
        r_o,
        tolerance,
    ))
}

/// The gap curve of case `c` (µin).
fn gap(figure: &str, c: &Case, tolerance: f64) -> Result<FigCurve, FigureError> {
    let (s, b) = run(figure, c, tolerance)?;
    let g = s.gap.iter().map(|g| 1e6 * g).collect();
    let r_o = (s.r_o, s.r_o_error);
    Ok(FigCurve::with_r_o(
        &c.label(),
        CurveKind::Gap,
        (s.radius, g),
        b,
        r_o,
        tolerance,
    ))
}

/// The loaded face's w(r) (µin) of case `c` out to 2B.
fn deflection(figure: &str, c: &Case, tolerance: f64) -> Result<FigCurve, FigureError> {
    let (joint, params, b) = setup(c, tolerance)?;
    let (s, field) = solve_field(&joint, &params).map_err(contact_error(figure))?;
    let mesh = &field.model.mesh;
    let mut face: Vec<(f64, f64)> = mesh
        .top(field.model.upper)
        .iter()
        .map(|&n| (mesh.nodes()[n][0], 1e6 * field.u[n][1]))
        .filter(|(r, _)| *r <= 2.0 * b)
        .collect();
    face.sort_by(|p, q| p.0.total_cmp(&q.0));
    let (x, y) = face.into_iter().unzip();
    Ok(FigCurve {
        label: format!(
            "{}: mean under the nut {:.1} µin",
            c.label(),
            1e6 * s.nut_deflection
        ),
        kind: CurveKind::Other,
        b,
        r_o: None,
        x,
        y,
    })
}

/// The single plate 2D thick of case `c`: midplane compression −σ_z (psi).
fn single_compression(figure: &str, c: &Case, tolerance: f64) -> Result<FigCurve, FigureError> {
    let r = row(c.case)?;
    let b = r.two_b / 2.0;
    let plate = SinglePlate::new(
        A,
        crate::joint::OuterRadius::Finite(reference::TABLE2_OUTER_RADIUS),
        r.d_table,
        crate::material::Material::steel_304_psi(),
        load(c, b)?,
    )?;
    let fem = |source| FigureError::Fem {
        figure: figure.to_string(),
        source,
    };
    let sp = SingleParams {
        tolerance,
        levels: crate::fem::single::MAX_LEVELS,
        ..SingleParams::default()
    };
    let (s, h) = solve_with_field(&plate, &sp).map_err(fem)?;
    let m = midplane_of(&plate, &h).map_err(fem)?;
    let compression = m.sigma_z.iter().map(|s| -s).collect();
    Ok(FigCurve::with_r_o(
        "single plate 2D thick, −σz",
        CurveKind::Pressure,
        (m.r, compression),
        b,
        (s.r_o, s.r_o_error),
        tolerance,
    ))
}

/// Figs. 18–27 (`id` = `fig18` … `fig27`).
pub fn pair_figure(id: &str, params: &FiguresParams) -> Result<FigureData, FigureError> {
    let tol = params.tolerance;
    let peak = |p| Case {
        peak: Some(p),
        ..case(4)
    };
    let fixed = |n| Case {
        fixed: true,
        ..case(n)
    };
    let nut = Case {
        nut: true,
        ..case(4)
    };
    type Job = (Case, fn(&str, &Case, f64) -> Result<FigCurve, FigureError>);
    let (title, n, jobs, p_label): (&str, u32, Vec<Job>, &str) = match id {
        "fig18" => (
            "Fig. 18: finite element analysis results for 1/4 inch plate pair",
            4,
            vec![(case(4), pressure), (case(4), single_compression)],
            "p [psi]",
        ),
        "fig19" => (
            "Fig. 19: pressure in joint, triangular loading",
            4,
            vec![(peak(Peak::AtA), pressure), (peak(Peak::AtB), pressure)],
            "p [psi]",
        ),
        "fig20" => return Ok(fig20()),
        "fig21" => (
            "Fig. 21: pressure in joint, uniform displacement under nut",
            4,
            vec![(nut, pressure)],
            "p [psi]",
        ),
        "fig22" => (
            "Fig. 22: deflection of plate under nut",
            4,
            vec![
                (case(4), deflection),
                (peak(Peak::AtA), deflection),
                (peak(Peak::AtB), deflection),
                (nut, deflection),
            ],
            "w [µin] (loaded face, toward the interface < 0)",
        ),
        "fig23" => (
            "Fig. 23: finite element analysis results for 3/16 inch plate pair",
            3,
            vec![(case(3), pressure)],
            "p [psi]",
        ),
        "fig24" => (
            "Fig. 24: finite element analysis results for 1/8 inch plate pair",
            2,
            vec![(case(2), pressure), (fixed(2), pressure)],
            "p [psi]",
        ),
        "fig25" => (
            "Fig. 25: gap deformation for free and fixed edges, 1/8 inch plate pair",
            2,
            vec![(case(2), gap), (fixed(2), gap), (case(4), gap)],
            "g [µin] (gap between the plates)",
        ),
        "fig26" => (
            "Fig. 26: finite element analysis result for 1/16 inch plate pair",
            1,
            vec![(case(1), pressure)],
            "p [psi]",
        ),
        "fig27" => (
            "Fig. 27: finite element analysis results for 1/8 inch plate mated with 1/4 inch plate",
            5,
            vec![(case(5), pressure)],
            "p [psi]",
        ),
        _ => return Err(FigureError::Unknown(id.to_string())),
    };
    let r = row(n)?;
    let curves = jobs
        .par_iter()
        .map(|(c, f)| f(id, c, tol))
        .collect::<Result<Vec<_>, _>>()?;
    let mut curves = curves;
    if let (Some(c), "fig25") = (curves.get_mut(2), id) {
        c.label = format!("1/4 in pair (case 4): {}", c.label);
    }
    let reach = curves
        .iter()
        .filter_map(|c| c.r_o.map(|v| v.value))
        .fold(r.computed / 2.0, f64::max);
    let x_max = match id {
        "fig22" => 2.0 * r.two_b / 2.0,
        "fig25" => reference::TABLE2_OUTER_RADIUS,
        _ => 1.4 * reach,
    };
    let curves: Vec<FigCurve> = curves
        .into_iter()
        .map(|mut c| {
            (c.x, c.y) = clip(&c.x, &c.y, x_max);
            c
        })
        .collect();
    let note = if id == "fig22" {
        " The curves are piecewise linear through the finite-element nodes: within about 1.2 B \
         the kink at the nut's edge is drawn to a few per cent of the curve's scale only \
         (tests/figures/deflection.rs)."
    } else {
        ""
    };
    let mut points = match id {
        "fig18" => [table2_points(&r), variant_points()?].concat(),
        "fig19" | "fig21" => variant_points()?,
        "fig22" => nut_points(r.two_b / 2.0)?,
        "fig25" => gap_points()?,
        _ => table2_points(&r),
    };
    let scale = curves
        .iter()
        .flat_map(|c: &FigCurve| c.y.iter())
        .fold(0.0, |m: f64, y| m.max(y.abs()));
    if id != "fig22" {
        stagger(&mut points, scale);
    }
    Ok(FigureData {
        id: id.to_string(),
        title: title.to_string(),
        note: format!(
            "Table 2 case {n}: plates {} and {} in thick (304 steel, E = 28e6 psi, ν = 0.3), \
             A = {A} in, B = {} in, C = 2 in, bolt force {FORCE} lb; two plates by finite \
             elements with the report's welded interface (as `boltzone table2`).{note}",
            r.d1,
            r.d2,
            r.two_b / 2.0
        ),
        x_label: "r [in]".into(),
        y_label: p_label.into(),
        curves,
        points,
        values: vec![],
        report_values: report_values(id, n),
        seconds: 0.0,
    })
}

/// Fig. 20: the bearing-pressure profiles of the load variants (equal force).
fn fig20() -> FigureData {
    let b = 0.211;
    let curves = [
        case(4),
        Case {
            peak: Some(Peak::AtA),
            ..case(4)
        },
        Case {
            peak: Some(Peak::AtB),
            ..case(4)
        },
    ]
    .iter()
    .filter_map(|c| {
        let l = load(c, b).ok()?;
        let x: Vec<f64> = (0..=200).map(|i| A + (b - A) * i as f64 / 200.0).collect();
        let y = x.iter().map(|r| l.pressure_at(*r)).collect();
        Some(FigCurve {
            label: format!("{}: total force {:.1} lb", c.label(), l.total_force()),
            kind: CurveKind::Other,
            x,
            y,
            b,
            r_o: None,
        })
    })
    .collect();
    FigureData {
        id: "fig20".into(),
        title: "Fig. 20: variations of loading and boundary conditions".into(),
        note: format!(
            "The bearing pressure under the nut of Figs. 18–22 (A = {A} in, B = {b} in, bolt force \
             {FORCE} lb): uniform (a, Fig. 18), triangular with the peak at A (Fig. 20(a)) or at B \
             (Fig. 20(b)); (c), the outer edge fixed, is Fig. 24's second case."
        ),
        x_label: "r [in]".into(),
        y_label: "bearing pressure [psi]".into(),
        curves,
        points: vec![],
        values: vec![],
        report_values: format!(
            "{}: the report draws the load variants (Fig. 20) without numbers; the profiles \
             carry Chapter III's bolt force of about 1100 lb.",
            super::NO_REPORT_VALUES
        ),
        seconds: 0.0,
    }
}
