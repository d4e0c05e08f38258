//! `--units` on `two` and `single`: the joint A = D = 0.1 in, B = 0.31 in written in
//! in-psi-lbf, mm-MPa-N and m-Pa-N (converted here from the definitions 1 in = 25.4 mm,
//! 1 lbf = 4.4482216152605 N, 1 psi = 1 lbf/in²) gives the same R_o to 1e-12 relative
//! (`single` by FE and by Hankel transforms, `two --method hankel`), and the JSON's `units`,
//! the text and the CSV header name the unit.
//!
//! `two --method fem` needs the solver's entry scaling to divide (lengths by the thinner plate,
//! stresses by the largest pressure and modulus): each scaled number is then its ratio correctly
//! rounded, the same bits in all three systems for this joint, and R_o agrees to the last digit.
//! Multiplying by a reciprocal instead (as before) spread the three by 1.4e-9, because the
//! FE R_o has a round-off floor: one ulp of B = 0.31 in moves it by 7.6e-11 and 2.7e-10 relative
//! (measured either way), already on the first, coarsest level. A joint whose ratios differ by an
//! ulp between systems (C/D = 1.54/0.1 in inches and 0.039116/0.00254 in metres) keeps that
//! floor: 2.4e-11 measured for the frictionless pair with C given.

use crate::scratch;
use std::process::{Command, Output};

/// (name, metres per length unit, newtons per force unit).
const SYSTEMS: [(&str, f64, f64); 3] = [
    ("in-psi-lbf", 0.0254, 4.4482216152605),
    ("mm-MPa-N", 1e-3, 1.0),
    ("m-Pa-N", 1.0, 1.0),
];

/// Pascals per stress unit of a system with `m` metres per length and `n` newtons per force.
fn pascals(m: f64, n: f64) -> f64 {
    n / (m * m)
}

/// `boltzone CMD` on the joint in the system `(units, m, _)` with `extra` flags.
fn run(
    cmd: &str,
    (units, m, _): (&str, f64, f64),
    extra: &[String],
    dir: &std::path::Path,
) -> Output {
    let l = |x: f64| format!("{:e}", x * 0.0254 / m);
    let mut args = vec![cmd.to_string(), "--units".into(), units.into()];
    for (flag, v) in [("--a", 0.1), ("--b", 0.31), ("--d", 0.1)] {
        args.extend([flag.to_string(), l(v)]);
    }
    args.extend(extra.iter().cloned());
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(&args)
        .current_dir(dir)
        .output()
        .unwrap()
}

/// R_o in metres from each system's JSON, checked to agree to `rel` relative; returns the
/// JSON objects.
fn same_r_o(
    cmd: &str,
    rel: f64,
    extra: impl Fn((&str, f64, f64)) -> Vec<String>,
) -> Vec<serde_json::Value> {
    let dir = scratch(&format!("joint_units_{cmd}"));
    let mut out = Vec::new();
    for s in SYSTEMS {
        let mut flags = extra(s);
        flags.push("--json".into());
        let v = crate::common::json_of(&run(cmd, s, &flags, &dir));
        assert_eq!(v["units"], s.0);
        assert_eq!(v["inputs"]["units"], s.0);
        out.push(v);
    }
    let r: Vec<f64> = out
        .iter()
        .zip(SYSTEMS)
        .map(|(v, s)| v["r_o"].as_f64().unwrap() * s.1)
        .collect();
    for x in &r[1..] {
        assert!((x / r[0] - 1.0).abs() < rel, "{cmd}: R_o {r:?} m");
    }
    out
}

#[test]
fn two_with_force_and_modulus_gives_the_same_joint_in_three_systems() {
    // 1000 lbf on aluminium (E = 10e6 psi), converted by the definitions
    let v = same_r_o("two", 1e-12, |(_, m, n)| {
        vec![
            "--force".into(),
            format!("{:e}", 1000.0 * 4.4482216152605 / n),
            "--e".into(),
            format!(
                "{:e}",
                10e6 * pascals(0.0254, 4.4482216152605) / pascals(m, n)
            ),
            "--tol".into(),
            "2e-3".into(),
        ]
    });
    // P = F / (π(B² − A²)) in psi, and the same pressure in each system's stress unit
    let p_psi = 1000.0 / (std::f64::consts::PI * (0.31f64.powi(2) - 0.1f64.powi(2)));
    for (v, (_, m, n)) in v.iter().zip(SYSTEMS) {
        let p = v["bearing_pressure"].as_f64().unwrap() * pascals(m, n);
        let want = p_psi * pascals(0.0254, 4.4482216152605);
        assert!((p / want - 1.0).abs() < 1e-12, "P = {p} Pa, want {want} Pa");
    }
}

#[test]
fn two_default_modulus_is_28e6_psi_in_every_system() {
    let v = same_r_o("two", 1e-12, |_| vec!["--tol".into(), "2e-3".into()]);
    for (v, (_, m, n)) in v.iter().zip(SYSTEMS) {
        let e = v["inputs"]["e"].as_f64().unwrap() * pascals(m, n);
        let want = 28e6 * 6894.757293168361;
        assert!((e / want - 1.0).abs() < 1e-14, "E = {e} Pa, want {want} Pa");
    }
    assert_eq!(v[0]["inputs"]["e"].as_f64(), Some(28e6));
}

#[test]
#[ignore = "the Hankel two-plate route: 39-137 s measured for the three systems"]
fn two_hankel_gives_the_same_r_o_in_three_systems() {
    same_r_o("two", 1e-12, |_| {
        ["--method", "hankel", "--tol", "1e-6"]
            .map(String::from)
            .to_vec()
    });
}

#[test]
fn single_gives_the_same_r_o_in_three_systems_by_both_methods() {
    same_r_o("single", 1e-12, |_| Vec::new());
    same_r_o("single", 1e-12, |_| {
        ["--method", "hankel"].map(String::from).to_vec()
    });
}

#[test]
fn curves_and_text_name_the_units() {
    let dir = scratch("joint_units_files");
    let mm = SYSTEMS[1];
    let curve = |f: &str| ["--curve".to_string(), f.to_string()].to_vec();
    let two = run(
        "two",
        mm,
        &[curve("t.csv"), vec!["--tol".into(), "2e-3".into()]].concat(),
        &dir,
    );
    assert_eq!(two.status.code(), Some(0));
    let text = String::from_utf8_lossy(&two.stdout);
    assert!(
        text.contains(" mm   (")
            && text
                .lines()
                .any(|l| l.contains("nut: ") && l.ends_with(" mm"))
            && text
                .lines()
                .any(|l| l.starts_with("rules: ") && l.contains(" mm (")),
        "{text}"
    );
    let csv = std::fs::read_to_string(dir.join("t.csv")).unwrap();
    assert!(
        csv.starts_with("r [mm],p [MPa],g [mm],tau [MPa]\n"),
        "{csv}"
    );
    assert!(csv.contains("# units: mm-MPa-N (lengths mm, stresses MPa, forces N)"));
    assert!(
        !csv.contains("[in]") && !csv.contains(" in +-") && !csv.contains("psi"),
        "{csv}"
    );
    for method in ["fem", "hankel"] {
        let f = format!("s_{method}.csv");
        let single = run(
            "single",
            mm,
            &[curve(&f), vec!["--method".into(), method.into()]].concat(),
            &dir,
        );
        assert_eq!(single.status.code(), Some(0), "{single:?}");
        let text = String::from_utf8_lossy(&single.stdout);
        assert!(
            text.contains("A = 2.54 mm") && text.contains(" mm\n"),
            "{text}"
        );
        let csv = std::fs::read_to_string(dir.join(&f)).unwrap();
        assert!(csv.starts_with("r [mm],sigma_z [MPa]\n"), "{csv}");
        assert!(
            !csv.contains("[in]") && !csv.contains(" in +-") && !csv.contains("psi"),
            "{csv}"
        );
    }
    // friction: the slip column and the zones in the text
    let friction = [
        "--d2",
        "5.08",
        "--e2",
        "70000",
        "--interface",
        "friction",
        "--mu",
        "0.3",
    ];
    let flags = [friction.map(String::from).to_vec(), curve("f.csv")].concat();
    let out = run(
        "two",
        mm,
        &[flags, vec!["--tol".into(), "5e-3".into()]].concat(),
        &dir,
    );
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains(" mm; slip r = ") && text.contains("largest slip "),
        "{text}"
    );
    let csv = std::fs::read_to_string(dir.join("f.csv")).unwrap();
    assert!(
        csv.starts_with("r [mm],p [MPa],g [mm],tau [MPa],s [mm],state [-]\n"),
        "{csv}"
    );
    // the VTU says its units
    for (cmd, tol) in [("two", "2e-3"), ("single", "5e-4")] {
        let flags = ["--field", "f.vtu", "--tol", tol].map(String::from);
        assert_eq!(run(cmd, mm, &flags, &dir).status.code(), Some(0));
        let vtu = std::fs::read_to_string(dir.join("f.vtu")).unwrap();
        assert!(vtu.contains("units mm-MPa-N: coordinates and displacements [mm], stresses [MPa]"));
        assert!(!vtu.contains("[in]") && !vtu.contains(" in +-") && !vtu.contains("psi"));
    }
    // the figures' axes and markers
    for cmd in ["two", "single"] {
        let flags = ["--plot", "f.svg", "--tol", "2e-3"].map(String::from);
        assert_eq!(run(cmd, mm, &flags, &dir).status.code(), Some(0));
        for file in ["f.svg", "f-deformed.svg"] {
            let svg = std::fs::read_to_string(dir.join(file)).unwrap();
            assert!(
                svg.contains("r [mm]") && svg.contains(" mm (computed)"),
                "{cmd} {file}"
            );
            assert!(!svg.contains("[in]") && !svg.contains(" in ") && !svg.contains("psi"));
        }
    }
    // the report: its units line, the inputs' and results' units
    let flags = ["--report", "x.md", "--tol", "2e-3", "--force", "1000"].map(String::from);
    assert_eq!(run("two", mm, &flags, &dir).status.code(), Some(0));
    let md = std::fs::read_to_string(dir.join("x.md")).unwrap();
    assert!(
        md.contains("units mm-MPa-N (lengths mm, stresses MPa, forces N)"),
        "{md}"
    );
    assert!(
        md.contains("| force | 1000 | N |") || md.contains("| force | 1000.0 | N |"),
        "{md}"
    );
    assert!(
        md.contains("R [mm]") && md.contains(" MPa |") && md.contains(" mm |"),
        "{md}"
    );
    assert!(
        !md.contains("[in]") && !md.contains(" in ") && !md.contains("psi"),
        "{md}"
    );
}
