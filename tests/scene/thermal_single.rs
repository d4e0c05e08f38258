//! The scene's `[temperature]` table on the single-plate model (issue 12 item 5): the example
//! scene equals, bit for bit, the library call it wraps (`fem::single_thermal`, built here by
//! hand in SI from the file's numbers), `auto` picks the finite elements; what the substitute
//! cannot represent is refused naming the key and the line (the slab:
//! `tests/scene/temperature.rs`).

use crate::example;
use boltzone::fem::plate_temperature::PlateTemperature;
use boltzone::fem::single::SingleParams;
use boltzone::fem::single_thermal::{solve_with_temperature, SingleTemperature};
use boltzone::scene::{Method, Scene};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

const IN: f64 = 0.0254;
const PSI: f64 = 4.4482216152605 / (IN * IN);

#[test]
fn example_scene_equals_the_library_call() {
    let scene = Scene::parse(&example("single_plate_thermal")).unwrap();
    let s = boltzone::solve(&scene).unwrap();
    assert_eq!(s.method, Method::Fem);
    let load = FaceLoad::uniform(0.1 * IN, 0.31 * IN, 1000.0 * PSI).unwrap();
    let m = Material::new(28.0e6 * PSI, 0.3).unwrap();
    let plate =
        SinglePlate::new(0.1 * IN, OuterRadius::Finite(1.54 * IN), 0.1 * IN, m, load).unwrap();
    let t = PlateTemperature::Linear {
        interface: 120.0,
        outer: 70.0,
    };
    let t = SingleTemperature::constant(&plate, 70.0, t, 9.6e-6).unwrap();
    let params = SingleParams {
        tolerance: 1e-3,
        ..SingleParams::default()
    };
    let lib = solve_with_temperature(&plate, &params, &t).unwrap();
    println!("R_o = {} in ± {} in", s.r_o, s.r_o_error);
    assert_eq!(s.r_o.to_bits(), (lib.r_o / IN).to_bits());
    assert_eq!(s.r_o_error.to_bits(), (lib.r_o_error / IN).to_bits());
    assert!(s.converged && s.field.is_some());
}

#[test]
fn what_the_substitute_cannot_take_is_refused_naming_key_and_line() {
    let base = example("single_plate_thermal");
    for (from, to, key, line) in [
        // two different plates: not a mirror image
        (
            "gradient = [[120.0, 70.0]]",
            "gradient = [[120.0, 70.0], [110.0, 70.0]]",
            "temperature.gradient",
            28,
        ),
        (
            "alpha = [9.6e-6]",
            "alpha = [9.6e-6, 1e-5]",
            "temperature.alpha",
            29,
        ),
        // the Hankel route has no thermal strains
        (
            "method = \"auto\"",
            "method = \"hankel\"",
            "temperature.reference",
            27,
        ),
        // a rigid nut has no stress scale to set the thermal stresses against
        (
            "pressure = 1000.0",
            "nut_displacement = 1e-4",
            "temperature.reference",
            27,
        ),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base);
        let e = Scene::parse(&text).unwrap_err();
        assert!(e.is_input(), "{e}");
        assert!(
            e.to_string().contains(key) && e.line() == Some(line),
            "{to}: {e} (line {:?})",
            e.line()
        );
    }
}
