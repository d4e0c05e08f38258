//! The one curve layout of every `--curve` file (`two`, `slab`, `single`): ONE header row with
//! units, `#` provenance lines after it, then data, first column r. Read back in Rust and, when
//! `BOLTZONE_PYTHON` is set (`.ci/run`), by `numpy.genfromtxt(names=True)` and
//! `pandas.read_csv(comment="#")` (both installed by `.ci/run`), independent readers that must see the same names and the same numbers. The
//! exported interface pressure integrates to the bolt force within the quadrature error of the
//! exported resolution.

use super::py::{boltzone_ok, csv_columns, force_and_bound, run, temp_dir};
use std::path::Path;

/// numpy's and pandas' view of each file: names, data, (pandas) columns and shape.
const READ: &str = r##"
import sys, json, numpy as np, pandas as pd
out = []
for f in sys.argv[1:]:
    d = np.genfromtxt(f, comments="#", names=True, delimiter=",")
    rec = {"names": list(d.dtype.names), "data": [[float(x) for x in row] for row in d.tolist()]}
    t = pd.read_csv(f, comment="#")
    rec["pandas_columns"] = list(t.columns)
    rec["pandas_shape"] = list(t.shape)
    rec["pandas_data"] = t.to_numpy().tolist()
    out.append(rec)
print(json.dumps(out))
"##;

/// Checks the layout of `path` in Rust; returns its header and rows.
fn layout(path: &Path, header: &str, method: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], header, "{}", path.display());
    let comments: Vec<&str> = lines[1..]
        .iter()
        .take_while(|l| l.starts_with('#'))
        .copied()
        .collect();
    let version = format!("# boltzone {}", env!("CARGO_PKG_VERSION"));
    for want in [
        version.as_str(),
        "# command: ",
        "# units: in-psi-lbf",
        method,
        "R_o = ",
        "converged: true",
    ] {
        assert!(
            comments.iter().any(|c| c.contains(want)),
            "{}: no '{want}' in {comments:?}",
            path.display()
        );
    }
    let (names, rows) = csv_columns(&text);
    assert!(rows.len() > 10);
    assert!(rows.iter().all(|r| r.len() == names.len()));
    // first column r, increasing
    assert!(rows.windows(2).all(|w| w[1][0] > w[0][0]));
    (names, rows)
}

#[test]
fn every_curve_has_one_header_then_provenance_and_numpy_reads_it() {
    let dir = temp_dir("csv-layout");
    let (slab, single, two, hankel) = (
        dir.join("slab.csv"),
        dir.join("single.csv"),
        dir.join("two.csv"),
        dir.join("hankel.csv"),
    );
    let g = "--a 0.1 --b 0.31 --d 0.1";
    let cases = [
        (
            format!("slab {g} --curve"),
            &slab,
            "r [in],sigma_z [psi],sigma_z_error [psi]",
            "# method: infinite slab",
            vec!["r_in", "sigma_z_psi", "sigma_z_error_psi"],
        ),
        (
            format!("single {g} --c 1.54 --tol 1e-2 --curve"),
            &single,
            "r [in],sigma_z [psi]",
            "# method: single plate 2D thick",
            vec!["r_in", "sigma_z_psi"],
        ),
        (
            format!("two {g} --c 1.54 --tol 1e-2 --curve"),
            &two,
            "r [in],p [psi],g [in],tau [psi]",
            "# method: two-plate FE contact",
            vec!["r_in", "p_psi", "g_in", "tau_psi"],
        ),
        (
            format!("single {g} --c 1.54 --method hankel --curve"),
            &hankel,
            "r [in],sigma_z [psi]",
            "# method: single plate 2D thick with a traction-free hole, semi-analytic",
            vec!["r_in", "sigma_z_psi"],
        ),
    ];
    let mut parsed = Vec::new();
    for (line, path, header, method, _) in &cases {
        boltzone_ok(line, &[path.as_path()]);
        parsed.push(layout(path, header, method));
    }
    let files: Vec<&Path> = cases.iter().map(|c| c.1.as_path()).collect();
    let Some(py) = run(READ, &files) else {
        return;
    };
    for (k, ((names, rows), case)) in parsed.iter().zip(&cases).enumerate() {
        let rec = &py[k];
        let np_names: Vec<&str> = rec["names"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        assert_eq!(np_names, case.4, "numpy's names of {}", case.0);
        let data = rec["data"].as_array().unwrap();
        assert_eq!(data.len(), rows.len(), "numpy's rows of {}", case.0);
        for (row, np_row) in rows.iter().zip(data) {
            let np_row: Vec<f64> = np_row
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v.as_f64().unwrap())
                .collect();
            // shortest round-trip digits: both readers get the same f64
            assert_eq!(row, &np_row, "{}", case.0);
        }
        let cols: Vec<&str> = rec["pandas_columns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        assert_eq!(cols, names.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(rec["pandas_shape"][0].as_u64(), Some(rows.len() as u64));
        // pandas reads the same f64 values as Rust (shortest round-trip digits)
        let pd_rows: Vec<Vec<f64>> = rec["pandas_data"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| {
                r.as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect()
            })
            .collect();
        assert_eq!(&pd_rows, rows, "pandas' data of {}", case.0);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// 2π∫p r dr of a `two --curve` file and its quadrature error bound ([`force_and_bound`]).
fn force_from_curve(path: &Path) -> (f64, f64) {
    let (_, rows) = csv_columns(&std::fs::read_to_string(path).unwrap());
    let r: Vec<f64> = rows.iter().map(|x| x[0]).collect();
    let pr: Vec<f64> = rows.iter().map(|x| x[1] * x[0]).collect();
    force_and_bound(&r, &pr)
}

#[test]
fn exported_pressure_integrates_to_the_bolt_force() {
    let dir = temp_dir("csv-force");
    let f = 1000.0;
    for (name, extra) in [("symmetric", ""), ("unequal", "--d2 0.15")] {
        let path = dir.join(format!("{name}.csv"));
        boltzone_ok(
            &format!(
                "two --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-3 --force 1000 {extra} --curve"
            ),
            &[&path],
        );
        let (force, bound) = force_from_curve(&path);
        eprintln!(
            "{name}: 2π∫p r dr = {force:.4} lbf (F = {f} lbf), error {:.2e}, bound |Δ| {bound:.2e}",
            force - f
        );
        assert!(
            (force - f).abs() <= bound,
            "{name}: {force} vs {f} ± {bound}"
        );
        // the bound is a real check: well below 1 % of F
        assert!(bound < 1e-2 * f, "{name}: bound {bound}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
