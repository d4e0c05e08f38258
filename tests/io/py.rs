//! The independent readers: Python's meshio and numpy in the virtual environment `.ci/run`
//! creates and names in `BOLTZONE_PYTHON`. Without it the Python checks are skipped with a note
//! (a bare `cargo test` passes); the Rust-side checks of each test still run.

use std::path::Path;
use std::process::Command;

/// Runs `script` with `python` (the file paths as `sys.argv[1..]`) and parses the JSON it prints
/// on its last line; None (with a printed note) when BOLTZONE_PYTHON is unset.
pub fn run(script: &str, files: &[&Path]) -> Option<serde_json::Value> {
    let Some(python) = std::env::var_os("BOLTZONE_PYTHON") else {
        eprintln!(
            "note: BOLTZONE_PYTHON is unset: the meshio/numpy reading is skipped (bash .ci/run \
             sets it up)"
        );
        return None;
    };
    let out = Command::new(python)
        .arg("-c")
        .arg(script)
        .args(files)
        .output()
        .expect("BOLTZONE_PYTHON runs");
    assert!(
        out.status.success(),
        "python failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let last = text.lines().last().expect("the script printed JSON");
    Some(serde_json::from_str(last).expect("JSON from the script"))
}

/// A fresh temporary directory for one test.
pub fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("boltzone-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Column `k` of a CSV in the one curve layout (header, `#` lines, data), parsed in Rust.
pub fn csv_columns(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// ∫ y dx by the trapezoidal rule on the points (x, y).
pub fn trapezoid(x: &[f64], y: &[f64]) -> f64 {
    x.windows(2)
        .zip(y.windows(2))
        .map(|(x, y)| 0.5 * (y[0] + y[1]) * (x[1] - x[0]))
        .sum()
}

/// 2π∫p r dr by the trapezoidal rule on the nodes (`pr` = p·r), and the bound |Δ| of its
/// quadrature error: the difference from the same rule on every other node (indices 0, 2, 4, …
/// and the last), which bounds the finer sum's error whenever the rule converges at least
/// linearly (it is second order here: the error measured is ≈ |Δ|/3).
pub fn force_and_bound(r: &[f64], pr: &[f64]) -> (f64, f64) {
    let fine = 2.0 * std::f64::consts::PI * trapezoid(r, pr);
    let mut idx: Vec<usize> = (0..r.len()).step_by(2).collect();
    if idx.last() != Some(&(r.len() - 1)) {
        idx.push(r.len() - 1);
    }
    let rc: Vec<f64> = idx.iter().map(|&i| r[i]).collect();
    let prc: Vec<f64> = idx.iter().map(|&i| pr[i]).collect();
    let coarse = 2.0 * std::f64::consts::PI * trapezoid(&rc, &prc);
    (fine, (fine - coarse).abs())
}

/// Runs `boltzone` with the words of `line` followed by the paths `files`, asserting exit 0.
pub fn boltzone_ok(line: &str, files: &[&Path]) {
    let mut args: Vec<&str> = line.split_whitespace().collect();
    args.extend(files.iter().map(|f| f.to_str().unwrap()));
    let out = crate::common::boltzone(&args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}
