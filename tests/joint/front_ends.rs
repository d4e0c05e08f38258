//! The bolted-joint front ends: the M10 8.8 example from its scene and from one `two` line
//! (bit for bit), against the library's own calls and the closed forms by hand, and bad input
//! named by flag and by key.

use super::builders::{own_faces, two_line};
use crate::common::{boltzone, json_of};
use boltzone::bolt::compliance::bolt_resilience;
use boltzone::bolt::thread::Thread;
use boltzone::contact::compliance::{member_compliance, ComplianceParams};
use boltzone::Material;

pub const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes/m10_bolt.toml");

/// The `two` line of the example scene (its header says so).
pub const LINE: &[&str] = &[
    "two",
    "--units",
    "m-Pa-N",
    "--bolt",
    "M10",
    "--grade",
    "8.8",
    "--d",
    "0.01",
    "--c",
    "0.02",
    "--e",
    "205e9",
    "--torque",
    "40",
    "--mu-thread",
    "0.12",
    "--mu-head",
    "0.12",
    "--stiffness",
    "--json",
];

const KEYS: [&str; 9] = [
    "r_o",
    "member_stiffness",
    "member_compliance",
    "rules_member_stiffness",
    "preload",
    "bolt_compliance",
    "clamp_length",
    "load_factor",
    "bearing_pressure",
];

#[test]
fn m10_example_scene_and_two_line_agree_bit_for_bit() {
    let scene = json_of(&boltzone(&["solve", SCENE, "--json"]));
    let two = json_of(&boltzone(LINE));
    for key in KEYS {
        assert!(!scene[key].is_null(), "solve --json lacks {key}");
        assert_eq!(scene[key], two[key], "{key}");
    }
    for rule in ["vdi2230", "shigley", "wileman", "cornwell"] {
        assert!(scene["rules_member_stiffness"][rule].is_object(), "{rule}");
    }
    assert!(
        scene["bearing_pressure"]["head"].is_f64() && scene["bearing_pressure"]["nut"].is_f64()
    );
}

#[test]
fn m10_example_against_the_library_and_the_closed_forms() {
    let v = json_of(&boltzone(&["solve", SCENE, "--json"]));
    // the catalogue's diameters went into the joint: ISO 273 medium 11 mm, ISO 4017 d_w 14.63 mm
    let inputs = &v["inputs"];
    assert_eq!(inputs["hole"]["radius"].as_f64(), Some(0.0055));
    assert!((inputs["load"]["outer_radius"].as_f64().unwrap() - 0.007315).abs() < 1e-15);
    // the preload: VDI 2230 R13/1 solved by hand, M_A/(0.16 P + 0.58 d2 μ_G + D_Km/2 μ_K)
    let (p, d2, dkm) = (1.5e-3, 10e-3 - 0.649519 * 1.5e-3, 0.5 * (14.63e-3 + 11e-3));
    let f_m = 40.0 / (0.16 * p + 0.58 * d2 * 0.12 + 0.5 * dkm * 0.12);
    let preload = v["preload"].as_f64().unwrap();
    assert!((preload / f_m - 1.0).abs() < 1e-12, "{preload} vs {f_m}");
    // k_P: the library's member compliance of the same joint, called directly (a second path
    // through the API, no front end)
    let steel = Material::new(205e9, 0.3).unwrap();
    // the head's face A..d_w/2 (ISO 4017) and the nut's own (ISO 4032 d_w 14.6 mm), the same
    // force on both
    assert_eq!(inputs["load"]["nut_outer_radius"].as_f64(), Some(0.0073));
    let joint = own_faces(0.0055, 0.5 * 14.63e-3, 0.0073, 0.01, Some(0.02), steel);
    let m = member_compliance(&joint, &ComplianceParams::default()).unwrap();
    let k = &v["member_stiffness"];
    let rel = (k["value"].as_f64().unwrap() / m.stiffness.value - 1.0).abs();
    // the scene loads the joint by the preload, the library call by a unit pressure: the
    // linear problem's answers agree to rounding
    assert!(rel < 1e-9, "{k} vs {:?}", m.stiffness);
    assert_eq!(k["converged"], true);
    assert!(k["error"].as_f64().unwrap() <= 5e-4 * k["value"].as_f64().unwrap());
    // δ_S of VDI 2230's sections for l_K = 20 mm, and Φ = δ_P/(δ_S + δ_P) from the JSON's own δ's
    let t = Thread::new(10e-3, 1.5e-3).unwrap();
    let ds = bolt_resilience(&t, 0.02, 0.0, 205e9, 205e9).unwrap();
    assert!((v["bolt_compliance"].as_f64().unwrap() / ds - 1.0).abs() < 1e-12);
    let dp = v["member_compliance"]["value"].as_f64().unwrap();
    let phi = v["load_factor"]["value"].as_f64().unwrap();
    assert!((phi - dp / (ds + dp)).abs() < 1e-12, "{phi}");
    // the bearing pressures: F over the annuli 11..14.63 mm (head) and 11..14.6 mm (ISO 4032)
    let area = |dw: f64| std::f64::consts::FRAC_PI_4 * (dw * dw - 11e-3 * 11e-3);
    let bp = &v["bearing_pressure"];
    assert!((bp["head"].as_f64().unwrap() * area(14.63e-3) / preload - 1.0).abs() < 1e-12);
    assert!((bp["nut"].as_f64().unwrap() * area(14.6e-3) / preload - 1.0).abs() < 1e-12);
    // the figures of the example: VDI's cone is stiffer than the exact k_P
    let vdi = &v["rules_member_stiffness"]["vdi2230"];
    assert!(
        vdi["error_percent"]["value"].as_f64().unwrap() > 10.0,
        "{vdi}"
    );
}

#[test]
fn millimetres_and_metres_give_the_same_joint() {
    let mm = json_of(&boltzone(&two_line(
        "mm-MPa-N",
        ["10", "20", "205e3"],
        &[
            "--bolt",
            "M10",
            "--torque",
            "40e3",
            "--mu-thread",
            "0.12",
            "--mu-head",
            "0.12",
            "--json",
        ],
    )));
    let m = json_of(&boltzone(LINE));
    let close = |a: f64, b: f64, what: &str| {
        assert!((a / b - 1.0).abs() < 1e-9, "{what}: {a} vs {b}");
    };
    let f = |v: &serde_json::Value, k: &str| v[k].as_f64().unwrap();
    close(f(&mm, "preload"), f(&m, "preload"), "preload");
    close(
        mm["member_stiffness"]["value"].as_f64().unwrap(),
        1e-3 * m["member_stiffness"]["value"].as_f64().unwrap(),
        "k_P (N/mm vs N/m)",
    );
    close(
        f(&mm, "bolt_compliance"),
        1e3 * f(&m, "bolt_compliance"),
        "delta_S",
    );
    close(
        mm["bearing_pressure"]["head"].as_f64().unwrap(),
        1e-6 * m["bearing_pressure"]["head"].as_f64().unwrap(),
        "bearing pressure",
    );
}

#[test]
fn text_output_names_the_quantities() {
    let mut line: Vec<&str> = LINE.to_vec();
    line.pop();
    let out = boltzone(&line);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for word in [
        "member stiffness k_P",
        "k_P rules",
        "preload F_M",
        "load factor Phi",
        "bearing pressure: head",
    ] {
        assert!(text.contains(word), "{word}: {text}");
    }
}

#[test]
fn bad_bolt_flags_exit_2_naming_the_flag() {
    let base = ["two", "--units", "mm-MPa-N", "--d", "10"];
    for (extra, flag) in [
        (&["--bolt", "M11"][..], "--bolt"),
        (&["--bolt", "M10", "--grade", "9.9"], "--grade"),
        (&["--bolt", "M10", "--preload", "-5"], "--preload"),
        (
            &["--bolt", "M10", "--torque", "40e3", "--mu-thread", "0.12"],
            "--mu-head",
        ),
        (
            &[
                "--bolt",
                "M10",
                "--torque",
                "40e3",
                "--mu-thread",
                "-1",
                "--mu-head",
                "0.1",
            ],
            "--mu-thread",
        ),
        (
            &[
                "--bolt",
                "M10",
                "--utilisation",
                "1.5",
                "--mu-thread",
                "0.1",
                "--grade",
                "8.8",
            ],
            "--utilisation",
        ),
        (&["--bolt", "M10", "--shank", "30"], "--shank"),
        (
            &["--bolt", "M10", "--load-introduction", "0"],
            "--load-introduction",
        ),
        (
            &["--bolt", "M10", "--limit-material", "cheese"],
            "--limit-material",
        ),
        (&["--bolt", "1/2-13"], "--a"),
        (&["--b", "8"], "--a"),
    ] {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        let out = boltzone(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn bad_bolt_keys_are_named_with_their_line() {
    let scene =
        |body: &str| format!("units = \"mm-MPa-N\"\n{body}\n[[plates]]\nthickness = 10.0\n");
    for (body, key, line) in [
        ("[bolt]\nsize = \"M11\"", "bolt.size", 3),
        ("[bolt]\nsize = \"M10\"\ngrade = \"9.9\"", "bolt.grade", 4),
        ("[bolt]\nsize = \"M10\"\n[preload]\ntorque = 40e3\nmu_thread = 0.1", "preload.mu_head", 4),
        ("[bolt]\nsize = \"M10\"\n[preload]\nforce = 1e4\ntorque = 40e3", "preload.torque", 6),
        ("[bolt]\nsize = \"M10\"\n[preload]\nforce = 1e4\n[load]\nforce = 2e4", "preload", 4),
        ("[washer]\nstandard = \"ISO 7089\"\n[hole]\nradius = 5.0", "washer", 2),
        ("[bolt]\nsize = \"M10\"\n[washer]\nstandard = \"DIN 125\"", "washer.standard", 5),
        ("[load]\nouter_radius = 8.0\nforce = 1.0", "hole.radius", 1),
        ("model = \"slab\"\n[hole]\nradius = 5.0\n[load]\nouter_radius = 8.0\nforce = 1.0\n[outputs]\nstiffness = true", "outputs.stiffness", 9),
    ] {
        let e = boltzone::scene::Scene::parse(&scene(body)).unwrap_err();
        let shown = e.to_string();
        assert!(shown.contains(&format!("`{key}`")), "{body}: {shown}");
        assert!(shown.contains(&format!("line {line}")), "{body}: {shown}");
    }
}
