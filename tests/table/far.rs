//! The far tables (`boltzone::table::far`) against solves that did not build them.

use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::hankel::receding::{Layer, RecedingParams};
use boltzone::hankel::{SeparationParams, Slab};
use boltzone::table::far::{separation_radius, FarTable};
use boltzone::table::Model;
use boltzone::{FaceLoad, InputError, Material, OuterRadius, SinglePlate};

fn two_plates_no_hole(b: f64) -> (f64, f64) {
    let layer = Layer::new(
        1.0,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(0.0, b, 1.0).unwrap(),
    )
    .unwrap();
    let c = layer.receding_contact(&RecedingParams::default()).unwrap();
    (c.r_o, c.info.r_o_error)
}

fn single_plate_no_hole(b: f64) -> (f64, f64) {
    let slab = Slab::new(
        1.0,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(0.0, b, 1.0).unwrap(),
    )
    .unwrap();
    let p = SeparationParams {
        rel_tol: 1e-12,
        ..Default::default()
    };
    let s = slab.separation_radius(&p).unwrap();
    (s.r_o, s.r_o_error)
}

/// The table's answer for the disk load 0..B (A = 0) against a fresh solve (r_o, its error),
/// and its bar within `tol`.
fn assert_table_holds(model: Model, b: f64, (r_o, err): (f64, f64), tol: f64) {
    let t = separation_radius(model, 0.0, b, 1.0, tol).unwrap();
    assert!(
        (t.value - r_o).abs() <= t.error + err,
        "{model:?}, B/D {b}: table {} ± {:.1e}, solve {r_o} ± {err:.1e}",
        t.value,
        t.error
    );
    assert!(t.converged, "{model:?}, B/D {b}: bar {:.1e}", t.error);
}

#[test]
fn the_two_plate_table_holds_against_fresh_no_hole_solves() {
    // B/D not among the table's nodes (first-kind points in D/B on [1/48, 1/2])
    for b in [2.3, 3.7, 6.1] {
        assert_table_holds(Model::TwoPlates, b, two_plates_no_hole(b), 1e-8);
    }
}

#[test]
fn the_single_plate_table_holds_against_fresh_no_hole_solves_out_to_wide_loads() {
    // the build's own estimate is 4e-10 D, times the Lebesgue function: 1e-9 of R_o ≥ 2D
    for b in [2.2, 4.9, 17.0, 333.0, 4100.0] {
        assert_table_holds(Model::SinglePlate, b, single_plate_no_hole(b), 1e-9);
    }
}

#[test]
fn an_extrapolated_bar_holds_on_the_single_plate_out_to_b_over_d_infinite() {
    // the two-plate table extrapolates beyond B/D = 48 (its solver's reach); the same
    // construction on the single plate, sampled only to B/D = 48 as the two-plate table is,
    // against the single plate's full table (sampled to B/D ≈ 10⁴ and through t = 0)
    let full = FarTable::of(Model::SinglePlate);
    let two = FarTable::of(Model::TwoPlates);
    let n = two.coefficients.len();
    let nodes = FarTable::nodes(two.t_lo, two.t_hi, n);
    let mut build = 0.0f64;
    let values: Vec<f64> = nodes
        .iter()
        .map(|t| {
            let (r_o, e) = single_plate_no_hole(1.0 / t);
            build = build.max(e);
            r_o - 1.0 / t
        })
        .collect();
    let short = FarTable::from_samples(two.t_lo, two.t_hi, &values, build);
    for t in [1.0 / 60.0, 1.0 / 100.0, 1.0 / 1000.0, 0.0] {
        let (g, bar) = short.g(t);
        let (g_full, bar_full) = full.g(t);
        assert!(bar.is_finite(), "D/B {t}: the extrapolation bounds nothing");
        assert!(
            (g - g_full).abs() <= bar + bar_full,
            "D/B {t}: extrapolated {g} ± {bar:.1e}, full {g_full} ± {bar_full:.1e}"
        );
    }
}

#[test]
fn the_holed_single_plate_lies_within_the_bar_where_the_hole_is_far() {
    let m = Material::unit(0.3).unwrap();
    for (a, b) in [(1.0, 4.5), (0.5, 5.5), (4.0, 9.0)] {
        let plate = SinglePlate::new(
            a,
            OuterRadius::Infinite,
            1.0,
            m,
            FaceLoad::uniform(a, b, 1.0).unwrap(),
        )
        .unwrap();
        let sep = SeparationParams {
            rel_tol: 1e-11,
            ..Default::default()
        };
        let (s, _) =
            single_plate_separation(&plate, &sep, &HoleParams::for_tolerance(1e-10)).unwrap();
        let t = separation_radius(Model::SinglePlate, a, b, 1.0, 1e-6).unwrap();
        assert!(
            (t.value - s.r_o).abs() <= t.error + s.r_o_error,
            "A/D {a}, B/D {b}: table {} ± {:.1e}, holed {} ± {:.1e}",
            t.value,
            t.error,
            s.r_o,
            s.r_o_error
        );
    }
}

#[test]
fn the_holed_two_plate_route_lies_within_the_bar_where_the_hole_is_far() {
    // one geometry (the 1e-8 route takes ~2 s here); the survey is example 24
    let (a, b) = (0.5, 4.5);
    let m = Material::unit(0.3).unwrap();
    let plate = SinglePlate::new(
        a,
        OuterRadius::Infinite,
        1.0,
        m,
        FaceLoad::uniform(a, b, 1.0).unwrap(),
    )
    .unwrap();
    let (h, _) = two_plate_hole_to(&plate, 1e-8, &[]).unwrap();
    let t = separation_radius(Model::TwoPlates, a, b, 1.0, 1e-6).unwrap();
    assert!(
        (t.value - h.r_o).abs() <= t.error + h.info.r_o_error,
        "table {} ± {:.1e}, holed {} ± {:.1e}",
        t.value,
        t.error,
        h.r_o,
        h.info.r_o_error
    );
}

#[test]
fn the_far_table_refuses_what_it_does_not_cover_naming_the_ratio() {
    let e = separation_radius(Model::TwoPlates, 0.1, 0.15, 0.1, 1e-6).unwrap_err();
    assert!(
        matches!(
            e,
            InputError::Parameter {
                field: "B/D (far table)",
                ..
            }
        ),
        "{e}"
    );
    let e = separation_radius(Model::TwoPlates, 0.5, 0.6, 0.1, 1e-6).unwrap_err();
    assert!(
        matches!(
            e,
            InputError::Parameter {
                field: "A/D (far table)",
                ..
            }
        ),
        "{e}"
    );
    let e = separation_radius(Model::TwoPlates, 0.1, 0.2, 0.1, 1e-6).unwrap_err();
    assert!(e.to_string().contains("(R_o − A)/D"), "{e}");
    let e = separation_radius(Model::SinglePlate, 0.3, 0.2, 0.1, 1e-6).unwrap_err();
    assert!(matches!(e, InputError::LoadRadii { .. }), "{e}");
    for bad in [f64::NAN, -1.0, 0.0] {
        assert!(separation_radius(Model::SinglePlate, 0.0, 1.0, bad, 1e-6).is_err());
    }
}

/// σ_z(x, 0)/(−P) of the plane-strain slab 2D thick (D = 1) pressed on both faces over x < 0:
/// 1/2 − (1/π)∫₀^∞ K(k) sin(kx)/k dk, K the slab's midplane kernel (the same K as the Hankel
/// route's: the z-dependence of the symmetric slab does not know the transform), by
/// Gauss–Legendre panels of width `panel` out to k = `end` (K ~ 2k e^(−k)).
fn plane_strain_midplane(x: f64, panel: f64, end: f64) -> f64 {
    let rule = boltzone::numerics::quadrature::gauss_legendre(20);
    let mut sum = 0.0;
    let mut a = 0.0;
    while a < end {
        let (h, m) = (0.5 * panel, a + 0.5 * panel);
        for &(s, w) in rule.iter() {
            let k = m + h * s;
            sum += w * h * boltzone::hankel::kernel::midplane(k) * (k * x).sin() / k;
        }
        a += panel;
    }
    0.5 - sum / std::f64::consts::PI
}

#[test]
fn the_single_plate_limit_is_the_plane_strain_edge_of_a_half_plane_load() {
    // B/D → ∞: the load edge of the single plate is the plane-strain slab's edge of a load on
    // x < 0, whose midplane σ_z changes sign at x₀ = g(∞): an independent formulation (a Fourier
    // sine integral instead of the Hankel route's root beyond a disk)
    let root = |panel: f64, end: f64| {
        let mut f = |x: f64| Ok::<f64, ()>(plane_strain_midplane(x, panel, end));
        let (fa, fb) = (f(0.5).unwrap(), f(1.5).unwrap());
        assert!(
            fa > 0.0 && fb < 0.0,
            "no sign change on [0.5, 1.5]: {fa} {fb}"
        );
        boltzone::numerics::root::brent(&mut f, 0.5, fa, 1.5, fb, 1e-13, 200).unwrap()
    };
    let fine = root(0.25, 80.0);
    let coarse = root(0.5, 60.0);
    let quadrature = (fine.x - coarse.x).abs() + fine.half_width;
    let (g, bar) = FarTable::of(Model::SinglePlate).g(0.0);
    eprintln!(
        "g(∞): table {g} ± {bar:.1e}, plane strain {} ± {quadrature:.1e}",
        fine.x
    );
    assert!(
        (g - fine.x).abs() <= bar + quadrature,
        "table g(∞) = {g} ± {bar:.1e}, plane strain {} ± {quadrature:.1e}",
        fine.x
    );
}
