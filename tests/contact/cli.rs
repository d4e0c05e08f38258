//! `boltzone two` end to end: JSON keys, the CSV curve, and typed errors for bad input.

use std::process::Command;

fn boltzone(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .expect("run boltzone")
}

#[test]
fn json_and_curve() {
    let dir = std::env::temp_dir().join(format!("boltzone-two-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let curve = dir.join("pair.csv");
    let out = boltzone(&[
        "two",
        "--a",
        "0.1285",
        "--b",
        "0.211",
        "--d",
        "0.124",
        "--d2",
        "0.257",
        "--c",
        "2",
        "--force",
        "1100",
        "--interface",
        "welded",
        "--tol",
        "5e-3",
        "--json",
        "--curve",
        curve.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let r_o = v["r_o"].as_f64().unwrap();
    assert!((v["r_o_over_a"].as_f64().unwrap() - r_o / 0.1285).abs() < 1e-12);
    assert!(v["r_o_error"].as_f64().unwrap() < 5e-3 * r_o);
    assert_eq!(v["interface"], "welded");
    assert!(v["nodes"].as_u64().unwrap() > 0 && v["dofs"].as_u64().unwrap() > 0);
    assert!(v["seconds"].as_f64().unwrap() > 0.0);
    // The curve: header, then r, p, g; p > 0 only inside R_o (up to one node), g > 0 beyond.
    let text = std::fs::read_to_string(&curve).unwrap();
    let rows: Vec<[f64; 3]> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('r'))
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [f[0], f[1], f[2]]
        })
        .collect();
    assert!(rows.len() > 10);
    let force: f64 = 1100.0;
    let pmax = force / (std::f64::consts::PI * (0.211f64.powi(2) - 0.1285f64.powi(2)));
    for [r, p, g] in &rows {
        assert!(*p >= 0.0 && *g >= -1e-12, "r = {r}: p = {p}, g = {g}");
        assert!(*p < 10.0 * pmax);
    }
    assert!(rows.iter().any(|x| x[0] > r_o && x[2] > 0.0));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_is_reported_not_panicked() {
    let out = boltzone(&["two", "--a", "0.1", "--b", "0.05", "--d", "0.1"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("B = 0.05"), "{err}");
    let out = boltzone(&[
        "two", "--a", "0.1", "--b", "0.3", "--d", "0.1", "--nu", "0.6",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("0.6"));
}

#[test]
fn a_defective_welded_dissimilar_joint_says_what_to_use_instead() {
    // one of 16 such exit-1 runs of the 10⁴ fuzz (25 Nov 2026): a modulus ratio of 9.3; the
    // model asked has no solution here, so it is bad input naming --interface (exit 2)
    let joint = [
        "two",
        "--a",
        "0",
        "--b",
        "5.364e-3",
        "--d",
        "1.7437e-3",
        "--nu",
        "0.19677",
        "--e",
        "1.34958e8",
        "--e2",
        "1.25494e9",
    ];
    let welded = boltzone(&[&joint[..], &["--interface", "welded"]].concat());
    let text = String::from_utf8_lossy(&welded.stderr);
    assert_eq!(welded.status.code(), Some(2), "{text}");
    assert!(text.contains("--interface = welded"), "{text}");
    assert!(text.contains("not positive definite"), "{text}");
    assert!(text.contains("--interface frictionless"), "{text}");
    // and the frictionless model answers it
    let frictionless = boltzone(&[&joint[..], &["--interface", "frictionless"]].concat());
    assert_eq!(frictionless.status.code(), Some(0));
}
