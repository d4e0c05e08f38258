//! `boltzone single --method fem`: JSON keys, agreement with the library, named errors.

use crate::common;

fn single(args: &[&str]) -> std::process::Output {
    common::boltzone(&[&["single"], args].concat())
}

#[test]
fn json_has_the_slab_keys_and_mesh_size() {
    let out = single(&[
        "--a", "0.1", "--b", "0.31", "--d", "0.1", "--c", "1.54", "--levels", "3", "--tol", "0.05",
        "--json",
    ]);
    let v = common::json_of(&out);
    for key in [
        "r_o",
        "r_o_over_a",
        "r_o_error",
        "nodes",
        "dofs",
        "seconds",
        "levels",
        "full_contact",
    ] {
        assert!(!v[key].is_null(), "missing {key}: {v}");
    }
    let r_o = v["r_o"].as_f64().unwrap();
    assert!((v["r_o_over_a"].as_f64().unwrap() - r_o / 0.1).abs() < 1e-12);
    assert!(v["levels"].as_array().unwrap().len() == 3);
    assert_eq!(v["full_contact"], false); // R_o well inside C
                                          // `levels` is laid out as two's, one object per level with its `r_o`; the single plate's
                                          // answer is its last level's
    let two = common::json_of(&common::boltzone(&[
        "two", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--c", "1.54", "--tol", "0.05",
        "--method", "fem", "--json",
    ]));
    assert!(two["levels"][0]["r_o"].is_f64(), "{two}");
    assert_eq!(v["levels"][2]["r_o"], v["r_o"], "{v}");
}

#[test]
fn bad_input_gives_named_errors() {
    // (`--method hankel` now runs: tests/hankel/hole_cli.rs)
    let out = single(&["--a", "0.1", "--b", "0.05", "--d", "0.1"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("B = 0.05"));
}
