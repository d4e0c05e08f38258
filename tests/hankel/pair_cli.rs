//! `boltzone two --method hankel|auto --a 0`: two plates without a hole by the receding contact
//! of the pair (`hankel::receding::Pair`): the library's value bit for bit, the exit codes
//! (0 converged, 2 naming the refused flag, 3 not converged), auto below its tolerance.

use crate::common::{boltzone, json_of};
use boltzone::hankel::receding::{Pair, RecedingParams};
use boltzone::{FaceLoad, Material, Plate};

const UNEQUAL: [&str; 16] = [
    "two", "--a", "0", "--b", "1.2", "--d", "1", "--e", "2e5", "--nu", "0.3", "--d2", "0.6",
    "--e2", "7e4", "--nu2",
];

fn args<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let mut v: Vec<&str> = UNEQUAL.to_vec();
    v.push("0.33");
    v.extend_from_slice(extra);
    v
}

#[test]
fn json_is_the_library_value() {
    let lib = Pair::new(
        Plate::new(1.0, Material::new(2e5, 0.3).unwrap()).unwrap(),
        Plate::new(0.6, Material::new(7e4, 0.33).unwrap()).unwrap(),
        FaceLoad::uniform(0.0, 1.2, 1.0).unwrap(),
    )
    .receding_contact(&RecedingParams::default())
    .unwrap();
    // R_o does not depend on the load's scale: --p is the CLI's default
    for method in ["hankel", "auto"] {
        let v = json_of(&boltzone(&args(&[
            "--method", method, "--tol", "1e-6", "--json",
        ])));
        assert_eq!(v["method"], "hankel");
        assert_eq!(v["converged"], true);
        let r_o = v["r_o"].as_f64().unwrap();
        assert!(
            (r_o - lib.r_o).abs() <= 1e-14 * lib.r_o,
            "{r_o} {}",
            lib.r_o
        );
        assert_eq!(v["r_o_error"].as_f64(), Some(lib.info.r_o_error));
        assert!(v.get("r_o_over_a").is_none());
    }
}

#[test]
fn refusals_name_the_flag_and_exit_2() {
    for (extra, flag) in [
        (&["--interface", "welded"][..], "--interface"),
        (&["--c", "5"], "--c"),
        (&["--b", "60"], "--b"),
    ] {
        let mut a = args(&["--method", "hankel"]);
        match a.iter().position(|&x| x == extra[0]) {
            Some(i) => a[i + 1] = extra[1], // --b: replace the default case's
            None => a.extend_from_slice(extra),
        }
        let out = boltzone(&a);
        assert_eq!(out.status.code(), Some(2), "{a:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(flag) && err.contains("--method fem"), "{err}");
    }
}

#[test]
fn a_tolerance_beyond_reach_exits_3_with_the_result() {
    let out = boltzone(&args(&["--method", "hankel", "--tol", "1e-15", "--json"]));
    assert_eq!(out.status.code(), Some(3));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["converged"], false);
    assert!(v["r_o"].as_f64().unwrap() > 1.2);
}

#[test]
fn the_curve_runs_from_the_axis_to_r_o() {
    let dir = std::env::temp_dir().join(format!("boltzone-pair-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curve.csv");
    let p = path.to_str().unwrap();
    let v = json_of(&boltzone(&args(&[
        "--method", "hankel", "--curve", p, "--json",
    ])));
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('r'))
        .map(|l| l.split(',').map(|x| x.trim().parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 101);
    let r_o = v["r_o"].as_f64().unwrap();
    assert_eq!(rows[0][0], 0.0);
    assert!((rows[100][0] - r_o).abs() <= 1e-14 * r_o);
    // compressive inside, vanishing like √(R_o − r) at the edge
    assert!(rows[..100].iter().all(|r| r[1] > 0.0) && rows[100][1] == 0.0);
    std::fs::remove_dir_all(&dir).unwrap();
}
