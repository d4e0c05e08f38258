//! Malformed scenes: exit 2 with the key, the value and the line; unknown keys are errors;
//! nothing is written when the scene is invalid; exit 3 when not converged.

use crate::scratch;
use boltzone::scene::{Scene, SceneError};
use std::process::Command;

const GOOD: &str = "units = \"in-psi-lbf\"\nmodel = \"slab\"\n[hole]\nradius = 0.1\n\
[load]\nouter_radius = 0.31\npressure = 1.0\n[[plates]]\nthickness = 0.1\n";

/// The (key, line) of the error of `text`.
fn located(text: &str) -> (String, usize, String) {
    match Scene::parse(text) {
        Err(e @ SceneError::Invalid { .. }) => {
            let msg = e.to_string();
            let SceneError::Invalid { key, line, .. } = e else {
                unreachable!()
            };
            (key, line, msg)
        }
        other => panic!("expected a located error, got {other:?}"),
    }
}

#[test]
fn typo_in_a_key_is_named_with_its_line() {
    let (key, line, msg) = located(&GOOD.replace("thickness", "thicknes"));
    assert_eq!(key, "plates[0].thicknes", "{msg}");
    assert_eq!(line, 9, "{msg}");
    assert!(msg.contains("expected `thickness`"), "{msg}");
}

#[test]
fn negative_thickness_names_key_value_line() {
    let (key, line, msg) = located(&GOOD.replace("thickness = 0.1", "thickness = -0.1"));
    assert_eq!((key.as_str(), line), ("plates[0].thickness", 9), "{msg}");
    assert!(msg.contains("-0.1"), "{msg}");
}

#[test]
fn wrong_type_and_unknown_units_are_located() {
    let (key, line, msg) = located(&GOOD.replace("radius = 0.1", "radius = \"wide\""));
    assert_eq!((key.as_str(), line), ("hole.radius", 4), "{msg}");
    assert!(msg.contains("wide"), "{msg}");
    let (key, line, msg) = located(&GOOD.replace("in-psi-lbf", "furlongs"));
    assert_eq!((key.as_str(), line), ("units", 1), "{msg}");
    assert!(msg.contains("furlongs"), "{msg}");
}

#[test]
fn syntax_error_names_the_key_of_its_line() {
    let (key, line, msg) = located(&GOOD.replace("pressure = 1.0", "pressure = 1.0.0"));
    assert_eq!((key.as_str(), line), ("load.pressure", 7), "{msg}");
}

#[test]
fn two_loads_and_unknown_material_are_rejected() {
    let (key, line, _) = located(&GOOD.replace("pressure = 1.0", "pressure = 1.0\nforce = 3.0"));
    assert_eq!((key.as_str(), line), ("load.force", 8));
    let text = GOOD.replace(
        "thickness = 0.1",
        "thickness = 0.1\nmaterial = \"unobtainium\"",
    );
    let (key, line, msg) = located(&text);
    assert_eq!((key.as_str(), line), ("plates[0].material", 10), "{msg}");
    assert!(
        msg.contains("steel-304"),
        "the message lists the library: {msg}"
    );
}

#[test]
fn invalid_scene_exits_2_and_writes_nothing() {
    let dir = scratch("invalid");
    let text = GOOD.replace("model = \"slab\"", "model = \"two-plate\"\ntolerance = -1")
        + "[outputs]\ninterface_pressure = \"p.csv\"\n";
    std::fs::write(dir.join("s.toml"), text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", "s.toml"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("line 3") && err.contains("tolerance") && err.contains("-1"),
        "{err}"
    );
    assert!(!dir.join("p.csv").exists());
    let out = crate::common::boltzone(&["solve", "/nonexistent/scene.toml"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn not_converged_exits_3_with_the_result_printed() {
    let dir = scratch("tight");
    std::fs::write(dir.join("s.toml"), format!("tolerance = 1e-15\n{GOOD}")).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", "s.toml", "--json"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(3));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["converged"], false);
    assert!(v["r_o"].as_f64().unwrap() > 0.31);
}

#[test]
fn sweep_prints_results_and_csv() {
    let dir = scratch("sweep");
    let text = format!(
        "{GOOD}[outputs]\nresults = \"r.csv\"\n[sweep]\n\"load.outer_radius\" = [0.25, 0.31]\n\
         \"plates[0].thickness\" = [0.1, 0.2]\n"
    );
    std::fs::write(dir.join("s.toml"), text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", "s.toml", "--json"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let v = crate::common::json_of(&out);
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), 4);
    // the slab's R_o scales with the geometry: B = 0.31, D = 0.1 (point 2) against B = 0.25,
    // D = 0.1 (point 0) differ; each point says its swept values
    assert_eq!(results[2]["sweep"]["load.outer_radius"], 0.31);
    assert_eq!(results[2]["inputs"]["load"]["outer_radius"], 0.31);
    assert_eq!(results[1]["inputs"]["plates"][0]["thickness"], 0.2);
    let csv = std::fs::read_to_string(dir.join("r.csv")).unwrap();
    assert!(
        csv.starts_with("load.outer_radius,plates[0].thickness,r_o_in,r_o_error_in,converged\n")
    );
    assert_eq!(csv.lines().filter(|l| !l.starts_with('#')).count(), 5);
}

#[test]
fn bad_sweep_value_is_located_at_the_sweep_key() {
    let text = format!("{GOOD}[sweep]\n\"load.outer_radius\" = [0.25, -1.0]\n");
    let e = boltzone::scene::sweep::points(&text).unwrap_err();
    let msg = e.to_string();
    assert_eq!(e.line(), Some(11), "{msg}");
    assert!(
        msg.contains("load.outer_radius") && msg.contains("-1"),
        "{msg}"
    );
}

#[test]
fn explain_prints_the_plan_with_the_skipped_route() {
    let dir = scratch("explain");
    let text = GOOD.replace("model = \"slab\"", "model = \"single-plate\"");
    std::fs::write(dir.join("s.toml"), text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", "s.toml", "--explain"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    // infinite plates inside the near table: auto answers from it and skips both solvers
    assert!(text.contains("(single-plate, table)"), "{text}");
    assert!(
        text.contains("ran     table route") && text.contains("skipped FE and Hankel routes"),
        "{text}"
    );
    assert!(text.contains(" in "), "R_o says its unit: {text}");
}

#[test]
fn a_sweep_writes_every_points_curve_to_one_file() {
    // the contract scene (mm-MPa-N, welded unequal plates) without its VTU field
    let dir = scratch("contract");
    let text = "units = \"mm-MPa-N\"\nmodel = \"two-plate\"\nmethod = \"auto\"\ntolerance = 1e-4\n\
        [hole]\nradius = 3.26\n[load]\nouter_radius = 5.36\nforce = 4893.0\nprofile = \"uniform\"\n\
        [[plates]]\nthickness = 3.15\nmaterial = { E = 193053, nu = 0.3 }\n[[plates]]\nthickness = 6.53\n\
        [joint]\nouter_radius = 50.8\ninterface = \"welded\"\n[outputs]\nr_o = true\n\
        interface_pressure = \"p.csv\"\n[sweep]\n\"load.outer_radius\" = [5.0, 6.0]\n";
    std::fs::write(dir.join("s.toml"), text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", "s.toml", "--json"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let v = crate::common::json_of(&out);
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    let csv = std::fs::read_to_string(dir.join("p.csv")).unwrap();
    assert!(
        csv.starts_with("load.outer_radius,r [mm],p [MPa],g [mm],tau [MPa]\n#"),
        "{csv}"
    );
    for (b, r) in [5.0, 6.0].iter().zip(results) {
        // each point's rows start at the hole, A = 3.26 mm, and its R_o is in the file
        let first = csv
            .lines()
            .find(|l| l.starts_with(&format!("{b:?},")))
            .unwrap();
        let r0: f64 = first.split(',').nth(1).unwrap().parse().unwrap();
        assert!((r0 - 3.26).abs() < 1e-9, "{first}");
        assert!(csv.contains(&format!("R_o = {}", r["r_o"].as_f64().unwrap())));
    }
}

#[test]
fn geometries_csv_gives_one_point_per_row_and_locates_bad_cells() {
    let dir = scratch("geometries");
    std::fs::write(dir.join("s.toml"), GOOD).unwrap();
    let csv = "load.outer_radius,plates[0].thickness\n# lengths in inches\n0.25,0.1\n0.31,0.2\n";
    std::fs::write(dir.join("g.csv"), csv).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", "s.toml", "--geometries", "g.csv", "--json"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let v = crate::common::json_of(&out);
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    assert_eq!(results[1]["inputs"]["plates"][0]["thickness"], 0.2);
    assert_eq!(results[1]["inputs"]["load"]["outer_radius"], 0.31);
    // the same point written in the scene itself gives the same R_o, bit for bit
    let direct = GOOD.replace("thickness = 0.1", "thickness = 0.2"); // B = 0.31 already
    let s = boltzone::solve(&Scene::parse(&direct).unwrap()).unwrap();
    assert_eq!(
        results[1]["r_o"].as_f64().unwrap().to_bits(),
        s.r_o.to_bits()
    );
    let e = boltzone::scene::sweep::rows(GOOD, "load.outer_radius\n0.25\nwide\n").unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.starts_with("geometries CSV line 3, column `load.outer_radius`"),
        "{msg}"
    );
    assert!(msg.contains("wide"), "{msg}");
    let e =
        boltzone::scene::sweep::rows(GOOD, "load.outer_radius,hole.radius\n0.25\n").unwrap_err();
    assert_eq!(e.line(), Some(2), "{e}");
}

#[test]
fn a_single_plate_beyond_the_hankel_reach_is_refused_by_name_and_auto_takes_a_table_or_the_fe() {
    // B/D = 4000 > route::reach::B_OVER_D_SINGLE_HANKEL (the ξ-quadrature's node budget)
    let wide = GOOD
        .replace("model = \"slab\"", "model = \"single-plate\"")
        .replace("outer_radius = 0.31", "outer_radius = 400.0");
    let (key, line, msg) = located(&format!("method = \"hankel\"\n{wide}"));
    assert_eq!((key.as_str(), line), ("plates[0].thickness", 10), "{msg}");
    assert!(msg.contains("Hankel route's reach"), "{msg}");
    // infinite, or with a rim far beyond R_o (its bound joins the bar), the far table answers
    // it; with a rim 1.6 D beyond R_o only the FE can
    use boltzone::route::Method::{Fem, Table};
    for (rim, expected) in [("", Table), ("[joint]\nouter_radius = 500.0\n", Table)] {
        let (method, why) =
            boltzone::scene::run::pick(&Scene::parse(&format!("{wide}{rim}")).unwrap());
        assert_eq!(method, expected, "{rim}: {why}");
    }
    let near = format!("{wide}[joint]\nouter_radius = 400.25\n");
    let (method, why) = boltzone::scene::run::pick(&Scene::parse(&near).unwrap());
    assert_eq!(method, Fem, "{why}");
}
