//! Scenes of two equal plates with a hole by the semi-analytic route (`method = "hankel"`):
//! the scene equals the library call bit for bit (SI scene: no conversion), agrees with the
//! finite elements within both error bars, `auto` takes the route only below a tolerance of
//! 3e-5 (`scene::two_hankel::AUTO_BELOW`), and every key that keeps a scene from the route is named with its line.

use boltzone::hankel::receding::holed::{two_plate_hole_pressure, HoledParams};
use boltzone::scene::{solve, Method, Scene, SceneError};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// Table 1's first geometry (A = D = 0.1, B = 0.31) in metres and pascals, infinite plates.
fn scene(method: &str, tolerance: f64, extra: &str) -> String {
    format!(
        "units = \"m-Pa-N\"\nmodel = \"two-plate\"\nmethod = \"{method}\"\ntolerance = {tolerance:e}\n\
         [hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\npressure = 1e6\n[[plates]]\n\
         thickness = 0.1\nmaterial = {{ E = 2e11, nu = 0.3 }}\n{extra}"
    )
}

#[test]
fn the_scene_is_the_library_call_and_agrees_with_the_finite_elements() {
    let text = scene(
        "hankel",
        1e-6,
        "[outputs]\ninterface_pressure = \"p.csv\"\n",
    );
    let s = solve(&Scene::parse(&text).unwrap()).unwrap();
    assert_eq!(s.method, Method::Hankel);
    let plate = SinglePlate::new(
        0.1,
        OuterRadius::Infinite,
        0.1,
        Material::new(2e11, 0.3).unwrap(),
        FaceLoad::uniform(0.1, 0.31, 1e6).unwrap(),
    )
    .unwrap();
    let (lib, _) = two_plate_hole_pressure(&plate, &HoledParams::for_tolerance(1e-6), &[]).unwrap();
    assert_eq!(s.r_o, lib.r_o, "bit for bit");
    assert_eq!(s.r_o_error, lib.info.r_o_error);
    assert!(
        s.converged && s.r_o_error <= 1e-6 * s.r_o,
        "{} ± {}",
        s.r_o,
        s.r_o_error
    );
    // the interface pressure carries the load: 2π∫q r dr = p π(B² − A²) to the trapezoid's
    // error on the curve's 101 points (q ~ √(R_o − r) at the end: O(h^1.5))
    let c = s.interface.as_ref().expect("interface curve asked");
    let force: f64 = c
        .radius
        .windows(2)
        .zip(c.pressure.windows(2))
        .map(|(r, q)| 0.5 * (q[0] * r[0] + q[1] * r[1]) * (r[1] - r[0]))
        .sum::<f64>()
        * 2.0
        * std::f64::consts::PI;
    let applied = 1e6 * std::f64::consts::PI * (0.31f64.powi(2) - 0.01);
    assert!((force / applied - 1.0).abs() < 1e-3, "{force} vs {applied}");
    assert!(c.gap.iter().all(|&g| g == 0.0) && c.pressure.iter().all(|&q| q >= 0.0));
    // a second method that shares no code: the finite elements on the same scene
    let fem = solve(&Scene::parse(&scene("fem", 1e-4, "")).unwrap()).unwrap();
    assert_eq!(fem.method, Method::Fem);
    assert!(
        (fem.r_o - s.r_o).abs() <= fem.r_o_error + s.r_o_error,
        "FE {} ± {} vs Hankel {} ± {}",
        fem.r_o,
        fem.r_o_error,
        s.r_o,
        s.r_o_error
    );
}

#[test]
fn auto_takes_the_route_only_below_3e_5_where_it_applies() {
    let pick = |text: &str| boltzone::scene::run::pick(&Scene::parse(text).unwrap()).0;
    assert_eq!(pick(&scene("auto", 1e-6, "")), Method::Hankel);
    // at 1e-4 the tables' bar meets it on these plates, infinite or with Table 1's rim (the rim
    // table's shift); with a rim within 4 D of R_o (beyond the tables' rim law) the FE is the
    // cheaper route above 3e-5
    assert_eq!(pick(&scene("auto", 1e-4, "")), Method::Table);
    let rim = "[joint]\nouter_radius = 1.54\n";
    assert_eq!(pick(&scene("auto", 1e-4, rim)), Method::Table);
    let near = "[joint]\nouter_radius = 0.6\n";
    assert_eq!(pick(&scene("auto", 1e-4, near)), Method::Fem);
    // a finite rim beyond B + D takes the route (its rim correction); one within D does not
    let finite = scene("auto", 1e-6, "[joint]\nouter_radius = 1.54\n");
    assert_eq!(pick(&finite), Method::Hankel);
    let close = scene("auto", 1e-6, "[joint]\nouter_radius = 0.35\n");
    assert_eq!(pick(&close), Method::Fem);
}

#[test]
fn keys_that_keep_a_scene_from_the_route_are_named_with_their_line() {
    for (extra, key) in [
        ("[joint]\nouter_radius = 0.35\n", "joint.outer_radius"),
        ("[outputs]\nfield = \"f.vtu\"\n", "outputs.field"),
        (
            "[[plates]]\nthickness = 0.2\nmaterial = { E = 2e11, nu = 0.3 }\n",
            "plates",
        ),
    ] {
        located(&scene("hankel", 1e-4, extra), key);
    }
    // a hole below 0.04 D (without one, hole.radius = 0, the receding contact is the route:
    // tests/scene/two_hankel_no_hole.rs)
    located(
        &scene("hankel", 1e-4, "").replace("radius = 0.1", "radius = 0.003"),
        "hole.radius",
    );
}

/// Asserts that parsing `text` fails naming `key` on the line where the key is written (for
/// a dotted key, its field after its table's header), with a reason that names the method
/// and points to another.
pub fn located(text: &str, key: &str) {
    match Scene::parse(text) {
        Err(SceneError::Invalid {
            key: k,
            line,
            reason,
        }) => {
            assert_eq!(k, key, "{reason}");
            if let Some((table, field)) = key.split_once('.') {
                let lines: Vec<&str> = text.lines().collect();
                let header = lines.iter().position(|l| *l == format!("[{table}]"));
                let want = header
                    .and_then(|h| (h + 1..lines.len()).find(|&i| lines[i].starts_with(field)));
                assert_eq!(Some(line), want.map(|i| i + 1), "{key}: {reason}");
            }
            assert!(
                reason.contains("hankel") && reason.contains("\"fem\""),
                "{reason}"
            );
        }
        other => panic!("{key}: expected a located error, got {other:?}"),
    }
}
