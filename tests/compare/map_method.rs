//! The design map by method (`compare::route`, `map --method`): the Hankel routes against the
//! finite elements, which share no code with them, within the sum of both estimates; `auto`
//! taking the two-plate Hankel route only within its reach and below a tolerance of 3e-5, and
//! the CSV saying which method ran; `--method` errors named, exit 2.

use boltzone::compare::map::{check_reach, compute, MapParams, METHOD_COLUMNS};
use boltzone::compare::{two_hankel_reach, CompareError, Comparison, Method, Route, Value};
use std::process::Command;

pub fn map(a_over_d: &[f64], b_over_a: &[f64], c_over_a: f64, method: Method) -> MapParams {
    MapParams {
        a_over_d: a_over_d.to_vec(),
        b_over_a: b_over_a.to_vec(),
        c_over_a,
        tolerance: 1e-3,
        method,
        ..MapParams::default()
    }
}

/// The CSV's column `name` (its header `name` or `name [unit]`) for every point.
pub fn column(csv: &str, name: &str) -> Vec<String> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let named = |h: &&str| *h == name || h.strip_prefix(name).is_some_and(|u| u.starts_with(" ["));
    let k = header.iter().position(named).unwrap();
    lines
        .map(|l| l.split(',').nth(k).unwrap().to_string())
        .collect()
}

#[test]
fn hankel_map_agrees_with_the_fem_within_both_estimates() {
    // A/D 1 (Table 1's D), B/A 1.3 (its narrowest load) and 2.2, C/A 15.4: both models by both
    // methods. The two methods share no code; each difference must lie within the sum of the
    // two estimates (the estimates are each route's own, checked against tighter runs in
    // example 13 and the solvers' tests).
    let (ad, ba) = ([1.0], [1.3, 2.2]);
    let fem = compute(&map(&ad, &ba, 15.4, Method::Fem), &|| ()).unwrap();
    let hankel = compute(&map(&ad, &ba, 15.4, Method::Hankel), &|| ()).unwrap();
    type Pick = fn(&Comparison) -> (Value, Route);
    let models: [(&str, Pick); 2] = [
        ("single", |c| (c.single, c.single_method)),
        ("two", |c| (c.two, c.two_method)),
    ];
    for (f, h) in fem.points.iter().zip(&hankel.points) {
        for (name, pick) in models {
            let ((vf, rf), (vh, rh)) = (pick(f), pick(h));
            assert_eq!((rf, rh), (Route::Fem, Route::Hankel), "{name}");
            assert!(vf.converged && vh.converged, "{name}: {vf:?} {vh:?}");
            assert!(
                (vf.value - vh.value).abs() <= vf.error + vh.error,
                "{name} at B/A {}: FE {vf:?}, Hankel {vh:?}",
                f.geometry.b_over_a()
            );
        }
    }
    let csv = hankel.csv();
    assert!(csv.lines().next().unwrap().ends_with(METHOD_COLUMNS));
    assert_eq!(column(&csv, "two_method"), ["hankel", "hankel"]);
    assert_eq!(column(&csv, "single_converged"), ["true", "true"]);
}

#[test]
fn auto_takes_the_two_plate_route_only_within_reach_and_below_3e_5() {
    // as `two --method auto` and a scene's `method = "auto"`: above 3e-5 the FE is several times
    // faster and claims the tolerance; `hankel` always (a point out of reach is refused before)
    use boltzone::compare::two_takes_hankel;
    use boltzone::hankel::receding::AUTO_BELOW;
    assert_eq!(AUTO_BELOW, boltzone::scene::two_hankel::AUTO_BELOW);
    for (method, tol, in_reach, takes) in [
        (Method::Auto, 1e-5, true, true),
        (Method::Auto, 1e-5, false, false),
        (Method::Auto, 1e-3, true, false),
        (Method::Hankel, 1e-3, true, true),
        (Method::Fem, 1e-5, true, false),
    ] {
        assert_eq!(
            two_takes_hankel(method, tol, in_reach),
            takes,
            "{method:?} {tol}"
        );
    }
    // (A/D 5, B/A 2.2): B/D = 11 > 8 with the rim; (A/D 1, B/A 2.2) with C/A = 3: C = 3A is
    // within one plate thickness of B + D = 3.2A (and beyond R_o ≈ 2.6A). The single plate's
    // route reaches both; at 1e-3 auto keeps the FE for the two plates in any case.
    for (ad, ba, c_over_a, limit) in [(5.0, 2.2, 15.4, "B/D"), (1.0, 2.2, 3.0, "C = ")] {
        let p = map(&[ad], &[ba], c_over_a, Method::Auto);
        let m = compute(&p, &|| ()).unwrap();
        let c = m.at(0, 0);
        assert!(two_hankel_reach(&c.geometry).unwrap_err().contains(limit));
        assert_eq!((c.single_method, c.two_method), (Route::Hankel, Route::Fem));
        assert!(c.converged());
        let csv = m.csv();
        assert_eq!(column(&csv, "single_method"), ["hankel"]);
        assert_eq!(column(&csv, "two_method"), ["fem"]);
        assert_eq!(column(&csv, "two_converged"), ["true"]);
        // --method hankel refuses the point before computing, as input naming it
        let e = check_reach(&map(&[ad], &[ba], c_over_a, Method::Hankel)).unwrap_err();
        assert!(matches!(e, CompareError::OutOfReach { .. }) && e.is_input());
        assert!(e.to_string().contains(&format!("A/D = {ad:.4}")), "{e}");
        let e = compute(&map(&[ad], &[ba], c_over_a, Method::Hankel), &|| ()).unwrap_err();
        assert!(e.is_input(), "{e}");
    }
}

/// `boltzone args` run in `dir`.
fn boltzone_in(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_boltzone"));
    cmd.current_dir(dir).args(args).output().expect("runs")
}

#[test]
fn map_method_flag_is_named_and_auto_says_which_method_ran() {
    let dir = std::env::temp_dir().join(format!("boltzone_map_method_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let boltzone = |args: &[&str]| boltzone_in(&dir, args);
    let o = boltzone(&["map", "--method", "galerkin"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--method"));
    // hankel over the default 40 × 40 map: refused before computing, naming the first point
    // beyond the two-plate route's reach
    let o = boltzone(&["map", "--method", "hankel"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--method") && err.contains("A/D = ") && err.contains("B/D"),
        "{err}"
    );
    // README's command
    let o = boltzone(&[
        "map",
        "--method",
        "auto",
        "--a-over-d",
        "1,5",
        "--b-over-a",
        "2.2",
        "--csv",
        "map_auto.csv",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        // the single plate at A/D 1 from the tables (its rim 15.4 A is bounded), at A/D 5
        // (beyond them) by the Hankel route
        out.contains("single plate table at 1, hankel at 1, fem at 0 of 2 points")
            // the two plates at A/D 1 from the tables with the rim table's shift, at A/D 5 by
            // the FE
            && out.contains("two plates table at 1, hankel at 0, fem at 1 of 2 points"),
        "{out}"
    );
    let text = std::fs::read_to_string(dir.join("map_auto.csv")).unwrap();
    assert_eq!(column(&text, "single_method"), ["table", "hankel"]);
    assert_eq!(column(&text, "two_method"), ["table", "fem"]);
    std::fs::remove_dir_all(&dir).unwrap();
}
