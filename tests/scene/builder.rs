//! The typed scene builder (`Scene::builder`) against the scene files it replaces: the example
//! scenes built in code equal the parsed files (`==`) and give the same answer bit for bit, and
//! every bad value is refused with its key.

use super::example;
use boltzone::scene::file::{Constants, InterfaceKind};
use boltzone::scene::{Method, Model, Scene, SceneError, UnitSystem};

fn table1_row1() -> boltzone::scene::SceneBuilder {
    Scene::builder(UnitSystem::InPsiLbf)
        .hole(0.1)
        .bearing_face(0.31)
        .pressure(1000.0)
        .plate(0.1)
        .material(Constants { e: 28.0e6, nu: 0.3 })
        .outer_radius(1.54)
}

#[test]
fn built_scenes_equal_the_parsed_example_files_and_their_answers() {
    let built = [
        ("table1_row1", table1_row1().build().unwrap()),
        (
            "table2_case5",
            Scene::builder(UnitSystem::InPsiLbf)
                .hole(0.1285)
                .bearing_face(0.211)
                .force(1100.0)
                .plate(0.124)
                .material("steel-304")
                .plate(0.257)
                .outer_radius(2.0)
                .interface(InterfaceKind::Welded)
                .build()
                .unwrap(),
        ),
    ];
    for (name, scene) in built {
        let parsed = Scene::parse(&example(name)).unwrap();
        assert_eq!(scene, parsed, "{name}");
        let (a, b) = (
            boltzone::solve(&scene).unwrap(),
            boltzone::solve(&parsed).unwrap(),
        );
        assert_eq!(a.r_o.to_bits(), b.r_o.to_bits(), "{name}");
        assert_eq!(a.r_o_error.to_bits(), b.r_o_error.to_bits(), "{name}");
    }
}

#[test]
fn a_built_scene_in_mm_equals_the_same_scene_in_inches() {
    // the same joint as Table 1 row 1 in mm-MPa-N: R_o in mm / 25.4 = R_o in inches, to the
    // route's stopping tolerance (1e-3 of the tolerance; each scene solves in its own units,
    // tests/scene/units.rs): an identity of the units, not of the builder
    let inch = boltzone::solve(&table1_row1().tolerance(1e-6).build().unwrap()).unwrap();
    let mm = Scene::builder(UnitSystem::MmMpaN)
        .hole(2.54)
        .bearing_face(0.31 * 25.4)
        .pressure(1000.0 * 6.894_757_293_168_361e-3)
        .plate(2.54)
        .material(Constants {
            e: 28.0e6 * 6.894_757_293_168_361e-3,
            nu: 0.3,
        })
        .outer_radius(1.54 * 25.4)
        .tolerance(1e-6)
        .build()
        .unwrap();
    let mm = boltzone::solve(&mm).unwrap();
    assert!(inch.converged && mm.converged);
    assert!(
        (mm.r_o / 25.4 - inch.r_o).abs() < 1e-9 * inch.r_o,
        "{} mm vs {} in",
        mm.r_o,
        inch.r_o
    );
}

#[test]
fn bad_values_are_refused_naming_their_key() {
    type Build = Box<dyn Fn() -> Result<Scene, SceneError>>;
    let cases: [(Build, &str); 8] = [
        (
            Box::new(|| table1_row1().tolerance(f64::NAN).build()),
            "tolerance",
        ),
        (Box::new(|| table1_row1().hole(-0.1).build()), "hole.radius"),
        (
            Box::new(|| table1_row1().bearing_face(0.05).build()),
            "load.outer_radius",
        ),
        (
            Box::new(|| table1_row1().plate(0.0).build()),
            "plates[1].thickness",
        ),
        (
            Box::new(|| table1_row1().material("unobtainium").build()),
            "plates[0].material",
        ),
        (
            Box::new(|| table1_row1().friction(-0.2).build()),
            "joint.mu",
        ),
        // the tables bound a single plate's rim far from R_o only: one inside the contact
        // zone is refused by its key
        (
            Box::new(|| {
                table1_row1()
                    .outer_radius(0.35)
                    .model(Model::SinglePlate)
                    .method(Method::Table)
                    .build()
            }),
            "joint.outer_radius",
        ),
        // and they hold no slab
        (
            Box::new(|| {
                Scene::builder(UnitSystem::InPsiLbf)
                    .hole(0.1)
                    .bearing_face(0.31)
                    .pressure(1000.0)
                    .plate(0.1)
                    .model(Model::Slab)
                    .method(Method::Table)
                    .build()
            }),
            "method",
        ),
    ];
    for (build, key) in cases {
        match build() {
            Err(SceneError::Key { key: k, reason }) => {
                assert_eq!(k, key, "{reason}");
                assert!(!reason.is_empty());
            }
            other => panic!("{key}: expected a key error, got {other:?}"),
        }
    }
    // no plate at all, and two loads at once
    let none = Scene::builder(UnitSystem::MPaN)
        .hole(0.0)
        .bearing_face(1.0)
        .pressure(1.0)
        .model(Model::Slab)
        .build();
    assert!(
        matches!(none, Err(SceneError::Key { ref key, .. }) if key == "plates"),
        "{none:?}"
    );
    let two = table1_row1().force(10.0).build();
    assert!(
        matches!(two, Err(SceneError::Key { ref key, .. }) if key.starts_with("load")),
        "{two:?}"
    );
}
