//! `boltzone slab`: the JSON keys, agreement with the library, the CSV curve, named errors.

use std::process::Command;

fn slab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .arg("slab")
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn json_has_the_keys_and_the_library_value() {
    let out = slab(&["--a", "0.1", "--b", "0.31", "--d", "0.1", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let r_o = v["r_o"].as_f64().unwrap();
    assert!((v["r_o_over_a"].as_f64().unwrap() - r_o / 0.1).abs() < 1e-12);
    assert!(v["r_o_error"].as_f64().unwrap() < 1e-10);
    use boltzone::hankel::{SeparationParams, Slab};
    let lib = Slab::new(
        0.1,
        boltzone::Material::unit(0.3).unwrap(),
        boltzone::FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
    )
    .unwrap()
    .separation_radius(&SeparationParams::default())
    .unwrap();
    assert!((r_o - lib.r_o).abs() <= lib.r_o_error);
}

#[test]
fn curve_is_written_with_a_header() {
    let dir = std::env::temp_dir().join(format!("boltzone-slab-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mid.csv");
    let out = slab(&[
        "--a",
        "0.1",
        "--b",
        "0.31",
        "--d",
        "0.1",
        "--curve",
        path.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let text = std::fs::read_to_string(&path).unwrap();
    // the one curve layout (tests/io/csv_out.rs): header with units first, then # lines
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "r [in],sigma_z [psi],sigma_z_error [psi]"
    );
    let rows: Vec<Vec<f64>> = lines
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 1001);
    // under the middle of the load (r = 2A) the midplane is compressed (P = 1 psi)
    assert!(rows
        .iter()
        .any(|r| (r[0] - 0.2).abs() < 0.002 && r[1] < -0.5));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_names_the_field_and_writes_nothing() {
    let path = std::env::temp_dir().join(format!("boltzone-bad-{}.csv", std::process::id()));
    let out = slab(&[
        "--a",
        "0.3",
        "--b",
        "0.1",
        "--d",
        "0.1",
        "--curve",
        path.to_str().unwrap(),
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("B = 0.1"));
    assert!(!path.exists());
    let out = slab(&["--a", "0.1", "--b", "0.3", "--d=-0.1"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("half-thickness D"));
    let out = slab(&["--a", "0.1", "--b", "0.3", "--d", "0.1", "--nu", "0.7"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("nu = 0.7"));
}
