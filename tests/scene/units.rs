//! One joint written in the three unit systems (the numbers of each file converted here by the
//! definitions 1 in = 25.4 mm, 1 psi = 6894.757293168361 Pa): its SI joint is the same to the
//! rounding of the conversions (4 ulp), and its R_o the same to the routes' own stopping
//! tolerance on the slab, the single plate (Hankel and FE) and the two-plate FE. A scene solves
//! in its own units, so the three solves start from numbers that differ in their last bits, and
//! each iteration may stop at another point within its target: the bound is 1e-3 of the
//! tolerance (the root search's, `route::single_plate::hankel_params`), at least 1e-12
//! (`tests/scene/joint_units.rs` says why the two-plate FE needs its entry scaling to divide);
//! and a library material by name equals its constants written out.

use boltzone::scene::Scene;

/// Metres per (in, mm, m); pascals per (psi, MPa, Pa).
const SYSTEMS: [(&str, f64, f64); 3] = [
    ("in-psi-lbf", 0.0254, 6894.757293168361),
    ("mm-MPa-N", 1e-3, 1e6),
    ("m-Pa-N", 1.0, 1.0),
];

/// The joint A = 0.1 in, B = 0.31 in, D = 0.1 in, C = 1.54 in (or infinite), P = 1000 psi,
/// E = 28e6 psi, ν = 0.3, in the system `(name, metres, pascals)`.
fn scene(model: &str, tol: f64, outer: bool, sys: (&str, f64, f64)) -> String {
    let (name, m, pa) = sys;
    let (model, method) = model.split_once(':').unwrap_or((model, "auto"));
    let len = |x: f64| x * 0.0254 / m;
    let st = |x: f64| x * 6894.757293168361 / pa;
    let joint = if outer {
        format!("[joint]\nouter_radius = {:e}\n", len(1.54))
    } else {
        String::new()
    };
    format!(
        "units = \"{name}\"\nmodel = \"{model}\"\nmethod = \"{method}\"\ntolerance = {tol:e}\n[hole]\nradius = {:e}\n\
         [load]\nouter_radius = {:e}\npressure = {:e}\n[[plates]]\nthickness = {:e}\n\
         material = {{ E = {:e}, nu = 0.3 }}\n{joint}",
        len(0.1),
        len(0.31),
        st(1000.0),
        len(0.1),
        st(28.0e6)
    )
}

fn r_o_in_metres(model: &str, tol: f64, outer: bool) -> Vec<f64> {
    SYSTEMS
        .iter()
        .map(|&sys| {
            let s =
                boltzone::solve(&Scene::parse(&scene(model, tol, outer, sys)).unwrap()).unwrap();
            assert_eq!(
                s.length_unit,
                ["in", "mm", "m"][SYSTEMS.iter().position(|x| x.0 == sys.0).unwrap()]
            );
            s.r_o * sys.1
        })
        .collect()
}

/// The three R_o agree to the routes' stopping tolerance at `tol` (module doc).
fn assert_same(r: &[f64], tol: f64, what: &str) {
    for x in &r[1..] {
        let rel = (x - r[0]).abs() / r[0];
        assert!(
            rel <= (1e-3 * tol).max(1e-12),
            "{what}: {r:?}, relative difference {rel:e}"
        );
    }
}

#[test]
fn same_joint_in_si_from_three_unit_systems() {
    let joints: Vec<boltzone::Joint> = SYSTEMS
        .iter()
        .map(|&sys| {
            let scene = Scene::parse(&scene("two-plate", 1e-2, true, sys)).unwrap();
            boltzone::scene::si::joint_si(&scene).unwrap().0
        })
        .collect();
    let numbers = |j: &boltzone::Joint| {
        let c = match j.outer_radius() {
            boltzone::OuterRadius::Finite(c) => c,
            boltzone::OuterRadius::Infinite => f64::INFINITY,
        };
        let m = j.upper().material();
        [
            j.hole_radius(),
            j.load().outer(),
            j.upper().thickness(),
            j.lower().thickness(),
            c,
            m.youngs_modulus(),
            m.poisson_ratio(),
            j.load().total_force(),
        ]
    };
    let first = numbers(&joints[0]);
    for j in &joints[1..] {
        for (x, y) in numbers(j).iter().zip(first) {
            assert!((x - y).abs() <= 4.0 * f64::EPSILON * y.abs(), "{x} vs {y}");
        }
    }
}

#[test]
fn same_joint_in_three_unit_systems_slab() {
    assert_same(&r_o_in_metres("slab", 1e-10, false), 1e-10, "slab");
}

#[test]
fn same_joint_in_three_unit_systems_single_plate_hankel() {
    assert_same(
        &r_o_in_metres("single-plate", 1e-6, true),
        1e-6,
        "single plate",
    );
}

#[test]
fn same_joint_in_three_unit_systems_single_plate_fem() {
    assert_same(
        &r_o_in_metres("single-plate:fem", 1e-4, true),
        1e-4,
        "single plate FE",
    );
}

#[test]
fn same_joint_in_three_unit_systems_two_plate() {
    assert_same(&r_o_in_metres("two-plate", 1e-2, true), 1e-2, "two-plate");
}

#[test]
fn library_steel_304_is_the_reports_constants() {
    // the report's specimens: E = 28e6 psi, nu = 0.3 (psi = 6894.757293168361 Pa)
    let m = boltzone::scene::materials::lookup("steel-304").unwrap();
    assert!((m.youngs_modulus / (28.0e6 * 6894.757293168361) - 1.0).abs() < 1e-15);
    assert_eq!(m.poisson_ratio, 0.3);
    assert_eq!(
        boltzone::scene::materials::lookup("Aluminum-6061-T6").map(|m| m.name),
        Some("aluminium-6061-t6")
    );
}
