//! `boltzone single --method hankel`: JSON keys and the same R_o as the library.

use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

use crate::common;

#[test]
fn single_hankel_json_matches_the_library() {
    let out = common::boltzone(&[
        "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--method", "hankel", "--json",
    ]);
    let v = common::json_of(&out);
    for key in [
        "r_o",
        "r_o_over_a",
        "r_o_error",
        "hole_terms",
        "hole_residual_max",
        "hole_residual_rms",
    ] {
        assert!(v.get(key).is_some(), "missing {key}: {v}");
    }
    let load = FaceLoad::uniform(0.1, 0.31, 1.0).unwrap();
    let plate = SinglePlate::new(
        0.1,
        OuterRadius::Infinite,
        0.1,
        Material::unit(0.3).unwrap(),
        load,
    )
    .unwrap();
    let (sep, hole) =
        single_plate_separation(&plate, &Default::default(), &HoleParams::default()).unwrap();
    // the same deterministic computation: equal to the printed digits
    assert_eq!(v["r_o"].as_f64().unwrap(), sep.r_o);
    assert_eq!(v["hole_terms"].as_u64().unwrap() as usize, hole.terms);
    assert!(
        (v["r_o_over_a"].as_f64().unwrap() - sep.r_o / 0.1).abs() < 1e-15 * sep.r_o / 0.1 + 1e-15
    );
}

#[test]
fn corner_terms_flag_reaches_the_solver_and_bad_values_name_the_field() {
    let args = |k: &'static str| {
        [
            "single",
            "--a",
            "0.1",
            "--b",
            "0.13",
            "--d",
            "0.2",
            "--method",
            "hankel",
            "--corner-terms",
            k,
            "--json",
        ]
    };
    // modes only miss the default 1e-6 here: printed, flagged, exit 3
    let out = common::boltzone(&args("0"));
    assert_eq!(out.status.code(), Some(3));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["converged"], false);
    let load = FaceLoad::uniform(0.1, 0.13, 1.0).unwrap();
    let plate = SinglePlate::new(
        0.1,
        OuterRadius::Infinite,
        0.2,
        Material::unit(0.3).unwrap(),
        load,
    )
    .unwrap();
    let params = HoleParams {
        corner_terms: 0,
        ..HoleParams::default()
    };
    let (sep, hole) = single_plate_separation(&plate, &Default::default(), &params).unwrap();
    assert_eq!(v["hole_corner_terms"].as_u64(), Some(0));
    assert_eq!(v["r_o"].as_f64().unwrap(), sep.r_o);
    assert_eq!(v["hole_terms"].as_u64().unwrap() as usize, hole.terms);
    // the default (enriched) run differs from the modes-only one, within both estimates
    let e = common::json_of(&common::boltzone(&args("3")));
    assert_eq!(e["hole_corner_terms"].as_u64(), Some(3));
    let diff = (e["r_o"].as_f64().unwrap() - sep.r_o).abs();
    assert!(diff > 0.0 && diff <= e["r_o_error"].as_f64().unwrap() + sep.r_o_error);
    let bad = common::boltzone(&args("7"));
    assert!(!bad.status.success());
    let msg = String::from_utf8_lossy(&bad.stderr);
    assert!(msg.contains("--corner-terms") && msg.contains('7'), "{msg}");
}
