//! The classic single-plate curves: the no-hole slab 2D thick pressed on both faces by a uniform
//! pressure P over a disc r ≤ B (Sneddon 1946; the shape in Greenwood 1964 and Lardner 1965),
//! midplane σ_z(r, 0)/P (compression negative) against r/D for B/D = 0.5, 1, 2, 4, each with its
//! first upward zero R_o (Fernlund's separation radius).
//!
//! Method: [`crate::hankel::Slab`] (Hankel transforms), the curve by its Chebyshev interpolant
//! [`crate::hankel::MidplaneCurve`] to 1e-9 P, R_o by [`crate::hankel::Slab::separation_radius`]
//! at the figures' tolerance.
//!
//! # Accuracy
//!
//! The slab and its R_o: `tests/hankel/slab.rs`
//! (`fast_midplane_rule_and_curve_match_direct_quadrature`,
//! `wide_uniform_load_compresses_the_midplane_by_p`); the drawn curves: `tests/figures/gallery.rs`
//! (`every_curve_separates_at_its_r_o`).
//!
//! # Cost
//!
//! `cargo bench --bench hankel` (`separation_radius 1e-10`, `midplane curve 1000 radii 1e-10`);
//! `boltzone figures` prints each figure's time; the whole set is timed by the ignored test
//! `every_curve_separates_at_its_r_o` (tests/figures/gallery.rs, which runs the whole set once,
//! about 6 s).
//!
//! ```
//! use boltzone::figures::{slab::slab_figure, FiguresParams};
//! let fig = slab_figure(&FiguresParams::default())?;
//! // the wider the load, the farther out the midplane turns tensile
//! let r_o: Vec<f64> = fig.curves.iter().filter_map(|c| c.r_o.map(|v| v.value)).collect();
//! assert!(r_o.windows(2).all(|w| w[0] < w[1]));
//! # Ok::<(), boltzone::figures::FigureError>(())
//! ```

use super::{
    CurveKind, DataPoint, DataSeries, FigCurve, FigureData, FigureError, FiguresParams, Source,
};
use crate::hankel::{MidplaneCurve, SeparationParams, Slab};
use crate::load::FaceLoad;
use crate::material::Material;

/// The loads' radii B/D of the figure.
pub const B_OVER_D: [f64; 4] = [0.5, 1.0, 2.0, 4.0];

/// Samples per curve.
const SAMPLES: usize = 400;

/// The classic slab figure (`id` = `slab`).
pub fn slab_figure(params: &FiguresParams) -> Result<FigureData, FigureError> {
    let d = 1.0;
    let slab_error = |source| FigureError::Slab {
        figure: "slab".into(),
        source,
    };
    let mut curves = Vec::new();
    let mut zeros = Vec::new();
    for b in B_OVER_D {
        let slab = Slab::new(d, Material::unit(0.3)?, FaceLoad::uniform(0.0, b, 1.0)?)?;
        let search = SeparationParams {
            rel_tol: params.tolerance,
            ..Default::default()
        };
        let sep = slab.separation_radius(&search).map_err(slab_error)?;
        let r_end = b + 6.0 * d;
        let curve = MidplaneCurve::new(&slab, 0.0, r_end, 1e-9)?;
        let x: Vec<f64> = (0..=SAMPLES)
            .map(|i| r_end * i as f64 / SAMPLES as f64)
            .collect();
        let y = x.iter().map(|r| curve.eval(*r).value).collect();
        zeros.push(DataPoint {
            x: sep.r_o,
            y: 0.0,
            x_bar: (sep.r_o - sep.r_o_error, sep.r_o + sep.r_o_error),
            y_bar: (0.0, 0.0),
        });
        let mut c = FigCurve::with_r_o(
            "",
            CurveKind::SigmaZ,
            (x, y),
            b,
            (sep.r_o, sep.r_o_error),
            params.tolerance,
        );
        // D = 1: radii are r/D, no unit
        c.label = format!("B/D = {b}: R_o/D = {:.4} ± {:.1e}", sep.r_o, sep.r_o_error);
        curves.push(c);
    }
    Ok(FigureData {
        id: "slab".into(),
        title:
            "The no-hole slab 2D thick: midplane σz (Sneddon 1946, Greenwood 1964, Lardner 1965)"
                .into(),
        note: "An infinite slab 2D thick (computed with D = 1: every radius is r/D), both faces pressed by P over r ≤ B, no hole; midplane \
               σ_z/P against r/D by Hankel transforms (boltzone::hankel); points: the first \
               upward zero R_o (the single-plate separation radius), with its error bar. Beyond \
               R_o the stress oscillates with amplitude falling ≈ e⁻⁶ per half-wave: those later \
               zeros are not separations."
            .into(),
        x_label: "r/D".into(),
        y_label: "σz/P".into(),
        curves,
        points: vec![DataSeries {
            label: "computed R_o (first upward zero)".into(),
            source: Source::Computed,
            points: zeros,
        }],
        values: vec![],
        report_values: format!(
            "{}: the slab is not one of the report's figures (the single-plate literature's \
             curve it cites).",
            super::NO_REPORT_VALUES
        ),
        seconds: 0.0,
    })
}
