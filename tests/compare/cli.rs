//! The commands `boltzone` (default case), `table2`, `map` and their named errors.

use std::process::Command;

fn boltzone(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .expect("runs")
}

#[test]
fn default_case_names_its_geometry_and_models() {
    let o = boltzone(&[]);
    assert!(o.status.success());
    let s = String::from_utf8(o.stdout).unwrap();
    for want in [
        "Table 1's first geometry",
        "two-plate model",
        "single-plate",
        "45°",
        "VDI",
        "30°",
    ] {
        assert!(s.contains(want), "missing {want} in\n{s}");
    }
}

#[test]
fn map_writes_csv_and_figures() {
    let dir = std::env::temp_dir().join(format!("boltzone_map_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, svg, png) = (dir.join("m.csv"), dir.join("m.svg"), dir.join("m.png"));
    let o = boltzone(&[
        "map",
        "--n",
        "2",
        "--tol",
        "2e-3",
        "--csv",
        csv.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 5);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    assert_eq!(&std::fs::read(&png).unwrap()[..4], b"\x89PNG");
    // Nothing left behind but the three files (temporary files were renamed).
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 3);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn map_takes_your_own_points() {
    // Table 1's first geometry through the map command, written as CSV.
    let csv = std::env::temp_dir().join(format!("boltzone_own_{}.csv", std::process::id()));
    let o = boltzone(&[
        "map",
        "--a-over-d",
        "1",
        "--b-over-a",
        "3.1",
        "--tol",
        "2e-3",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8(o.stdout)
        .unwrap()
        .contains("design map 1 x 1"));
    let text = std::fs::read_to_string(&csv).unwrap();
    let first: Vec<f64> = text
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .take(2)
        .map(|x| x.parse().unwrap())
        .collect();
    assert!(
        (first[0] - 1.0).abs() < 1e-12 && (first[1] - 3.1).abs() < 1e-12,
        "{text}"
    );
    std::fs::remove_file(&csv).unwrap();
}

#[test]
fn bad_arguments_are_named() {
    let o = boltzone(&["map", "--n", "1"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--n"));
    let o = boltzone(&["map", "--n", "2", "--svg", "/tmp/boltzone_map.txt"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("extension"));
    let o = boltzone(&["table1", "--tol=-1"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("tolerance"));
    let o = boltzone(&["map", "--a-over-d", "1,-2", "--b-over-a", "2"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("A/D"));
    let o = boltzone(&["table2", "--interface", "glued"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("glued"));
}
