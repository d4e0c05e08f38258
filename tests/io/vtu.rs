//! `single --field` and `two --field` (VTU) read back by Python's meshio, an independent
//! reader: the points span A..C and the plates' thickness, the number and type of cells, and the
//! nodal displacements and stresses equal the library's (the same finest level solved through
//! the library API); the two-plate interface pressure in the file integrates to the bolt force
//! within the quadrature error of the exported resolution. Without `BOLTZONE_PYTHON` only the
//! Rust-side checks run.

use super::py::{boltzone_ok, force_and_bound, run, temp_dir};
use crate::common::boltzone;
use boltzone::contact::two_plate::{solve_field, TwoPlateParams};
use boltzone::fem::nodal_stresses;
use boltzone::fem::single::{solve, solve_with_field, SingleParams};
use boltzone::fem::{ElementKind, Stress};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate, SinglePlate};
use serde_json::Value;
use std::f64::consts::PI;
use std::path::Path;

/// meshio's view of a VTU: points, cell blocks, point and cell data as plain lists.
const READ: &str = r##"
import sys, json, meshio
m = meshio.read(sys.argv[1])
print(json.dumps({
    "points": m.points.tolist(),
    "cells": [[c.type, len(c.data)] for c in m.cells],
    "point_data": {k: v.tolist() for k, v in m.point_data.items()},
    "plate": [int(x) for x in m.cell_data["plate"][0]],
}))
"##;

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// Asserts `got` equals `want` to 1e-12 of the largest |want| (the file prints round-trip
/// digits: the only difference allowed is a solver's summation order between two runs).
fn same(name: &str, got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{name}");
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= 1e-12 * scale,
            "{name}[{k}]: file {g}, library {w}"
        );
    }
}

/// Compares the file's first `n` nodes (the computed plate or plates) with the library's
/// nodes, displacements and nodal stresses.
fn compare_nodes(m: &Value, nodes: &[[f64; 2]], u: &[[f64; 2]], s: &[Stress]) {
    let n = nodes.len();
    let pts = m["points"].as_array().unwrap();
    let x: Vec<f64> = pts[..n].iter().map(|p| p[0].as_f64().unwrap()).collect();
    let y: Vec<f64> = pts[..n].iter().map(|p| p[1].as_f64().unwrap()).collect();
    same("x", &x, &nodes.iter().map(|p| p[0]).collect::<Vec<_>>());
    same("y", &y, &nodes.iter().map(|p| p[1]).collect::<Vec<_>>());
    let disp = m["point_data"]["displacement"].as_array().unwrap();
    for c in 0..2 {
        let got: Vec<f64> = disp[..n].iter().map(|d| d[c].as_f64().unwrap()).collect();
        same(
            "displacement",
            &got,
            &u.iter().map(|d| d[c]).collect::<Vec<_>>(),
        );
    }
    for (name, f) in [
        ("sigma_r", (|s: &Stress| s.r) as fn(&Stress) -> f64),
        ("sigma_z", |s| s.z),
        ("sigma_theta", |s| s.theta),
        ("tau_rz", |s| s.rz),
    ] {
        let got = floats(&m["point_data"][name]);
        same(name, &got[..n], &s.iter().map(f).collect::<Vec<_>>());
    }
    // von Mises from the file's own components (an identity, not the writer's code path)
    let c: Vec<Vec<f64>> = ["sigma_r", "sigma_z", "sigma_theta", "tau_rz", "von_mises"]
        .iter()
        .map(|k| floats(&m["point_data"][*k]))
        .collect();
    for (k, vm_file) in c[4].iter().enumerate().take(n) {
        let (r, z, t, rz) = (c[0][k], c[1][k], c[2][k], c[3][k]);
        let j2 = ((r - z).powi(2) + (z - t).powi(2) + (t - r).powi(2)) / 6.0 + rz * rz;
        let vm = (3.0 * j2).sqrt();
        assert!(
            (vm_file - vm).abs() <= 1e-12 * vm.max(1e-300),
            "von Mises at {k}"
        );
    }
}

fn span(m: &Value) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in m["points"].as_array().unwrap() {
        for c in 0..2 {
            lo[c] = lo[c].min(p[c].as_f64().unwrap());
            hi[c] = hi[c].max(p[c].as_f64().unwrap());
        }
    }
    (lo, hi)
}

/// The file's text: the Rust-side checks (cell count, axisymmetry note, cell type).
fn text_checks(path: &Path, cells: usize) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.contains(&format!("NumberOfCells=\"{cells}\"")));
    assert!(text.contains("the axis of symmetry is x = 0"));
    assert!(!text.contains("NaN") && !text.contains("inf"));
}

/// The Rust-side checks, then meshio's reading: `cells` quad9 cells, points spanning
/// `x_span` and `y_span`, and the first nodes equal to the library's `(nodes, u, stresses)`.
/// None when BOLTZONE_PYTHON is unset.
fn read_and_compare(
    path: &Path,
    cells: usize,
    x_span: [f64; 2],
    y_span: [f64; 2],
    (nodes, u, s): (&[[f64; 2]], &[[f64; 2]], &[Stress]),
) -> Option<Value> {
    text_checks(path, cells);
    let m = run(READ, &[path])?;
    assert_eq!(m["cells"], serde_json::json!([["quad9", cells]]));
    let (lo, hi) = span(&m);
    // equal up to the round-off of the solver's unit scaling (× 1/L in, × L out: a few ulps)
    let near = |x: f64, want: f64| (x - want).abs() <= 4.0 * f64::EPSILON * want.abs();
    assert!(
        near(lo[0], x_span[0]) && near(hi[0], x_span[1]),
        "points span A..C: {lo:?} {hi:?}"
    );
    assert!(
        near(lo[1], y_span[0]) && near(hi[1], y_span[1]),
        "the plates' thickness: {lo:?} {hi:?}"
    );
    compare_nodes(&m, nodes, u, s);
    Some(m)
}

#[test]
fn single_plate_field_reads_back_with_meshio() {
    let dir = temp_dir("vtu-single");
    let path = dir.join("single.vtu");
    let (a, b, d, c) = (0.1, 0.31, 0.1, 1.54);
    boltzone_ok(
        "single --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-2 --field",
        &[&path],
    );
    // the library, as the command calls it
    let plate = SinglePlate::new(
        a,
        OuterRadius::Finite(c),
        d,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(a, b, 1.0).unwrap(),
    )
    .unwrap();
    let params = SingleParams {
        kind: ElementKind::Q9,
        levels: 8,
        tolerance: 1e-2,
        ..SingleParams::default()
    };
    let (sol, h) = solve_with_field(&plate, &params).unwrap();
    // keeping the field changes nothing of the answer
    let plain = solve(&plate, &params).unwrap();
    assert_eq!((plain.r_o, plain.r_o_error), (sol.r_o, sol.r_o_error));
    assert_eq!(plain.info.levels, sol.info.levels);
    let s = nodal_stresses(&h.mesh, &[plate.material()], &h.u).unwrap();
    let cells = 2 * h.mesh.n_elements();
    let Some(m) = read_and_compare(&path, cells, [a, c], [-d, d], (h.mesh.nodes(), &h.u, &s))
    else {
        return;
    };
    // the mirror half: w and τ_rz change sign
    let n = h.mesh.n_nodes();
    let disp = m["point_data"]["displacement"].as_array().unwrap();
    for k in 0..n {
        assert_eq!(disp[n + k][1].as_f64().unwrap(), -h.u[k][1]);
    }
    let plates = m["plate"].as_array().unwrap();
    assert_eq!(
        plates.iter().filter(|p| p.as_i64() == Some(1)).count(),
        cells / 2
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn two_plate_field_reads_back_and_its_pressure_carries_the_bolt_force() {
    let dir = temp_dir("vtu-two");
    let (a, b, d, c, f) = (0.1, 0.31, 0.1, 1.54, 1000.0);
    // (name, extra flags, lower plate's thickness): the symmetric joint is computed as one plate
    // and written with its mirror image, the unequal pair as both plates
    for (name, extra, d2) in [("symmetric", "", d), ("unequal", "--d2 0.15", 0.15)] {
        let path = dir.join(format!("{name}.vtu"));
        boltzone_ok(
            &format!(
                "two --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-3 --force 1000 {extra} --field"
            ),
            &[&path],
        );
        let m28 = Material::new(28e6, 0.3).unwrap();
        let joint = Joint::new(
            a,
            OuterRadius::Finite(c),
            Plate::new(d, m28).unwrap(),
            Plate::new(d2, m28).unwrap(),
            FaceLoad::uniform(a, b, f / (PI * (b * b - a * a))).unwrap(),
        )
        .unwrap();
        let params = TwoPlateParams {
            tolerance: 1e-3,
            ..TwoPlateParams::default()
        };
        let (sol, field) = solve_field(&joint, &params).unwrap();
        let model = &field.model;
        let mesh = &model.mesh;
        let s = nodal_stresses(mesh, &model.materials, &field.u).unwrap();
        let mirrored = model.lower.is_none();
        assert_eq!(mirrored, name == "symmetric");
        let cells = if mirrored { 2 } else { 1 } * mesh.n_elements();
        let lib = (mesh.nodes(), field.u.as_slice(), s.as_slice());
        let Some(m) = read_and_compare(&path, cells, [a, c], [-d2, d], lib) else {
            continue;
        };
        // the interface nodes of the upper plate (the file's first nodes are the mesh's)
        let pts = m["points"].as_array().unwrap();
        let p = floats(&m["point_data"]["contact_pressure"]);
        let st = floats(&m["point_data"]["contact_status"]);
        let face = mesh.bottom(model.upper);
        let r: Vec<f64> = face.iter().map(|&k| pts[k][0].as_f64().unwrap()).collect();
        let pr: Vec<f64> = face.iter().zip(&r).map(|(&k, r)| p[k] * r).collect();
        assert!(face.iter().all(|&k| pts[k][1].as_f64().unwrap() == 0.0));
        assert_eq!(r, sol.radius);
        let (force, bound) = force_and_bound(&r, &pr);
        eprintln!("VTU {name}: 2π∫p r dr = {force:.4} lbf, F = {f} lbf, bound {bound:.2e}");
        assert!((force - f).abs() <= bound && bound < 1e-2 * f, "{name}");
        // open beyond R_o (status 0), closed at the hole
        for (&k, &rk) in face.iter().zip(&r) {
            if rk > 1.05 * sol.r_o {
                assert_eq!(st[k], 0.0, "{name}: open beyond R_o at r = {rk}");
            }
        }
        assert_eq!(st[face[0]], 1.0, "{name}: closed at A");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn field_paths_are_checked_before_any_work() {
    let dir = temp_dir("vtu-paths");
    let path = dir.join("f.vtu");
    let p = path.to_str().unwrap();
    let missing = dir.join("no-such-dir").join("f.vtu");
    let m = missing.to_str().unwrap();
    for (args, flag) in [
        (
            vec![
                "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--method", "hankel",
                "--field", p,
            ],
            "--field",
        ),
        (
            vec![
                "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--method", "hankel",
                "--plot", p,
            ],
            "--plot",
        ),
        (
            vec![
                "two", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--field", m,
            ],
            "--field",
        ),
        (
            vec![
                "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--field", m,
            ],
            "--field",
        ),
    ] {
        let out = boltzone(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(flag),
            "{args:?}"
        );
        assert!(!path.exists() && !missing.exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
