//! The reach of the semi-analytic two-plate route with the hole (`hankel::receding::MAX_B_OVER_D`,
//! B/D ≤ 16): the library refuses a wider load as bad input naming the ratio and its value,
//! before any computation; a scene with `method = "hankel"` is refused (exit 2) naming the key
//! `load.outer_radius` and its line; `method = "auto"` takes the finite elements there.

use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
use boltzone::hankel::receding::MAX_B_OVER_D;
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
    // auto falls back to the finite elements there, and keeps the route within its reach
    let wide = Scene::parse(&scene("auto", 1e-6, 1.7)).unwrap();
    assert!(!two_hankel::auto_takes(&wide));
    let inside = Scene::parse(&scene("auto", 1e-6, 1.6)).unwrap();
    assert!(two_hankel::auto_takes(&inside));
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
