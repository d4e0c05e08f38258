//! `--units` on the commands (so far `slab`): the same slab (A = D = 0.1 in, B = 0.31 in)
//! written in in-psi-lbf, mm-MPa-N and m-Pa-N (converted here by 1 in = 25.4 mm) gives the same
//! R_o to 1e-12 relative (each solved to --tol 1e-12), and every printed number and file names
//! the unit: the JSON's `units`, the text's lengths, the CSV header.

use crate::scratch;
use std::process::Command;

fn slab(units: &str, metres: f64, extra: &[&str], dir: &std::path::Path) -> std::process::Output {
    let l = |x: f64| format!("{:e}", x * 0.0254 / metres);
    let mut args = vec![
        "slab".to_string(),
        "--a".into(),
        l(0.1),
        "--b".into(),
        l(0.31),
        "--d".into(),
        l(0.1),
        "--units".into(),
        units.into(),
        "--tol".into(),
        "1e-12".into(),
    ];
    args.extend(extra.iter().map(|s| s.to_string()));
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(&args)
        .current_dir(dir)
        .output()
        .unwrap()
}

#[test]
fn slab_gives_the_same_r_o_in_three_unit_systems() {
    let dir = scratch("command_units");
    let mut r_o_m = Vec::new();
    for (units, metres) in [("in-psi-lbf", 0.0254), ("mm-MPa-N", 1e-3), ("m-Pa-N", 1.0)] {
        let v = crate::common::json_of(&slab(units, metres, &["--json"], &dir));
        assert_eq!(v["units"], units);
        r_o_m.push(v["r_o"].as_f64().unwrap() * metres);
    }
    for r in &r_o_m[1..] {
        assert!((r / r_o_m[0] - 1.0).abs() < 1e-12, "{r_o_m:?} m");
    }
    let out = slab("mm-MPa-N", 1e-3, &["--curve", "c.csv"], &dir);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("R_o   = ") && text.contains(" mm  ± "),
        "{text}"
    );
    let csv = std::fs::read_to_string(dir.join("c.csv")).unwrap();
    assert!(
        csv.starts_with("r [mm],sigma_z [MPa],sigma_z_error [MPa]\n"),
        "{csv}"
    );
    assert!(csv.contains("# units: mm-MPa-N (lengths mm, stresses MPa, forces N)"));
    let bad = slab("furlongs", 1.0, &[], &dir);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--units"));
}
