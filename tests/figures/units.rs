//! `boltzone figures --units`: the CSV files and the manifest in mm-MPa-N and m-Pa-N equal the
//! report's-units run times the exact factors, built here from the definitions of the inch
//! (0.0254 m) and the pound-force (0.45359237 kg × 9.80665 m/s²).

use super::gallery::{dir, rows};
use crate::common::boltzone;
use serde_json::Value;
use std::path::{Path, PathBuf};

const INCH: f64 = 0.0254;
const PSI: f64 = 0.453_592_37 * 9.806_65 / (INCH * INCH);

/// Runs `figures --only only --units units` into a fresh directory.
fn run(only: &str, units: &str) -> PathBuf {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("figures_{units}"));
    let _ = std::fs::remove_dir_all(&out);
    let run = boltzone(&[
        "figures",
        "--only",
        only,
        "--units",
        units,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    out
}

/// Every number of `name` in `other` is the report's-units one times the factor of its column.
fn scaled(other: &Path, name: &str, factors: &[f64]) {
    let (a, b) = (rows(&dir().join(name)), rows(&other.join(name)));
    assert_eq!(a.len(), b.len(), "{name}");
    assert!(!a.is_empty());
    for (ra, rb) in a.iter().zip(&b) {
        for ((x, y), f) in ra.iter().zip(rb).zip(factors) {
            assert!(
                (y - x * f).abs() <= 1e-12 * (x * f).abs(),
                "{name}: {y} vs {x} × {f}"
            );
        }
    }
}

fn header(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines().next().unwrap().to_string()
}

fn manifest(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("figures.json")).unwrap()).unwrap()
}

/// mm-MPa-N: lengths × 25.4 (the mm CSV equals the inch CSV × 25.4 to 1e-12), stresses × the
/// psi in MPa, µin → µm × 0.0254; the headers, the manifest's units, R_o and B follow.
#[test]
fn mm_csv_is_the_inch_csv_times_25_4() {
    let mm = run("12,22,28", "mm-MPa-N");
    let length = INCH / 1e-3;
    assert!((length - 25.4).abs() <= 4.0 * f64::EPSILON * 25.4);
    scaled(&mm, "fig12.csv", &[length, PSI / 1e6, 1.0]);
    scaled(&mm, "fig22.csv", &[length, INCH, 1.0]);
    scaled(&mm, "fig28.csv", &[length, length, 1.0]);
    scaled(&mm, "fig28_points.csv", &[length; 6]);
    scaled(
        &mm,
        "fig12_points.csv",
        &[length, PSI / 1e6, length, length],
    );
    assert_eq!(header(&mm.join("fig12.csv")), "r [mm],sigma_z [MPa],curve");
    assert_eq!(header(&mm.join("fig22.csv")), "r [mm],w [um],curve");
    let (inch, metric) = (manifest(dir()), manifest(&mm));
    assert_eq!(metric["units"], "mm-MPa-N");
    assert_eq!(inch["units"], "in-psi-lbf");
    let fig12 = |m: &Value| {
        m["figures"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["id"] == "fig12")
            .unwrap()
            .clone()
    };
    let (a, b) = (fig12(&inch), fig12(&metric));
    for key in ["value", "error"] {
        let (x, y) = (
            a["curves"][0]["r_o"][key].as_f64().unwrap(),
            b["curves"][0]["r_o"][key].as_f64().unwrap(),
        );
        assert!((y - x * length).abs() <= 1e-12 * y.abs(), "R_o {key}");
    }
    assert!(b["curves"][0]["label"].as_str().unwrap().ends_with(" mm"));
    assert_eq!(b["x_label"], "r [mm]");
}

/// m-Pa-N on Fig. 20 (the bearing pressures, no solve): r × 0.0254, psi × 6894.757…
#[test]
fn si_csv_is_the_inch_csv_times_the_factors() {
    let si = run("20", "m-Pa-N");
    scaled(&si, "fig20.csv", &[INCH, PSI, 1.0]);
    assert_eq!(
        header(&si.join("fig20.csv")),
        "r [m],bearing pressure [Pa],curve"
    );
    let m = manifest(&si);
    let label = m["figures"][0]["curves"][0]["label"].as_str().unwrap();
    // 1100 lbf in N
    assert!(label.contains("4893.04 N"), "{label}");
}

/// A unit system that does not exist exits 2 and names the flag.
#[test]
fn bad_units_exit_2() {
    let out = boltzone(&[
        "figures",
        "--only",
        "20",
        "--units",
        "furlongs",
        "--out",
        env!("CARGO_TARGET_TMPDIR"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--units"));
}
