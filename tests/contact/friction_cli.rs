//! `boltzone two --interface friction --mu M` end to end: the JSON zones against the curve's
//! node states, the curve's friction columns against Coulomb's law, and exit 2 for bad flags.

use std::process::Command;

fn boltzone(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .expect("run boltzone")
}

/// Table 2 case 5's pair with the lower plate in aluminium.
const PAIR: [&str; 14] = [
    "two", "--a", "0.1285", "--b", "0.211", "--d", "0.124", "--d2", "0.257", "--c", "2", "--e2",
    "10e6", "--force",
];

#[test]
fn zones_curve_and_json_agree() {
    let dir = std::env::temp_dir().join(format!("boltzone-friction-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let curve = dir.join("pair.csv");
    let mut args = PAIR.to_vec();
    args.extend([
        "1100",
        "--interface",
        "friction",
        "--mu",
        "0.3",
        "--tol",
        "5e-3",
        "--json",
        "--curve",
        curve.to_str().unwrap(),
    ]);
    let out = boltzone(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["interface"], "friction");
    assert_eq!(v["mu"], 0.3);
    let text = std::fs::read_to_string(&curve).unwrap();
    let header = text.lines().next().unwrap();
    assert_eq!(header, "r [in],p [psi],g [in],tau [psi],s [in],state [-]");
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let pmax = rows.iter().fold(0.0f64, |m, r| m.max(r[1]));
    for r in &rows {
        let (p, t, s, st) = (r[1], r[3], r[4], r[5]);
        match st as u8 {
            0 => assert_eq!(p, 0.0, "open node at r = {}", r[0]),
            1 => assert!(
                t.abs() <= 0.3 * p + 1e-9 * pmax,
                "stick beyond the cone at {}",
                r[0]
            ),
            2 => {
                assert!(
                    (t.abs() - 0.3 * p).abs() <= 1e-9 * pmax,
                    "slip off the cone at {}",
                    r[0]
                );
                assert!(t * s <= 0.0, "τ does not oppose the slip at r = {}", r[0]);
            }
            x => panic!("state {x}"),
        }
    }
    // every node of a JSON zone has that state in the curve, and every such node is in a zone
    for (key, code) in [("stick_zones", 1.0), ("slip_zones", 2.0)] {
        let zones: Vec<(f64, f64)> = v[key]
            .as_array()
            .unwrap()
            .iter()
            .map(|z| (z[0].as_f64().unwrap(), z[1].as_f64().unwrap()))
            .collect();
        assert!(!zones.is_empty(), "{key} empty");
        for r in &rows {
            let inside = zones.iter().any(|&(a, b)| r[0] >= a && r[0] <= b);
            assert_eq!(inside, r[5] == code, "{key} at r = {}", r[0]);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_friction_flags_exit_2_naming_them() {
    let cases: [(&[&str], &[&str]); 4] = [
        (&["--mu", "0.3"], &["--mu", "--interface friction"]),
        (&["--interface", "friction"], &["--interface", "--mu"]),
        (
            &["--interface", "friction", "--mu", "-0.1"],
            &["--mu", "-0.1"],
        ),
        (
            &["--interface", "friction", "--mu", "inf"],
            &["--mu", "inf"],
        ),
    ];
    for (extra, names) in cases {
        let mut args = PAIR.to_vec();
        args.push("1100");
        args.extend(extra);
        let out = boltzone(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        for n in names {
            assert!(err.contains(n), "{extra:?}: {err} does not name {n}");
        }
    }
}

/// Table 2 case 5 as a scene with the `[joint]` lines `joint`.
fn scene(joint: &str) -> String {
    format!(
        "units = \"in-psi-lbf\"\nmodel = \"two-plate\"\ntolerance = 5e-3\n[hole]\nradius = 0.1285\n\
         [load]\nouter_radius = 0.211\npressure = 1.0\n[[plates]]\nthickness = 0.124\n\
         material = \"steel-304\"\n[[plates]]\nthickness = 0.257\n[joint]\nouter_radius = 2.0\n{joint}"
    )
}

#[test]
fn scene_friction_keys_reach_the_model() {
    use boltzone::contact::two_plate::{solve, InterfaceModel, TwoPlateParams};
    let text = scene("interface = \"friction\"\nmu = 0.3\n");
    let s = boltzone::solve(&boltzone::scene::Scene::parse(&text).unwrap()).unwrap();
    // the library call the scene wraps: Table 2 case 5 in the scene's own units (inches and
    // psi; the library's steel-304 divided by the psi once); equal bit for bit
    use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
    let psi = boltzone::scene::UnitSystem::InPsiLbf.stress();
    let m = boltzone::scene::materials::lookup("steel-304").unwrap();
    let steel = Material::new(m.youngs_modulus / psi, m.poisson_ratio).unwrap();
    let joint = Joint::new(
        0.1285,
        OuterRadius::Finite(2.0),
        Plate::new(0.124, steel).unwrap(),
        Plate::new(0.257, steel).unwrap(),
        FaceLoad::uniform(0.1285, 0.211, 1.0).unwrap(),
    )
    .unwrap();
    let params = TwoPlateParams {
        interface: InterfaceModel::Friction { mu: 0.3 },
        tolerance: 5e-3,
        ..Default::default()
    };
    let direct = solve(&joint, &params).unwrap();
    assert_eq!(
        s.r_o.to_bits(),
        direct.r_o.to_bits(),
        "{} vs {}",
        s.r_o,
        direct.r_o
    );
    for (joint, key) in [
        ("interface = \"friction\"\n", "joint.interface"),
        ("interface = \"friction\"\nmu = -1.0\n", "joint.mu"),
        ("interface = \"welded\"\nmu = 0.3\n", "joint.mu"),
    ] {
        let e = boltzone::scene::Scene::parse(&scene(joint)).unwrap_err();
        assert!(e.to_string().contains(key), "{joint}: {e}");
    }
}

/// Runs the aluminium pair with friction and `extra` flags; returns the JSON and the curve's rows.
fn friction_curve(extra: &[&str]) -> (serde_json::Value, Vec<Vec<f64>>) {
    let curve = std::env::temp_dir().join(format!("boltzone-fr-edge-{}.csv", std::process::id()));
    let mut args = PAIR.to_vec();
    args.extend(["1100", "--interface", "friction", "--json", "--curve"]);
    args.push(curve.to_str().unwrap());
    args.extend(extra);
    let out = boltzone(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&curve).unwrap();
    std::fs::remove_file(&curve).ok();
    let rows = text
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (serde_json::from_slice(&out.stdout).unwrap(), rows)
}

/// Steel on aluminium with friction: the pressure ends like √(R_o − r) (a smooth receding
/// contact edge, Johnson, *Contact Mechanics*, §5.8), with no spike, and |τ| = μp where slipping.
/// The welded model of the same pair spiked at R_o (issue 17 item 11).
#[test]
fn dissimilar_plates_end_in_a_square_root_edge_without_spikes() {
    let (v, rows) = friction_curve(&["--mu", "0.3"]);
    let r_o = v["r_o"].as_f64().unwrap();
    let p_max = rows.iter().map(|r| r[1]).fold(0.0, f64::max);
    // the last nodes in contact within 0.01 in of R_o (about 2.5 D/100): p/√(R_o − r) constant
    let edge: Vec<f64> = rows
        .iter()
        .filter(|r| r[0] < r_o && r_o - r[0] < 0.01 && r[1] > 0.0)
        .map(|r| r[1] / (r_o - r[0]).sqrt())
        .collect();
    assert!(edge.len() >= 4, "{} nodes near the edge", edge.len());
    let (lo, hi) = edge
        .iter()
        .fold((f64::MAX, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    assert!(hi / lo < 1.15, "p/√(R_o − r) from {lo:.4e} to {hi:.4e}");
    for r in &rows {
        // no spike: nothing near the edge above the pressure at the hole side of the zone
        if r_o - r[0] < 0.05 * r_o {
            assert!(
                r[1] < 0.2 * p_max,
                "r = {}: p = {} of max {p_max}",
                r[0],
                r[1]
            );
        }
        if r[5] == 2.0 {
            assert!(
                (r[3].abs() - 0.3 * r[1]).abs() <= 1e-9 * p_max,
                "slip at r = {}",
                r[0]
            );
        }
    }
}
