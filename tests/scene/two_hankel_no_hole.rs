//! Two-plate scenes without a hole (`hole.radius = 0`) by `method = "hankel"`: the scene answers
//! as `boltzone two --method hankel --a 0` does — the receding contact of the two plates
//! (`hankel::receding::Pair`), with a rim C `hankel::receding::rim::rim_contact` — bit for bit
//! against the library call and the command (SI units on both: no conversion), agrees with the
//! finite elements (which share no code with it) within both error bars, `auto` follows the
//! command's rule, and each key that keeps a scene from the route is named with its line.

use super::two_hankel::located;
use crate::common::{boltzone, json_of};
use boltzone::hankel::receding::rim::rim_contact;
use boltzone::hankel::receding::{Pair, RecedingParams};
use boltzone::scene::{solve, Method, Scene};
use boltzone::{FaceLoad, Material, Plate};
use std::f64::consts::PI;

const E: f64 = 2e11;
const P: f64 = 1e6;

/// Two plates D = 0.1 m (one `[[plates]]` entry: equal) without a hole, loaded over r ≤ 0.1 m.
fn scene(method: &str, tolerance: f64, extra: &str) -> String {
    format!(
        "units = \"m-Pa-N\"\nmodel = \"two-plate\"\nmethod = \"{method}\"\ntolerance = {tolerance:e}\n\
         [hole]\nradius = 0.0\n[load]\nouter_radius = 0.1\npressure = {P:e}\n[[plates]]\n\
         thickness = 0.1\nmaterial = {{ E = {E:e}, nu = 0.3 }}\n{extra}"
    )
}

fn steel(d: f64) -> Plate {
    Plate::new(d, Material::new(E, 0.3).unwrap()).unwrap()
}

fn load() -> FaceLoad {
    FaceLoad::uniform(0.0, 0.1, P).unwrap()
}

/// (R_o, estimate, converged, JSON) of `two --method hankel --a 0 --b 0.1 --d 0.1` in SI.
fn command(extra: &[&str]) -> (f64, f64, bool, serde_json::Value) {
    let mut args = vec![
        "two", "--units", "m-Pa-N", "--method", "hankel", "--a", "0", "--b", "0.1", "--d", "0.1",
        "--e", "2e11", "--nu", "0.3", "--p", "1e6", "--json",
    ];
    args.extend(extra);
    let v = json_of(&boltzone(&args));
    let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k}: {v}"));
    (f("r_o"), f("r_o_error"), v["converged"] == true, v)
}

/// 2π∫q r dr by the trapezoid rule on the curve's points.
fn force(c: &boltzone::scene::run::InterfaceCurve) -> f64 {
    let sum: f64 = c
        .radius
        .windows(2)
        .zip(c.pressure.windows(2))
        .map(|(r, q)| 0.5 * (q[0] * r[0] + q[1] * r[1]) * (r[1] - r[0]))
        .sum();
    2.0 * PI * sum
}

#[test]
fn the_scene_is_the_receding_contact_of_the_command_and_the_library() {
    let curve = "[outputs]\ninterface_pressure = \"p.csv\"\n";
    let s = solve(&Scene::parse(&scene("hankel", 1e-6, curve)).unwrap()).unwrap();
    assert_eq!(s.method, Method::Hankel);
    let lib = Pair::new(steel(0.1), steel(0.1), load())
        .receding_contact(&RecedingParams::default())
        .unwrap();
    assert_eq!(
        (s.r_o, s.r_o_error),
        (lib.r_o, lib.info.r_o_error),
        "bit for bit"
    );
    let (r_o, error, converged, _) = command(&[]);
    assert_eq!((s.r_o, s.r_o_error, s.converged), (r_o, error, converged));
    assert!(s.converged, "{} ± {}", s.r_o, s.r_o_error);
    // the curve is the library's pressure on 0 ≤ r ≤ R_o and carries the load P πB² to the
    // trapezoid's error on 101 points graded toward R_o (q ~ √(R_o − r): O(h^1.5), about 1e-4)
    let c = s.interface.as_ref().expect("curve asked");
    assert_eq!((c.radius[0], *c.radius.last().unwrap()), (0.0, s.r_o));
    for (r, q) in c.radius.iter().zip(&c.pressure) {
        assert_eq!(*q, lib.solution.pressure(*r));
    }
    let applied = P * PI * 0.01;
    assert!((force(c) / applied - 1.0).abs() < 1e-3, "{}", force(c));
}

#[test]
fn unequal_plates_and_a_rim_are_the_commands_routes() {
    // steel 0.1 m on aluminium 0.05 m, frictionless: the pair in series, as --d2 --e2 --nu2
    let lower = "[[plates]]\nthickness = 0.05\nmaterial = { E = 7e10, nu = 0.33 }\n";
    let s = solve(&Scene::parse(&scene("hankel", 1e-6, lower)).unwrap()).unwrap();
    let lower_plate = Plate::new(0.05, Material::new(7e10, 0.33).unwrap()).unwrap();
    let lib = Pair::new(steel(0.1), lower_plate, load())
        .receding_contact(&RecedingParams::default())
        .unwrap();
    assert_eq!((s.r_o, s.r_o_error), (lib.r_o, lib.info.r_o_error));
    let unequal = ["--d2", "0.05", "--e2", "7e10", "--nu2", "0.33"];
    let (r_o, error, _, _) = command(&unequal);
    assert_eq!((s.r_o, s.r_o_error), (r_o, error));
    // equal plates with a free rim C = 0.5 m (C − B = 4D), as --c 0.5
    let s = solve(&Scene::parse(&scene("hankel", 1e-6, "[joint]\nouter_radius = 0.5\n")).unwrap())
        .unwrap();
    let m = Material::new(E, 0.3).unwrap();
    let params = RecedingParams::default();
    let (lib, _) = rim_contact(0.1, m, &load(), 0.5, &params, 1e-6, &[]).unwrap();
    assert_eq!((s.r_o, s.r_o_error), (lib.r_o, lib.info.r_o_error));
    let (r_o, error, converged, v) = command(&["--c", "0.5", "--tol", "1e-6"]);
    assert_eq!((s.r_o, s.r_o_error, s.converged), (r_o, error, converged));
    assert_eq!(v["hankel"]["rim"]["outer_radius"].as_f64(), Some(0.5));
}

#[test]
fn the_no_hole_scene_agrees_with_the_finite_elements() {
    let h = solve(&Scene::parse(&scene("hankel", 1e-6, "")).unwrap()).unwrap();
    // auto at 1e-4 is the FE (above AUTO_BELOW); it shares no code with the receding solver
    let fem = solve(&Scene::parse(&scene("auto", 1e-4, "")).unwrap()).unwrap();
    assert_eq!(fem.method, Method::Fem);
    println!(
        "no hole, B = D: Hankel R_o = {:.9} ± {:.1e} m, FE {:.9} ± {:.1e} m, |FE − Hankel| = {:.2e} m",
        h.r_o,
        h.r_o_error,
        fem.r_o,
        fem.r_o_error,
        (fem.r_o - h.r_o).abs()
    );
    assert!((fem.r_o - h.r_o).abs() <= fem.r_o_error + h.r_o_error);
}

#[test]
fn auto_follows_the_commands_rule() {
    let pick = |text: &str| boltzone::scene::run::pick(&Scene::parse(text).unwrap()).0;
    assert_eq!(pick(&scene("auto", 1e-6, "")), Method::Hankel);
    assert_eq!(pick(&scene("auto", 1e-4, "")), Method::Fem);
    // unequal welded plates, or a fixed edge: not the route's problems, so the FE
    let welded = "[joint]\ninterface = \"welded\"\n[[plates]]\nthickness = 0.05\n";
    assert_eq!(pick(&scene("auto", 1e-6, welded)), Method::Fem);
    let fixed = "[joint]\nouter_radius = 0.5\nfixed_edge = true\n";
    assert_eq!(pick(&scene("auto", 1e-6, fixed)), Method::Fem);
    // equal welded plates carry no shear: the route's problem
    let equal_welded = "[joint]\ninterface = \"welded\"\n";
    assert_eq!(pick(&scene("auto", 1e-6, equal_welded)), Method::Hankel);
}

#[test]
fn keys_that_keep_a_no_hole_scene_from_the_route_are_named_with_their_line() {
    // each scene beside the command with the same joint: the command refuses (exit 2) naming
    // the flag of the key the scene names
    let thin = "[[plates]]\nthickness = 0.05\nmaterial = { E = 2e11, nu = 0.3 }\n";
    let wide = |b: &str, extra: &str| {
        scene("hankel", 1e-4, extra)
            .replace("outer_radius = 0.1\n", &format!("outer_radius = {b}\n"))
    };
    for (text, key, args, flag) in [
        (
            scene(
                "hankel",
                1e-4,
                &format!("[joint]\ninterface = \"welded\"\n{thin}"),
            ),
            "joint.interface",
            &["--b", "0.1", "--interface", "welded", "--d2", "0.05"][..],
            "--interface",
        ),
        (
            scene(
                "hankel",
                1e-4,
                &format!("[joint]\nouter_radius = 0.5\n{thin}"),
            ),
            "joint.outer_radius",
            &["--b", "0.1", "--c", "0.5", "--d2", "0.05"],
            "--c",
        ),
        (
            scene("hankel", 1e-4, "[joint]\nouter_radius = 0.15\n"),
            "joint.outer_radius",
            &["--b", "0.1", "--c", "0.15"],
            "--c",
        ),
        (
            scene(
                "hankel",
                1e-4,
                "[joint]\nouter_radius = 0.5\nfixed_edge = true\n",
            ),
            "joint.fixed_edge",
            &["--b", "0.1", "--c", "0.5", "--fixed-edge"],
            "--fixed-edge",
        ),
        // loads beyond the reach: B = 9D with a rim (at most 8D), B = 70D without (B + 2D
        // within about 64D)
        (
            wide("0.9", "[joint]\nouter_radius = 2.0\n"),
            "load.outer_radius",
            &["--b", "0.9", "--c", "2.0"],
            "--b",
        ),
        (wide("7.0", ""), "load.outer_radius", &["--b", "7.0"], "--b"),
    ] {
        located(&text, key);
        let mut all = vec![
            "two", "--units", "m-Pa-N", "--method", "hankel", "--a", "0", "--d", "0.1",
        ];
        all.extend(args);
        let out = boltzone(&all);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{key}: {stderr}");
        assert!(stderr.contains(flag), "{key}: {stderr}");
    }
    // within the reach without a rim at B = 20D (beyond the rim's 8D): the route takes it
    let fits = Scene::parse(&wide("2.0", "")).unwrap();
    assert!(boltzone::scene::two_hankel::blocker(&fits).is_none());
}
