//! `boltzone figures`: what each figure shows, checked against its own files and independent
//! references (module docs of `main.rs`).

use crate::common::{boltzone, json_of};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The whole set (Figs. 12–29 and the slab) runs once for the whole crate at the default
/// tolerance, in the report's units (~6 s on two busy cores); every test reads its files.
pub(crate) fn dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("figures_gallery");
        let _ = std::fs::remove_dir_all(&dir);
        let out = boltzone(&["figures", "--out", dir.to_str().unwrap()]);
        assert!(
            out.status.success(),
            "figures failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        dir
    })
}

pub(crate) fn manifest() -> Value {
    let text = std::fs::read_to_string(dir().join("figures.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

pub(crate) fn figure(id: &str) -> Value {
    manifest()["figures"]
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["id"] == id)
        .unwrap_or_else(|| panic!("{id} missing from figures.json"))
        .clone()
}

/// The numeric rows of one of our CSV files (header first, `#` comments skipped).
pub(crate) fn rows(path: &Path) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// (x, y) of curve `k` of figure `id`.
pub(crate) fn curve(id: &str, k: usize) -> (Vec<f64>, Vec<f64>) {
    rows(&dir().join(format!("{id}.csv")))
        .into_iter()
        .filter(|r| r[2] == k as f64)
        .map(|r| (r[0], r[1]))
        .unzip()
}

/// The nodes [r_i, r_{i+1}] beyond `b` between which the curve of `kind` separates.
fn bracket(kind: &str, b: f64, x: &[f64], y: &[f64]) -> (f64, f64) {
    let scale = y.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    (1..x.len())
        .find(|&i| {
            x[i] > b
                && match kind {
                    "sigma-z" => y[i - 1] < 0.0 && y[i] >= 0.0,
                    "pressure" => y[i - 1] > 0.0 && y[i] <= 0.0,
                    "gap" => y[i] > 1e-12 * scale,
                    other => panic!("no separation on a {other} curve"),
                }
        })
        .map(|i| (x[i - 1], x[i]))
        .unwrap_or_else(|| panic!("the {kind} curve does not separate beyond B = {b}"))
}

/// Checks that each curve's R_o (± its error) in `dir` lies between the two nodes where the
/// drawn curve changes sign (or opens), and that it converged; returns how many were checked.
fn curves_separate_at_their_r_o(dir: &Path) -> usize {
    let text = std::fs::read_to_string(dir.join("figures.json")).unwrap();
    let manifest: Value = serde_json::from_str(&text).unwrap();
    let mut checked = 0;
    for fig in manifest["figures"].as_array().unwrap() {
        let id = fig["id"].as_str().unwrap();
        let data = rows(&dir.join(format!("{id}.csv")));
        for c in fig["curves"].as_array().unwrap() {
            let Some(r_o) = c["r_o"].as_object() else {
                continue;
            };
            let (value, error) = (
                r_o["value"].as_f64().unwrap(),
                r_o["error"].as_f64().unwrap(),
            );
            assert_eq!(r_o["converged"], true, "{id}: {}", c["label"]);
            let k = c["curve"].as_f64().unwrap();
            let (x, y): (Vec<f64>, Vec<f64>) = data
                .iter()
                .filter(|r| r[2] == k)
                .map(|r| (r[0], r[1]))
                .unzip();
            if c["kind"] == "other" {
                // a drawing (Fig. 29): the contact zone is the circle of radius R_o
                let off = x.iter().zip(&y).map(|(x, y)| (x.hypot(*y) - value).abs());
                assert!(off.fold(0.0, f64::max) <= 1e-12 * value, "{id} curve {k}");
                checked += 1;
                continue;
            }
            let (lo, hi) = bracket(
                c["kind"].as_str().unwrap(),
                c["b"].as_f64().unwrap(),
                &x,
                &y,
            );
            assert!(
                value + error >= lo && value - error <= hi,
                "{id} curve {k}: R_o = {value} ± {error} outside the curve's sign change [{lo}, {hi}]"
            );
            checked += 1;
        }
    }
    checked
}

/// Each curve's R_o (± its error) lies between the two nodes where the drawn curve changes sign
/// (or opens), in every figure of the set: the figure shows the R_o it prints. The check is
/// exact, no tolerance: a piecewise-linear curve's zero lies in that bracket, and so must R_o.
#[test]
fn every_curve_separates_at_its_r_o() {
    // 12–17: 24, 18: 2, 19: 2, 21: 1, 23: 1, 24: 2, 25: 3, 26: 1, 27: 1, 29: 1, slab: 4
    assert_eq!(curves_separate_at_their_r_o(dir()), 42);
}

/// The report's CSV tables, parsed here without the library: (header, rows of fields).
pub(crate) fn reference(name: &str) -> Vec<Vec<String>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("reference")
        .join(name);
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// The points series `k` of figure `id` from its points CSV: (x, y, x_lo, x_hi, y_lo, y_hi).
pub(crate) fn points(id: &str, k: usize) -> Vec<[f64; 6]> {
    rows(&dir().join(format!("{id}_points.csv")))
        .into_iter()
        .filter(|r| r[6] == k as f64)
        .map(|r| [r[0], r[1], r[2], r[3], r[4], r[5]])
        .collect()
}

/// The single plate's R_o of Fig. 12 (finite elements) against the Hankel route with the hole
/// and rim corrected (`single --method hankel`: shares no code with the FE): they agree within
/// the sum of their error estimates.
#[test]
fn fig12_single_plate_r_o_match_the_hankel_route() {
    let fig = figure("fig12");
    let c = &fig["curves"][0];
    let fe = c["r_o"]["value"].as_f64().unwrap();
    let fe_error = c["r_o"]["error"].as_f64().unwrap();
    let b = c["b"].as_f64().unwrap();
    let hankel = json_of(&boltzone(&[
        "single",
        "--method",
        "hankel",
        "--a",
        "0.1",
        "--b",
        &b.to_string(),
        "--d",
        "0.1",
        "--c",
        "1.54",
        "--json",
    ]));
    let (h, h_error) = (
        hankel["r_o"].as_f64().unwrap(),
        hankel["r_o_error"].as_f64().unwrap(),
    );
    assert!(
        (fe - h).abs() <= fe_error + h_error,
        "FE {fe} ± {fe_error} vs Hankel {h} ± {h_error}"
    );
}

/// Fig. 20's three bearing-pressure profiles carry the tests' bolt force, 1100 lb (Table 2's
/// provenance). p is linear in r on the uniform grid A..B, so 2πr·p is quadratic and the
/// trapezoidal rule's error is exactly c·h²: Richardson's extrapolation from h and 2h is exact
/// up to rounding (200 terms of size ≈ 10 lb: 1e-12 relative).
#[test]
fn fig20_profiles_carry_the_bolt_force() {
    for k in 0..3 {
        let (r, p) = curve("fig20", k);
        assert_eq!(r.len(), 201);
        let trapezoid = |step: usize| -> f64 {
            let idx: Vec<usize> = (0..r.len()).step_by(step).collect();
            idx.windows(2)
                .map(|w| {
                    let (i, j) = (w[0], w[1]);
                    std::f64::consts::PI * (p[i] * r[i] + p[j] * r[j]) * (r[j] - r[i])
                })
                .sum()
        };
        let (fine, coarse) = (trapezoid(1), trapezoid(2));
        let force = fine + (fine - coarse) / 3.0;
        assert!(
            (force - 1100.0).abs() <= 1e-12 * 1100.0,
            "curve {k}: {force} lb"
        );
    }
}

/// Every figure asked for has its SVG (with the report's caption as title), PNG of the drawn
/// size, curve CSV, and an entry in the gallery.
#[test]
fn files_and_gallery_are_complete() {
    let index = std::fs::read_to_string(dir().join("index.html")).unwrap();
    for fig in manifest()["figures"].as_array().unwrap() {
        let id = fig["id"].as_str().unwrap();
        let svg = std::fs::read_to_string(dir().join(format!("{id}.svg"))).unwrap();
        let title = fig["title"].as_str().unwrap();
        let first = title.split(':').next().unwrap();
        assert!(svg.contains(first), "{id}.svg lacks its caption '{first}'");
        let png = std::fs::read(dir().join(format!("{id}.png"))).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        let w = u32::from_be_bytes(png[16..20].try_into().unwrap());
        let h = u32::from_be_bytes(png[20..24].try_into().unwrap());
        assert_eq!((w, h), (1000, 660));
        assert!(dir().join(format!("{id}.csv")).is_file());
        assert!(
            index.contains(&format!("src=\"{id}.svg\"")),
            "{id} not in the gallery"
        );
    }
    assert_eq!(manifest()["figures"].as_array().unwrap().len(), 19);
}

/// Bad flags exit 2 and name the flag, before any work.
#[test]
fn bad_flags_exit_2() {
    let out = boltzone(&[
        "figures",
        "--only",
        "99",
        "--out",
        env!("CARGO_TARGET_TMPDIR"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--only"));
    let file = Path::new(env!("CARGO_TARGET_TMPDIR")).join("figures_not_a_dir");
    std::fs::write(&file, "x").unwrap();
    let out = boltzone(&["figures", "--only", "20", "--out", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--out"));
    let out = boltzone(&[
        "figures",
        "--only",
        "20",
        "--tol",
        "-1",
        "--out",
        env!("CARGO_TARGET_TMPDIR"),
    ]);
    assert_eq!(out.status.code(), Some(2));
}
