//! `[heat]` and `[outputs] conductance = true` (issue 11 item 6): a power law of exponent 1
//! against G = c (m/σ) k F/H (equilibrium: Σ nodal forces = F), worked in the report's units
//! here (Btu/(hr·ft·°F), inches, psi, lbf; 12 in = 1 ft) for three load profiles and an unequal
//! pair; the same joint in three unit systems (1 Btu/(hr·°F) = 1055.05585262 J / 3600 s / (5/9 K));
//! the Chapter V scene against the library calls it wraps, bit for bit; located errors.

use crate::{example, scratch};
use boltzone::contact::two_plate::{self, TwoPlateParams};
use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
use boltzone::heat::joint::{joint_conductance, JointParams};
use boltzone::heat::units::{Conductivity, Length, Pressure};
use boltzone::scene::{Scene, SceneError};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::f64::consts::PI;
use std::process::Command;

const IN: f64 = 0.0254;
const PSI: f64 = 4.4482216152605 / (IN * IN);
/// W/K per Btu/(hr·°F), from the IT Btu, the hour and the Fahrenheit degree.
const BTU_HR_F: f64 = 1055.05585262 / 3600.0 / (5.0 / 9.0);

const HEAT: &str = "conductivity = [100.0, 60.0]\nroughness = [50e-6, 30e-6]\n\
                    slope = [0.08, 0.05]\nhardness = 150000.0\n";

fn joint_text(profile: &str, d2: f64) -> String {
    format!(
        "[hole]\nradius = 0.1\n[load]\nouter_radius = 0.16\nforce = 1000.0\nprofile = \"{profile}\"\n\
         [[plates]]\nthickness = 0.1\nmaterial = {{ E = 1.0e7, nu = 0.33 }}\n[[plates]]\n\
         thickness = {d2}\n[joint]\nouter_radius = 1.54\n"
    )
}

fn conductance(text: &str) -> (f64, boltzone::scene::Solution) {
    let s = boltzone::solve(&Scene::parse(text).unwrap()).unwrap();
    (s.joint_conductance.unwrap(), s)
}

#[test]
fn exponent_one_gives_c_m_over_sigma_k_force_over_hardness() {
    // k = 2·100·60/160 = 75 Btu/(hr·ft·°F), σ = √(50² + 30²) µin, m = √(0.08² + 0.05²)
    let (k, sigma_in, m) = (75.0, (50e-6f64).hypot(30e-6), 0.08f64.hypot(0.05));
    let (c, f, h) = (1.3, 1000.0, 150_000.0);
    // Btu/(hr·ft·°F) · (1/in) · in² = Btu/(hr·°F) · in/ft: divide by 12
    let expect = c * m / sigma_in * k * (f / h) / 12.0;
    for (profile, d2) in [
        ("uniform", 0.1),
        ("peak-a", 0.1),
        ("peak-b", 0.1),
        ("uniform", 0.25),
    ] {
        let text = format!(
            "{}[heat]\ncorrelation = {{ coefficient = {c}, exponent = 1.0 }}\n{HEAT}\
             [outputs]\nconductance = true\n",
            joint_text(profile, d2)
        );
        let (g, s) = conductance(&text);
        assert!(
            (g / expect - 1.0).abs() < 1e-9,
            "{profile}, D2 = {d2}: {g} vs {expect} Btu/(hr·°F)"
        );
        assert_eq!(s.conductance_unit, Some("Btu/(hr·°F)"));
    }
}

#[test]
fn same_conductance_in_three_unit_systems() {
    // the joint of exponent_one_… (uniform, equal plates) with eq. (1.1), rewritten in mm-MPa-N
    // and m-Pa-N; conductivity 100 and 60 Btu/(hr·ft·°F) in W/(m·K)
    let k_si = BTU_HR_F / 0.3048;
    let write = |name: &str, len: f64, st: f64, force: f64, k: f64| {
        let l = |x: f64| x * IN / len;
        let s = |x: f64| x * PSI / st;
        format!(
            "units = \"{name}\"\n[hole]\nradius = {:e}\n[load]\nouter_radius = {:e}\nforce = {:e}\n\
             [[plates]]\nthickness = {:e}\nmaterial = {{ E = {:e}, nu = 0.33 }}\n[joint]\n\
             outer_radius = {:e}\n[heat]\nconductivity = [{:e}, {:e}]\nroughness = [{:e}, {:e}]\n\
             slope = [0.08, 0.05]\nhardness = {:e}\n[outputs]\nconductance = true\n",
            l(0.1),
            l(0.16),
            1000.0 * 4.4482216152605 / force,
            l(0.1),
            s(1.0e7),
            l(1.54),
            100.0 * k,
            60.0 * k,
            l(50e-6),
            l(30e-6),
            s(150_000.0)
        )
    };
    let (g_in, s_in) = conductance(&write("in-psi-lbf", IN, PSI, 4.4482216152605, 1.0));
    let (g_mm, s_mm) = conductance(&write("mm-MPa-N", 1e-3, 1e6, 1.0, k_si));
    let (g_m, s_m) = conductance(&write("m-Pa-N", 1.0, 1.0, 1.0, k_si));
    assert_eq!(s_mm.conductance_unit, Some("W/K"));
    assert_eq!(s_m.conductance_unit, Some("W/K"));
    // each scene solves in its own units: the same to the FE's stopping tolerance, 1e-3 of the
    // scenes' 5e-4 (tests/scene/units.rs)
    let bound = 1e-3 * 5e-4;
    for (g, what) in [(g_mm, "mm-MPa-N"), (g_m, "m-Pa-N")] {
        let rel = (g / (g_in * BTU_HR_F) - 1.0).abs();
        assert!(
            rel < bound,
            "{what}: {g} W/K vs {} W/K ({rel:e})",
            g_in * BTU_HR_F
        );
    }
    assert!((s_mm.r_o / (s_in.r_o * 25.4) - 1.0).abs() < bound);
    assert!((s_m.r_o / (s_in.r_o * IN) - 1.0).abs() < bound);
}

/// The Chapter V joint built by hand in the scene's own units (inches, psi, lbf; the surfaces
/// in SI), as the scene's numbers say.
fn chapter5_by_hand() -> (f64, f64) {
    let al = Material::new(1.0e7, 0.33).unwrap();
    let (a, b) = (0.1, 0.13);
    let p = 1000.0 / (PI * (b * b - a * a));
    let joint = Joint::new(
        a,
        OuterRadius::Finite(1.54),
        Plate::new(0.1, al).unwrap(),
        Plate::new(0.1, al).unwrap(),
        FaceLoad::uniform(a, b, p).unwrap(),
    )
    .unwrap();
    let sol = two_plate::solve(&joint, &TwoPlateParams::default()).unwrap();
    let surfaces = Surfaces::new(
        [Conductivity::from_si(100.0 * BTU_HR_F / 0.3048); 2],
        [Length::from_si(50e-6 * IN); 2],
        [0.07071067811865475; 2],
        Pressure::from_si(150_000.0 * PSI),
    )
    .unwrap();
    let mut params =
        JointParams::new(ContactConductance::new(Correlation::Cmy1969, surfaces).unwrap());
    params.length_unit = Length::from_si(IN);
    params.pressure_unit = Pressure::from_si(PSI);
    let g = joint_conductance(&sol, &params).unwrap();
    (g.total.si(), sol.r_o)
}

#[test]
fn chapter5_scene_equals_the_library_calls_and_the_command() {
    let (g_si, r_o) = chapter5_by_hand();
    let (g, s) = conductance(&example("chapter5_lap"));
    assert_eq!(s.r_o.to_bits(), r_o.to_bits());
    // the conductance factor differs from the test's BTU_HR_F by rounding only
    assert!((g * BTU_HR_F / g_si - 1.0).abs() < 1e-14, "{g} Btu/(hr·°F)");
    let dir = scratch("chapter5");
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/scenes/chapter5_lap.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", path.to_str().unwrap(), "--json"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let v = crate::common::json_of(&out);
    assert_eq!(v["joint_conductance"].as_f64(), Some(g));
    assert_eq!(v["conductance_unit"], "Btu/(hr·°F)");
    assert_eq!(v["inputs"]["heat"]["correlation"], "cmy1969");
}

/// The located message "key: reason" and line of the error of `text` (also used by `from_heat`).
pub fn error_of(text: &str) -> (String, usize) {
    match Scene::parse(text) {
        Err(SceneError::Invalid { key, line, reason }) => (format!("{key}: {reason}"), line),
        other => panic!("expected a located error, got {other:?}"),
    }
}

#[test]
fn heat_errors_name_key_value_and_line() {
    let base = joint_text("uniform", 0.1); // 13 lines
                                           // (what follows the joint, the message's start, the line)
    let heat = |c: &str, r: &str, more: &str| {
        format!("[heat]\nconductivity = [{c}]\nroughness = [{r}]\nslope = [0.1, 0.1]\n{more}")
    };
    let cases = [
        (
            "[outputs]\nconductance = true\n".to_string(),
            "outputs.conductance: true",
            15,
        ),
        (
            format!("[heat]\ncorrelation = \"cmy1970\"\n{HEAT}"),
            "heat.correlation: \"cmy1970\"",
            15,
        ),
        (
            heat("1.0, 1.0", "0.0, 0.0", "hardness = 1.0\n"),
            "heat.roughness: [0, 0]",
            16,
        ),
        (
            heat("1.0, -2.0", "1e-6, 0.0", ""),
            "heat.conductivity[1]: -2",
            15,
        ),
        (heat("1.0", "1e-6, 0.0", ""), "heat.conductivity", 15),
        (heat("1.0, 1.0", "1e-6, 0.0", ""), "heat: (no hardness)", 14),
        (
            heat("1.0, 1.0", "1e-6, 0.0", "hardnes = 1.0\n"),
            "heat.hardnes",
            18,
        ),
    ];
    for (tail, start, at) in cases {
        let (m, line) = error_of(&format!("{base}{tail}"));
        assert!(
            m.starts_with(start) && line == at,
            "{m} (line {line}) for {tail}"
        );
    }
    // mikic-elastic takes E′ from the plates and needs no hardness
    let text = format!(
        "{base}[heat]\ncorrelation = \"mikic-elastic\"\nconductivity = [100.0, 100.0]\n\
         roughness = [50e-6, 50e-6]\nslope = [0.07, 0.07]\n[outputs]\nconductance = true\n"
    );
    assert!(conductance(&text).0 > 0.0);
}

/// `boltzone two` with `args`, its exit code, JSON (when 0) and stderr.
fn two(args: &[&str]) -> (Option<i32>, serde_json::Value, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .arg("two")
        .args(args)
        .output()
        .unwrap();
    let json = serde_json::from_slice(&out.stdout).unwrap_or_default();
    (
        out.status.code(),
        json,
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

/// The joint of `joint_text("uniform", 0.1)` as `two` flags (inches, psi, lbf).
const TWO_JOINT: [&str; 16] = [
    "--a",
    "0.1",
    "--b",
    "0.16",
    "--d",
    "0.1",
    "--c",
    "1.54",
    "--e",
    "1e7",
    "--nu",
    "0.33",
    "--force",
    "1000",
    "--json",
    "--conductance",
];

/// `HEAT` as `two` flags.
const TWO_HEAT: [&str; 8] = [
    "--conductivity",
    "100,60",
    "--roughness",
    "50e-6,30e-6",
    "--slope",
    "0.08,0.05",
    "--hardness",
    "150000",
];

#[test]
fn two_conductance_flags_give_the_closed_form_and_the_scene() {
    // the power law of exponent 1 against equilibrium, as exponent_one_…
    let (k, sigma_in, m) = (75.0, (50e-6f64).hypot(30e-6), 0.08f64.hypot(0.05));
    let expect = 1.3 * m / sigma_in * k * (1000.0 / 150_000.0) / 12.0;
    let (code, v, err) = two(&[&TWO_JOINT[..], &TWO_HEAT, &["--power-law", "1.3,1"]].concat());
    assert_eq!(code, Some(0), "{err}");
    let g = v["joint_conductance"].as_f64().unwrap();
    assert!((g / expect - 1.0).abs() < 1e-9, "{g} vs {expect}");
    assert_eq!(v["conductance_unit"], "Btu/(hr·°F)");
    assert_eq!(
        v["method"], "fem",
        "the conductance asks the finite elements' pressure"
    );
    // eq. (1.1) and mikic-elastic: `two` equals the scene bit for bit (both solve in inches)
    for law in ["cmy1969", "mikic-elastic"] {
        let (code, v, err) = two(&[&TWO_JOINT[..], &TWO_HEAT, &["--correlation", law]].concat());
        assert_eq!(code, Some(0), "{law}: {err}");
        let text = format!(
            "{}[heat]\ncorrelation = \"{law}\"\n{HEAT}[outputs]\nconductance = true\n",
            joint_text("uniform", 0.1)
        );
        let (scene, s) = conductance(&text);
        let g = v["joint_conductance"].as_f64().unwrap();
        assert_eq!(
            g.to_bits(),
            scene.to_bits(),
            "{law}: two {g}, scene {scene}"
        );
        assert_eq!(v["r_o"].as_f64().map(f64::to_bits), Some(s.r_o.to_bits()));
    }
}

#[test]
fn two_heat_flag_errors_name_the_flag() {
    let bad: [(&[&str], &str); 5] = [
        (&["--correlation", "cmy1970"], "--correlation = cmy1970"),
        (&["--hardness", "-1"], "--hardness = -1"),
        (&["--slope", "0.08,NaN"], "--slope = NaN"),
        (&["--roughness", "0"], "--roughness = 0"),
        (&["--method", "hankel", "--tol", "1e-6"], "--conductance"),
    ];
    for (extra, named) in bad {
        let mut args = TWO_JOINT.to_vec();
        args.extend(TWO_HEAT);
        // a bad value replaces the good one of the same flag
        if let Some(k) = args.iter().position(|a| *a == extra[0]) {
            args.drain(k..k + 2);
        }
        args.extend(extra);
        let (code, _, err) = two(&args);
        assert_eq!(code, Some(2), "{extra:?}: {err}");
        assert!(err.contains(named), "{extra:?}: {err}");
    }
    // --conductance needs the surfaces; a heat flag needs --conductance
    let (code, _, err) = two(&TWO_JOINT);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--conductivity"), "{err}");
    let (code, _, err) = two(&["--slope", "0.1"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--conductance"), "{err}");
}

#[test]
fn two_conductance_in_si_is_the_scene_bit_for_bit() {
    // m-Pa-N: the scene and `two` solve in the same units, so they read the same numbers
    let joint = "[hole]\nradius = 0.0025\n[load]\nouter_radius = 0.004\nforce = 5000.0\n\
                 [[plates]]\nthickness = 0.0025\nmaterial = { E = 7.0e10, nu = 0.33 }\n\
                 [joint]\nouter_radius = 0.04\n";
    let heat = "conductivity = [160.0, 160.0]\nroughness = [1.2e-6, 1.2e-6]\n\
                slope = [0.1, 0.1]\nhardness = 1.0e9\n";
    let text = format!(
        "units = \"m-Pa-N\"\nmethod = \"fem\"\n{joint}[heat]\n{heat}[outputs]\nconductance = true\n"
    );
    let (scene, s) = conductance(&text);
    let (code, v, err) = two(&[
        "--units",
        "m-Pa-N",
        "--method",
        "fem",
        "--a",
        "0.0025",
        "--b",
        "0.004",
        "--d",
        "0.0025",
        "--c",
        "0.04",
        "--e",
        "7e10",
        "--nu",
        "0.33",
        "--force",
        "5000",
        "--json",
        "--conductance",
        "--conductivity",
        "160",
        "--roughness",
        "1.2e-6",
        "--slope",
        "0.1",
        "--hardness",
        "1e9",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(v["r_o"].as_f64().map(f64::to_bits), Some(s.r_o.to_bits()));
    assert_eq!(
        v["joint_conductance"].as_f64().map(f64::to_bits),
        Some(scene.to_bits()),
        "two {} W/K, scene {scene} W/K",
        v["joint_conductance"]
    );
    assert_eq!(v["conductance_unit"], "W/K");
}
