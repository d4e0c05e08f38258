//! The design map of infinite plates (`map --c-over-a inf`): `auto` answers both models from the
//! tables wherever their bars meet the tolerance, and those answers agree with the Hankel
//! routes (which share no data with them) within the sum of both estimates; VDI 2230, whose
//! cone angle needs a rim, is left out with its reason; `--method table` is refused outside
//! the tables naming the point; the guide's commands run.

use super::map_method::{column, map};
use crate::common::boltzone;
use boltzone::compare::map::{check_reach, compute};
use boltzone::compare::{CompareError, Method, Route};

#[test]
fn auto_answers_infinite_plates_from_the_tables_within_the_hankel_routes_bars() {
    let (ad, ba) = ([0.5, 2.0], [1.6, 3.0]);
    let by_table = compute(&map(&ad, &ba, f64::INFINITY, Method::Auto), &|| ()).unwrap();
    let by_hankel = compute(&map(&ad, &ba, f64::INFINITY, Method::Hankel), &|| ()).unwrap();
    for (t, h) in by_table.points.iter().zip(&by_hankel.points) {
        assert_eq!(
            (t.single_method, t.two_method),
            (Route::Table, Route::Table)
        );
        assert_eq!(
            (h.single_method, h.two_method),
            (Route::Hankel, Route::Hankel)
        );
        for (a, b) in [(t.single, h.single), (t.two, h.two)] {
            assert!(
                (a.value - b.value).abs() <= a.error + b.error,
                "{:?}: table {a:?} hankel {b:?}",
                t.geometry
            );
        }
        assert!(t.rules[1].is_none() && t.rules[0].is_some() && t.rules[2].is_some());
        assert_eq!(t.rules_left_out[0].name, "VDI 2230");
    }
}

#[test]
fn the_tables_are_refused_outside_them_naming_the_point() {
    let p = map(&[0.2, 1.0], &[2.0], f64::INFINITY, Method::Table);
    match check_reach(&p) {
        Err(CompareError::OutOfReach { reason, .. }) => {
            assert!(reason.contains("A/D = 0.2"), "{reason}")
        }
        other => panic!("{other:?}"),
    }
    // with a rim the command line refuses the tables before any point
    let out = boltzone(&["map", "--n", "2", "--method", "table"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn the_guides_map_and_single_commands_from_the_tables_run() {
    let guide = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/guide.md"),
    )
    .unwrap();
    let dir = std::env::temp_dir().join(format!("boltzone-map-inf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("map_inf.csv");
    assert!(guide.contains("boltzone map --c-over-a inf --method auto --n 8 --csv map_inf.csv"));
    let out = boltzone(&[
        "map",
        "--c-over-a",
        "inf",
        "--method",
        "auto",
        "--n",
        "8",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let methods = column(&text, "two_method");
    assert!(methods.iter().any(|m| m == "table") && methods.iter().any(|m| m != "table"));
    // VDI 2230 is left out: its columns are empty
    assert!(column(&text, "vdi_r_over_a").iter().all(String::is_empty));
    assert!(guide.contains("boltzone single --a 0.1 --b 0.31 --d 0.1 --method table --tol 1e-4"));
    let out = boltzone(&[
        "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--method", "table", "--tol", "1e-4",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}
