//! The scene's `[temperature]` table: the same joint and temperatures through a scene file (in
//! two unit systems) and through the library call give the same R_o; bad tables are refused
//! naming the key and the line.

use boltzone::contact::thermal::{solve_with_temperature, JointTemperature, PlateTemperature};
use boltzone::contact::two_plate::TwoPlateParams;
use boltzone::scene::Scene;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};

const BASE: &str = "tolerance = 2e-3
[hole]
radius = 0.1
[load]
outer_radius = 0.31
pressure = 1000.0
[[plates]]
thickness = 0.1
material = { E = 1e7, nu = 0.33 }
[joint]
outer_radius = 1.0
";

#[test]
fn scene_gradient_equals_the_library_call() {
    let text = format!(
        "{BASE}[temperature]\nreference = 70.0\ngradient = [[70.0, 70.2]]\nalpha = [13e-6]\n"
    );
    let s = boltzone::solve(&Scene::parse(&text).unwrap()).unwrap();
    let p = Plate::new(0.1, Material::new(1e7, 0.33).unwrap()).unwrap();
    let load = FaceLoad::uniform(0.1, 0.31, 1000.0).unwrap();
    let j = Joint::new(0.1, OuterRadius::Finite(1.0), p, p, load).unwrap();
    let hot = PlateTemperature::Linear {
        interface: 70.0,
        outer: 70.2,
    };
    let t = JointTemperature::constant(&j, 70.0, [hot.clone(), hot], [13e-6; 2]).unwrap();
    let params = TwoPlateParams {
        tolerance: 2e-3,
        ..Default::default()
    };
    let lib = solve_with_temperature(&j, &params, &t).unwrap();
    // the scene converts to SI and back: inputs moved by an ulp, which the thermal problem
    // amplifies as any rounding (tests/contact/thermal.rs: ΔR_o/R_o ≤ 1e-9; measured 2e-12)
    assert!(
        (s.r_o - lib.r_o).abs() < 1e-9 * lib.r_o,
        "{} vs {}",
        s.r_o,
        lib.r_o
    );
    // in mm-MPa-N the same joint (temperatures and α unchanged: only differences matter)
    let mm = format!(
        "units = \"mm-MPa-N\"\ntolerance = 2e-3\n[hole]\nradius = 2.54\n[load]\nouter_radius = 7.874\n\
         pressure = {}\n[[plates]]\nthickness = 2.54\nmaterial = {{ E = {}, nu = 0.33 }}\n\
         [joint]\nouter_radius = 25.4\n[temperature]\nreference = 70.0\n\
         gradient = [[70.0, 70.2]]\nalpha = [13e-6]\n",
        1000.0 * 6894.757293168361e-6,
        1e7 * 6894.757293168361e-6
    );
    let s_mm = boltzone::solve(&Scene::parse(&mm).unwrap()).unwrap();
    assert!(
        (s_mm.r_o / 25.4 - lib.r_o).abs() < 1e-9 * lib.r_o,
        "{} mm",
        s_mm.r_o
    );
}

#[test]
fn bad_temperature_tables_name_key_and_line() {
    for (table, key, line) in [
        (
            "reference = 70.0\nalpha = [1e-5]\n",
            "temperature.reference",
            13,
        ),
        (
            "reference = 70.0\nplates = [1.0, 2.0, 3.0]\nalpha = [1e-5]\n",
            "temperature.plates",
            14,
        ),
        (
            "reference = 70.0\nplates = [1.0]\ngradient = [[1.0, 2.0]]\nalpha = [1e-5]\n",
            "temperature.gradient",
            15,
        ),
        (
            "reference = 70.0\nplates = [1.0]\nalpha = []\n",
            "temperature.alpha",
            15,
        ),
    ] {
        let text = format!("{BASE}[temperature]\n{table}");
        let e = Scene::parse(&text).unwrap_err();
        assert!(e.is_input(), "{e}");
        assert!(
            e.to_string().contains(key) && e.line() == Some(line),
            "{table}: {e}"
        );
    }
    let slab = format!(
        "model = \"slab\"\n{}[temperature]\nreference = 1.0\nplates = [2.0]\nalpha = [1e-5]\n",
        BASE.replace("[joint]\nouter_radius = 1.0\n", "")
    );
    let e = Scene::parse(&slab).unwrap_err();
    assert!(e.to_string().contains("two-plate"), "{e}");
}
