//! `--units` on `table1` and `table2`: the same tables in in-psi-lbf, mm-MPa-N and m-Pa-N. Every
//! length of the JSON, converted to metres here by the definitions (1 in = 0.0254 m, 1 mm =
//! 0.001 m), agrees across the three to 1e-15 relative (one multiplication each: a few ulps);
//! the geometry equals the report's inch values converted (Table 2 case 1: d1 = 0.065 in =
//! 1.651 mm); the ratios and percentages are the same numbers in every system; every row says
//! its `units`; the text and the CSV header name the length unit and no other.

use std::process::Command;

/// (name, metres per length unit).
const SYSTEMS: [(&str, f64); 3] = [("in-psi-lbf", 0.0254), ("mm-MPa-N", 1e-3), ("m-Pa-N", 1.0)];

fn boltzone(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .expect("runs")
}

/// The JSON rows of `table` (with `flags`) in each system.
fn rows(table: &str, flags: &[&str]) -> Vec<Vec<serde_json::Value>> {
    SYSTEMS
        .iter()
        .map(|(units, _)| {
            let mut args = vec![table, "--units", units, "--json"];
            args.extend(flags);
            let o = boltzone(&args);
            assert_eq!(o.status.code(), Some(0), "{table} {units}: {o:?}");
            let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
            let rows = v.as_array().unwrap().clone();
            assert!(rows.iter().all(|r| r["units"] == *units));
            rows
        })
        .collect()
}

/// The number at the JSON pointer `at` of each system's row `i`, times `scale(system)`.
fn same(r: &[Vec<serde_json::Value>], i: usize, at: &str, metres: bool, rel: f64) {
    let x: Vec<f64> = r
        .iter()
        .zip(SYSTEMS)
        .map(|(rows, (_, m))| {
            rows[i].pointer(at).unwrap().as_f64().unwrap() * if metres { m } else { 1.0 }
        })
        .collect();
    for v in &x[1..] {
        assert!((v / x[0] - 1.0).abs() <= rel, "row {i} {at}: {x:?}");
    }
}

#[test]
fn table2_in_three_unit_systems() {
    let r = rows("table2", &["--tol", "1e-2"]);
    for i in 0..7 {
        for at in [
            "/two_r_o/value",
            "/two_r_o/error",
            "/report/computed",
            "/report/d1",
            "/report/d2",
            "/report/two_b",
            "/report/rubbing/min",
            "/report/rubbing/average",
        ] {
            same(&r, i, at, true, 1e-15);
        }
        same(&r, i, "/discrepancy_rubbing_percent", false, 0.0);
    }
    let d1_mm = r[1][0]["report"]["d1"].as_f64().unwrap();
    assert!((d1_mm - 0.065 * 25.4).abs() <= 1e-15 * d1_mm, "{d1_mm}");
    let o = boltzone(&["table2", "--units", "mm-MPa-N", "--tol", "1e-2"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("2R_o [mm]") && text.contains("A = 3.264 mm, C = 50.80 mm"),
        "{text}"
    );
    // (" in " alone is the timing line's "7 cases in 0.5 s")
    assert!(
        !text.contains(" in,") && !text.contains("inch") && !text.contains(" in;"),
        "{text}"
    );
}

#[test]
fn table2_csv_names_its_units() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("table_units");
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("t2.csv");
    let o = boltzone(&[
        "table2",
        "--units",
        "m-Pa-N",
        "--tol",
        "1e-2",
        "--csv",
        f.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let csv = std::fs::read_to_string(&f).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(
        header.starts_with("case,d1 [m],d2 [m],two_b [m],two_r_o [m]"),
        "{header}"
    );
    assert!(header.ends_with("report_disc_rad_percent [%]") && !header.contains("[in]"));
    // case 1's d1 = 0.065 in in metres
    let d1: f64 = csv
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(1)
        .unwrap()
        .parse()
        .unwrap();
    assert!((d1 - 0.065 * 0.0254).abs() <= 1e-15 * d1, "{d1}");
}

#[test]
fn table1_in_three_unit_systems() {
    let r = rows("table1", &["--tol", "2e-2", "--no-hankel"]);
    for i in 0..12 {
        for at in [
            "/ours/geometry/a",
            "/ours/geometry/c",
            "/ours/two/value",
            "/ours/single/value",
            "/ours/rules/0/radius",
        ] {
            same(&r, i, at, true, 1e-15);
        }
        same(&r, i, "/ours/discrepancy_percent/value", false, 0.0);
        same(&r, i, "/report/two", false, 0.0);
    }
    let a_mm = r[1][0]["ours"]["geometry"]["a"].as_f64().unwrap();
    assert!((a_mm - 2.54).abs() <= 1e-15 * 2.54, "{a_mm}");
    let o = boltzone(&[
        "table1",
        "--units",
        "mm-MPa-N",
        "--tol",
        "2e-2",
        "--no-hankel",
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("A = 2.54 mm, C = 39.116 mm"), "{text}");
    assert!(!text.contains(" in,") && !text.contains("[in]"), "{text}");
}

/// The fields of a CSV's first data line, by header name.
fn first_row(csv: &str) -> std::collections::HashMap<String, String> {
    let mut lines = csv.lines();
    let header = lines.next().unwrap().split(',').map(String::from);
    header
        .zip(lines.next().unwrap().split(',').map(String::from))
        .collect()
}

#[test]
fn table1_and_map_csv_name_every_unit_and_print_inputs_as_entered() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("table_units");
    std::fs::create_dir_all(&dir).unwrap();
    let (t1, map) = (dir.join("t1.csv"), dir.join("map.csv"));
    let table = [
        "table1",
        "--units",
        "mm-MPa-N",
        "--tol",
        "2e-2",
        "--no-hankel",
    ];
    let o = boltzone(&[&table[..], &["--csv", t1.to_str().unwrap()]].concat());
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    let o = boltzone(&[
        "map",
        "--a-over-d",
        "0.3",
        "--b-over-a",
        "1.7",
        "--tol",
        "2e-2",
        "--csv",
        map.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    let (t1, map) = (
        std::fs::read_to_string(t1).unwrap(),
        std::fs::read_to_string(map).unwrap(),
    );
    // every column but the map's method columns (text) carries a [unit]
    let text = [
        "single_method",
        "single_converged",
        "two_method",
        "two_converged",
    ];
    for csv in [&t1, &map] {
        for name in csv.lines().next().unwrap().split(',') {
            assert!(
                name.ends_with(']') || text.contains(&name),
                "column {name} has no unit"
            );
        }
    }
    // Table 1's first row as the report prints it: A/D = 1, B/A = 3.1, A = 0.1 in = 2.54 mm,
    // C = 1.54 in = 39.116 mm (exact decimal conversions), not their last-bit neighbours
    let row = first_row(&t1);
    assert_eq!(row["a_over_d [1]"], "1");
    assert_eq!(row["b_over_a [1]"], "3.1");
    assert_eq!(row["a [mm]"], "2.54");
    assert_eq!(row["c [mm]"], "39.116");
    // the map's point as typed on the command line
    let row = first_row(&map);
    assert_eq!(row["a_over_d [1]"], "0.3");
    assert_eq!(row["b_over_a [1]"], "1.7");
    // the computed R_o/A is there, beyond the bearing face
    let r: f64 = row["two_r_o_over_a [1]"].parse().unwrap();
    assert!(r > 1.7 && r.is_finite());
}
