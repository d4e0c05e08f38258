//! The reach of the semi-analytic two-plate route with the hole (`hankel::receding::MAX_B_OVER_D`,
//! B/D ≤ 16): the library refuses a wider load as bad input naming the ratio and its value,
//! before any computation; a scene with `method = "hankel"` is refused (exit 2) naming the key
//! `load.outer_radius` and its line; `method = "auto"` takes the finite elements there.

use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
use boltzone::hankel::receding::{MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
use boltzone::scene::{two_hankel, Scene};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// Table 1's hole and plate (A = D = 0.1) with a uniform load out to `b`.
fn plate(b: f64) -> SinglePlate {
    SinglePlate::new(
        0.1,
        OuterRadius::Infinite,
        0.1,
        Material::new(3.0e7, 0.3).unwrap(),
        FaceLoad::uniform(0.1, b, 1.0).unwrap(),
    )
    .unwrap()
}

/// A two-plate scene of Table 1's plate with the load out to `b` (line 7).
fn scene(method: &str, tolerance: f64, b: f64) -> String {
    format!(
        "model = \"two-plate\"\nmethod = \"{method}\"\ntolerance = {tolerance:e}\n\
         [hole]\nradius = 0.1\n[load]\nouter_radius = {b}\npressure = 1.0\n[[plates]]\n\
         thickness = 0.1\nmaterial = {{ E = 3e7, nu = 0.3 }}\n"
    )
}

#[test]
fn the_library_refuses_a_load_beyond_its_reach() {
    assert_eq!(MAX_B_OVER_D, 16.0);
    // B/D = 17: refused at once (the run at 16 takes 4.7 s; the refusal no measurable time)
    let start = std::time::Instant::now();
    let err = two_plate_hole(&plate(1.7), &HoledParams::for_tolerance(1e-6)).unwrap_err();
    assert!(err.is_input(), "{err}");
    let text = err.to_string();
    assert!(text.contains("B/D") && text.contains("17"), "{text}");
    assert!(
        start.elapsed().as_secs_f64() < 0.5,
        "refused before computing"
    );
}

#[test]
fn a_scene_asking_for_the_route_beyond_its_reach_is_refused_by_key() {
    let err = Scene::parse(&scene("hankel", 1e-6, 1.7)).unwrap_err();
    assert!(err.is_input(), "{err}");
    assert_eq!(err.line(), Some(7), "{err}");
    assert!(err.to_string().contains("load.outer_radius"), "{err}");
    // auto never takes the route beyond its reach, and within it answers semi-analytically:
    // by the route, or by the tables built from it where their bar meets the tolerance
    let wide = Scene::parse(&scene("auto", 1e-6, 1.7)).unwrap();
    assert!(!two_hankel::auto_takes(&wide));
    let inside = Scene::parse(&scene("auto", 1e-6, 1.6)).unwrap();
    assert!(two_hankel::auto_takes(&inside) || two_hankel::table_blocker(&inside).is_none());
    // the command: exit 2 naming the key, before computing
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("holed_reach_scene");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("s.toml");
    std::fs::write(&path, scene("hankel", 1e-6, 1.7)).unwrap();
    let out = crate::common::boltzone(&["solve", path.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert!(
        text.contains("load.outer_radius") && text.contains("line 7"),
        "{text}"
    );
}

#[test]
fn a_rim_halves_the_reach_in_the_library_the_cli_and_the_scene() {
    // with a finite rim C the route costs 2–5× the infinite plate's: B/D ≤ 8
    // (`MAX_B_OVER_D_RIM`); the infinite plate keeps its 16
    assert_eq!(MAX_B_OVER_D_RIM, 8.0);
    let mat = Material::new(3.0e7, 0.3).unwrap();
    let rimmed = SinglePlate::new(
        0.1,
        OuterRadius::Finite(3.0),
        0.1,
        mat,
        FaceLoad::uniform(0.1, 0.85, 1.0).unwrap(),
    )
    .unwrap();
    let start = std::time::Instant::now();
    let err = two_plate_hole(&rimmed, &HoledParams::for_tolerance(1e-3)).unwrap_err();
    assert!(err.is_input(), "{err}");
    assert!(err.to_string().contains("8.5"), "{err}");
    assert!(
        start.elapsed().as_secs_f64() < 0.5,
        "refused before computing"
    );
    // the CLI names --b and exits 2; auto takes the finite elements (exit 0 or 3, not 2)
    let args = |method: &str| {
        crate::common::boltzone(&[
            "two", "--a", "0.1", "--b", "0.85", "--d", "0.1", "--c", "3", "--method", method,
            "--tol", "1e-2",
        ])
    };
    let out = args("hankel");
    let text = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert!(text.contains("--b") && text.contains("rim"), "{text}");
    assert_ne!(args("auto").status.code(), Some(2));
    // the scene: refused by key with a rim, taken by auto's FE
    let with_rim = |method: &str| {
        scene(method, 1e-6, 0.85).replace("[hole]", "[joint]\nouter_radius = 3.0\n[hole]")
    };
    let err = Scene::parse(&with_rim("hankel")).unwrap_err();
    assert!(err.to_string().contains("load.outer_radius"), "{err}");
    assert!(!two_hankel::auto_takes(
        &Scene::parse(&with_rim("auto")).unwrap()
    ));
}

#[test]
fn holes_below_the_smallest_validated_are_refused() {
    // A/D = 0.001 (the 10⁴ fuzz: residual tractions of 1e1–1e4 P on the hole, and over 30 s
    // with a rim): refused at once as input naming A/D; the CLI names --a, auto takes the FE
    assert_eq!(MIN_A_OVER_D, 0.04);
    let tiny = SinglePlate::new(
        0.001,
        OuterRadius::Infinite,
        1.0,
        Material::new(3.0e7, 0.3).unwrap(),
        FaceLoad::uniform(0.001, 0.5, 1.0).unwrap(),
    )
    .unwrap();
    let err = two_plate_hole(&tiny, &HoledParams::for_tolerance(1e-3)).unwrap_err();
    assert!(err.is_input() && err.to_string().contains("A/D"), "{err}");
    let args = |method: &str| {
        crate::common::boltzone(&[
            "two", "--a", "0.001", "--b", "0.5", "--d", "1", "--method", method, "--tol", "1e-2",
        ])
    };
    let out = args("hankel");
    let text = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert!(text.contains("--a"), "{text}");
    assert_ne!(args("auto").status.code(), Some(2));
    // the scene: refused by key
    let s = scene("hankel", 1e-3, 0.5)
        .replace("radius = 0.1", "radius = 0.001")
        .replace("thickness = 0.1", "thickness = 1.0");
    let err = Scene::parse(&s).unwrap_err();
    assert!(err.to_string().contains("hole.radius"), "{err}");
}
