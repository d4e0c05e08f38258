//! `[outputs] field` and `midplane` (issue 10): asking for the field leaves R_o bit for bit as
//! without it (the field is the finest level of the same study, not a second solve); the
//! midplane σ_z changes sign at R_o (found by the separate root search); the files are in the
//! scene's units (the VTU's largest radius is C in mm, to 1e-12); a sweep writes one file per point; invalid
//! requests exit 2 and write nothing.

use crate::scratch;
use boltzone::scene::Scene;
use std::process::Command;

fn text(model: &str, method: &str, units_mm: bool, outputs: &str) -> String {
    // Table 1's first geometry (A = D = 0.1 in, B = 0.31 in, C = 1.54 in), or in mm
    let (l, st, units) = if units_mm {
        (25.4, 6894.757293168361e-6, "mm-MPa-N")
    } else {
        (1.0, 1.0, "in-psi-lbf")
    };
    let joint = if model == "slab" {
        String::new()
    } else {
        format!("[joint]\nouter_radius = {:e}\n", 1.54 * l)
    };
    let hole = if model == "slab" { 0.0 } else { 0.1 * l };
    format!(
        "units = \"{units}\"\nmodel = \"{model}\"\nmethod = \"{method}\"\ntolerance = 5e-4\n\
         [hole]\nradius = {hole:e}\n[load]\nouter_radius = {:e}\npressure = {:e}\n[[plates]]\n\
         thickness = {:e}\nmaterial = {{ E = {:e}, nu = 0.3 }}\n{joint}[outputs]\n{outputs}",
        0.31 * l,
        1000.0 * st,
        0.1 * l,
        28e6 * st
    )
}

fn solve(t: &str) -> boltzone::scene::Solution {
    boltzone::solve(&Scene::parse(t).unwrap()).unwrap()
}

#[test]
fn field_asked_leaves_r_o_bit_for_bit() {
    for model in ["two-plate", "single-plate"] {
        let plain = solve(&text(model, "fem", false, "r_o = true\n"));
        let with = solve(&text(model, "fem", false, "field = \"f.vtu\"\n"));
        assert_eq!(plain.r_o.to_bits(), with.r_o.to_bits(), "{model}");
        assert_eq!(
            plain.r_o_error.to_bits(),
            with.r_o_error.to_bits(),
            "{model}"
        );
        assert!(plain.field.is_none() && with.field.is_some(), "{model}");
    }
    // auto picks the FE for a single plate's field, the tables for R_o alone (the rim's bound
    // in their bar)
    let auto = solve(&text(
        "single-plate",
        "auto",
        false,
        "midplane = \"m.csv\"\n",
    ));
    assert_eq!(auto.method, boltzone::scene::Method::Fem);
    let auto = solve(&text("single-plate", "auto", false, "r_o = true\n"));
    assert_eq!(auto.method, boltzone::scene::Method::Table);
}

/// The radius where σ_z(r) turns from compression to tension beyond B.
fn crossing(r: &[f64], s: &[f64], b: f64) -> f64 {
    let i = (1..r.len())
        .find(|&i| r[i] > b && s[i - 1] < 0.0 && s[i] >= 0.0)
        .unwrap();
    r[i - 1] + (r[i] - r[i - 1]) * (-s[i - 1]) / (s[i] - s[i - 1])
}

#[test]
fn midplane_changes_sign_at_r_o() {
    let slab = solve(&text("slab", "auto", false, "midplane = \"m.csv\"\n"));
    let m = slab.midplane.as_ref().unwrap();
    let x = crossing(&m.radius, &m.sigma_z, 0.31);
    // linear interpolation over a spacing h = 3 R_o / 120 errs by at most h²|σ''|/(8|σ'|):
    // well under 1e-3 R_o here; the error estimates of the curve are below 1e-6 of the load
    assert!((x / slab.r_o - 1.0).abs() < 1e-3, "{x} vs {}", slab.r_o);
    assert!(m.error.as_ref().unwrap().iter().all(|e| *e < 1e-3));
    // the FE single plate: its crossing is the R_o of its finest level (nodal interpolation)
    let fe = solve(&text(
        "single-plate",
        "fem",
        false,
        "midplane = \"m.csv\"\n",
    ));
    let m = fe.midplane.as_ref().unwrap();
    let x = crossing(&m.radius, &m.sigma_z, 0.31);
    assert!(
        (x - fe.r_o).abs() < 2.0 * fe.r_o_error + 1e-9,
        "{x} vs {} ± {}",
        fe.r_o,
        fe.r_o_error
    );
}

#[test]
fn files_in_the_scene_units_and_invalid_requests_exit_2() {
    let dir = scratch("field");
    let run = |name: &str, t: &str| {
        std::fs::write(dir.join(name), t).unwrap();
        Command::new(env!("CARGO_BIN_EXE_boltzone"))
            .args(["solve", name])
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    let out = run(
        "mm.toml",
        &text(
            "single-plate",
            "auto",
            true,
            "field = \"f.vtu\"\nmidplane = \"m.csv\"\n",
        ),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = std::fs::read_to_string(dir.join("m.csv")).unwrap();
    assert!(csv.starts_with("r [mm],sigma_z [MPa]\n"), "{csv}");
    assert!(csv.contains("# units: mm-MPa-N"));
    let vtu = std::fs::read_to_string(dir.join("f.vtu")).unwrap();
    assert!(vtu.contains("stresses and contact_pressure in MPa"));
    let s = solve(&text("single-plate", "auto", true, "field = \"f.vtu\"\n"));
    let r_max = s
        .field
        .unwrap()
        .points
        .iter()
        .map(|p| p[0])
        .fold(0.0, f64::max);
    assert!((r_max / (1.54 * 25.4) - 1.0).abs() < 1e-12, "{r_max} mm");
    // a sweep writes one field per point, NAME_i.vtu
    let sweep = "field = \"s.vtu\"\n[sweep]\n\"load.outer_radius\" = [0.3, 0.31]\n";
    let out = run("sweep.toml", &text("two-plate", "auto", false, sweep));
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.join("s_0.vtu").exists() && dir.join("s_1.vtu").exists());
    // a field of the slab, a midplane of two plates: exit 2, nothing written
    for (name, t, key) in [
        (
            "slab.toml",
            text("slab", "auto", false, "field = \"x.vtu\"\n"),
            "outputs.field",
        ),
        (
            "two.toml",
            text("two-plate", "auto", false, "midplane = \"x.csv\"\n"),
            "outputs.midplane",
        ),
    ] {
        let out = run(name, &t);
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(key), "{name}: {err}");
        assert!(!dir.join("x.vtu").exists() && !dir.join("x.csv").exists());
    }
}
