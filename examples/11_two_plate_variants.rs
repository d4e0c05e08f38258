//! Example 11: the report's load variants for the 1/4 in and 1/8 in steel pairs (Figs. 18–22, 24).
//!
//! 304 steel (E = 28·10⁶ psi, ν = 0.3), A = 0.1285 in, B = 0.211 in, C = 2.0 in, bolt force
//! 1100 lb. For the 0.253 in pair: uniform bearing pressure (Fig. 18), triangular with the peak at
//! A and at B and the same force (Figs. 19–20), a uniform displacement of 50 µin under each nut
//! (Fig. 21), and the single-plate model (Fernlund's substitution, by `fem::single`) beside them;
//! the report: "the point of separation obtained by using the two plate model for all variations
//! of loading … occurs in the range of r/A values of 2.73 to 2.93 while the [single] plate model
//! yields separation at … 3.5", deflections under the nut in Fig. 22. For the 0.124 in pair the
//! fixed outer edge of Fig. 20(c) (Fig. 24: "within the resolution of the finite element grid
//! size, the effect is negligible").
//!
//! Self-checks (panics): convergence of every case; equilibrium of the interface force with the
//! bolt force (pressure loads); the single plate separates farther out than the two plates.
//! `BOLTZONE_QUICK=1` runs a loose tolerance (the test suite does).
//!
//! Builds on: example 04 (the model, now under other loads).

use boltzone::contact::two_plate::{solve, EdgeSupport, Loading, TwoPlateParams, TwoPlateSolution};
use boltzone::fem::single::{single_plate_r_o, SingleParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Peak, SinglePlate};
use std::f64::consts::PI;

const A: f64 = 0.1285;
const B: f64 = 0.211;
const C: f64 = 2.0;
const FORCE: f64 = 1100.0;

fn pair(d: f64, load: FaceLoad) -> Joint {
    Joint::symmetric(A, B, d, Material::steel_304_psi())
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(C))
        .unwrap()
        .with_load(load)
        .unwrap()
}

fn line(name: &str, s: &TwoPlateSolution, force: Option<f64>) {
    assert!(s.converged, "{name}: not converged");
    let total: f64 = s.force.iter().sum();
    if let Some(f) = force {
        assert!(
            (total - f).abs() < 1e-8 * f,
            "{name}: interface force {total} ≠ {f}"
        );
    }
    println!(
        "{:<34} {:>8.4} {:>7.3} {:>9.1e} {:>10.1} {:>10.1}",
        name,
        s.r_o,
        s.r_o / A,
        s.r_o_error,
        1e6 * s.nut_deflection,
        total
    );
}

pub fn main() {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let params = TwoPlateParams {
        tolerance: if quick { 5e-3 } else { 5e-4 },
        ..Default::default()
    };
    let p = FORCE / (PI * (B * B - A * A));
    println!(
        "1/4 in pair (D = 0.253 in), bolt force {FORCE} lb (mean bearing pressure {p:.0} psi)"
    );
    println!(
        "{:<34} {:>8} {:>7} {:>9} {:>10} {:>10}",
        "case", "R_o in", "R_o/A", "error", "nut µin", "force lb"
    );
    let d = 0.253;
    let uniform = solve(&pair(d, FaceLoad::uniform(A, B, p).unwrap()), &params).unwrap();
    line("uniform pressure (Fig. 18)", &uniform, Some(FORCE));
    for (peak, name) in [
        (Peak::AtA, "triangular, peak at A (Fig. 20a)"),
        (Peak::AtB, "triangular, peak at B (Fig. 20b)"),
    ] {
        let j = pair(d, FaceLoad::triangular(A, B, p, peak).unwrap());
        line(name, &solve(&j, &params).unwrap(), Some(FORCE));
    }
    let nut = TwoPlateParams {
        loading: Loading::NutDisplacement(50e-6),
        ..params
    };
    let s = solve(&pair(d, FaceLoad::uniform(A, B, p).unwrap()), &nut).unwrap();
    line("50 µin under each nut (Fig. 21)", &s, None);
    let plate = SinglePlate::new(
        A,
        OuterRadius::Finite(C),
        d,
        Material::steel_304_psi(),
        FaceLoad::uniform(A, B, p).unwrap(),
    )
    .unwrap();
    let (single, info) = single_plate_r_o(&plate, &SingleParams::default()).unwrap();
    println!(
        "{:<34} {:>8.4} {:>7.3} {:>9.1e}   (report: two-plate variants 2.73–2.93, single 3.5)",
        "single plate 2D thick (Fernlund)",
        single,
        single / A,
        info.error_estimate
    );
    assert!(
        single > uniform.r_o,
        "the single plate must separate farther out"
    );

    println!("\n1/8 in pair (D = 0.124 in): outer edge free and fixed (Figs. 20(c), 24)");
    let j = pair(0.124, FaceLoad::uniform(A, B, p).unwrap());
    let free = solve(&j, &params).unwrap();
    line("outer edge free", &free, Some(FORCE));
    let fixed = solve(
        &j,
        &TwoPlateParams {
            edge: EdgeSupport::Fixed,
            ..params
        },
    )
    .unwrap();
    line("outer edge fixed (Fig. 20c)", &fixed, None);
    println!(
        "fixed − free: {:.2e} in (the report's grid interval: 0.015 in)",
        fixed.r_o - free.r_o
    );
}
