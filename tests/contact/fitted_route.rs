//! The route layer's fitted contact edge (`route::two_plate::Question::fitted_edge`): asked
//! below `AUTO_BELOW` for the joints whose bars were measured, and through every front end the
//! same study. Checked against the semi-analytic routes (a second method): Table 1's first row
//! with the report's rim at `--tol 1e-6`, where the default study's 2e-5 floor stopped it.

use boltzone::contact::two_plate::{InterfaceModel, Loading};
use boltzone::route::two_plate::{Question, AUTO_BELOW, FITTED_MAX_LEVELS};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::process::Command;

fn boltzone(args: &[&str]) -> (Option<i32>, serde_json::Value) {
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .expect("run boltzone");
    let v = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{e}: {}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code(), v)
}

fn steel() -> Material {
    Material::new(28e6, 0.3).unwrap()
}

#[test]
fn the_fitted_edge_is_asked_below_auto_below_for_the_measured_joints_only() {
    let equal = Joint::symmetric(0.1, 0.31, 0.1, steel())
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(1.54))
        .unwrap();
    let q = Question::new(&equal, 1e-6);
    assert!(q.fitted_edge());
    let p = q.fem_params();
    assert!(p.fitted_edge);
    assert_eq!(p.max_levels, FITTED_MAX_LEVELS);
    // at and above AUTO_BELOW the default study, with the default levels
    for tol in [AUTO_BELOW, 5e-4] {
        let p = Question::new(&equal, tol).fem_params();
        assert!(!p.fitted_edge, "{tol}");
        assert_eq!(
            p.max_levels,
            boltzone::contact::two_plate::TwoPlateParams::default().max_levels
        );
    }
    // equal plates: any interface (the symmetric model)
    for interface in [InterfaceModel::Welded, InterfaceModel::Friction { mu: 0.3 }] {
        assert!(Question { interface, ..q }.fitted_edge(), "{interface:?}");
    }
    // what was not measured: a fixed rim, temperatures, a nut displacement
    assert!(!Question {
        fixed_edge: true,
        ..q
    }
    .fitted_edge());
    assert!(!Question { thermal: true, ..q }.fitted_edge());
    let nut = Question {
        loading: Loading::NutDisplacement(1e-4),
        ..q
    };
    assert!(!nut.fitted_edge());
    // a nut face of its own
    let own_nut = equal
        .clone()
        .with_nut_load(
            FaceLoad::uniform(0.1, 0.4, (0.31f64.powi(2) - 0.01) / (0.16 - 0.01)).unwrap(),
        )
        .unwrap();
    assert!(!Question::new(&own_nut, 1e-6).fitted_edge());
    // unequal plates: frictionless only
    let unequal = Joint::new(
        0.1,
        OuterRadius::Infinite,
        Plate::new(0.1, steel()).unwrap(),
        Plate::new(0.2, Material::new(10e6, 0.33).unwrap()).unwrap(),
        FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
    )
    .unwrap();
    let u = Question::new(&unequal, 1e-6);
    assert!(u.fitted_edge());
    for interface in [InterfaceModel::Welded, InterfaceModel::Friction { mu: 0.0 }] {
        assert!(!Question { interface, ..u }.fitted_edge(), "{interface:?}");
    }
}

#[test]
fn table1_row1_at_1e6_by_the_fe_lies_within_both_bars_of_the_holed_route() {
    let joint = [
        "two", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--c", "1.54", "--json",
    ];
    let run = |extra: &[&str]| boltzone(&[&joint[..], extra].concat());
    let (code, fe) = run(&["--method", "fem", "--tol", "1e-6"]);
    let (_, exact) = run(&["--method", "hankel", "--tol", "1e-8"]);
    assert_eq!(code, Some(0), "{fe}");
    assert_eq!(fe["method"], "fem");
    assert_eq!(fe["converged"], true);
    let f = |v: &serde_json::Value, k: &str| v[k].as_f64().unwrap();
    let (r_o, bar) = (f(&fe, "r_o"), f(&fe, "r_o_error"));
    assert!(bar <= 1e-6 * r_o, "bar {bar:e} of {r_o}");
    let actual = (r_o - f(&exact, "r_o")).abs();
    assert!(
        actual <= bar + f(&exact, "r_o_error"),
        "FE {r_o} ± {bar:e} against {} ± {}",
        exact["r_o"],
        exact["r_o_error"]
    );
    // every level record carries its edge-force root
    for level in fe["levels"].as_array().unwrap() {
        assert!(level["r_o_fit_force"].is_number(), "{level}");
    }
}

#[test]
fn the_scene_asks_the_cli_s_study() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("examples/scenes/table1_row1.toml"))
        .unwrap()
        .replace("method = \"auto\"", "method = \"fem\"")
        .replace("tolerance = 5e-4", "tolerance = 1e-5");
    let dir = std::env::temp_dir().join(format!("boltzone-fitted-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("row1.toml");
    std::fs::write(&path, text).unwrap();
    let (code, scene) = boltzone(&["solve", path.to_str().unwrap(), "--json"]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(code, Some(0), "{scene}");
    let (_, cli) = boltzone(&[
        "two", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--c", "1.54", "--e", "28e6", "--p",
        "1000", "--method", "fem", "--tol", "1e-5", "--json",
    ]);
    assert_eq!(scene["r_o"], cli["r_o"]);
    assert_eq!(scene["r_o_error"], cli["r_o_error"]);
    // the fitted study's bar, below the default study's 2e-5 floor
    assert!(cli["r_o_error"].as_f64().unwrap() < 2e-5 * cli["r_o"].as_f64().unwrap());
}
