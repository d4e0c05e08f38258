//! One joint written in the three unit systems gives the same R_o to 1e-12 relative (the
//! numbers of each file converted here by the definitions 1 in = 25.4 mm, 1 psi =
//! 6894.757293168361 Pa), on the slab, the single plate (Hankel and FE) and the two-plate FE
//! routes (`tests/scene/joint_units.rs` says why the two-plate FE needs its entry scaling to
//! divide);
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

fn assert_same(r: &[f64], what: &str) {
    for x in &r[1..] {
        let rel = (x - r[0]).abs() / r[0];
        assert!(rel <= 1e-12, "{what}: {r:?}, relative difference {rel:e}");
    }
}

#[test]
fn same_joint_in_three_unit_systems_slab() {
    assert_same(&r_o_in_metres("slab", 1e-10, false), "slab");
}

#[test]
fn same_joint_in_three_unit_systems_single_plate_hankel() {
    assert_same(&r_o_in_metres("single-plate", 1e-6, true), "single plate");
}

#[test]
fn same_joint_in_three_unit_systems_single_plate_fem() {
    assert_same(
        &r_o_in_metres("single-plate:fem", 1e-4, true),
        "single plate FE",
    );
}

#[test]
fn same_joint_in_three_unit_systems_two_plate() {
    assert_same(&r_o_in_metres("two-plate", 1e-2, true), "two-plate");
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
