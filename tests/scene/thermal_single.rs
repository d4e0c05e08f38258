//! The scene's `[temperature]` table on the single-plate model (issue 12 item 5): the example
//! scene (a material table read between rows) equals, bit for bit, the library call it wraps
//! (`fem::single_thermal`, built here by hand in SI from the file's numbers), `auto` picks the finite elements; what the substitute
//! cannot represent is refused naming the key and the line (the slab:
//! `tests/scene/temperature.rs`).

use crate::example;
use boltzone::fem::plate_temperature::PlateTemperature;
use boltzone::fem::single::SingleParams;
use boltzone::fem::single_thermal::{solve_with_temperature, SingleTemperature};
use boltzone::fem::thermal::ThermalMaterial;
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
    let rows = [[70.0, 28.3e6, 0.29, 9.2e-6], [200.0, 27.6e6, 0.29, 9.5e-6]];
    let si = rows.map(|r| [r[0], r[1] * PSI, r[2], r[3]]);
    let t = SingleTemperature {
        reference: 70.0,
        plate: t,
        material: ThermalMaterial::table(si.to_vec()).unwrap(),
    };
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
            31,
        ),
        // alpha beside a table that holds it
        (
            "reference = 70.0",
            "reference = 70.0\nalpha = [1e-5]",
            "temperature.alpha",
            31,
        ),
        // a face temperature off the table
        (
            "[[120.0, 70.0]]",
            "[[220.0, 70.0]]",
            "temperature.gradient",
            31,
        ),
        // the Hankel route has no thermal strains
        (
            "method = \"auto\"",
            "method = \"hankel\"",
            "temperature.reference",
            30,
        ),
        // a rigid nut has no stress scale to set the thermal stresses against
        (
            "pressure = 1000.0",
            "nut_displacement = 1e-4",
            "temperature.reference",
            30,
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
