//! The near tables (`boltzone::table::near`, two plates and the single plate) against fresh
//! 1e-8 solves that did not build them, their domain, and the tables through the command line
//! and a scene (`method = "table"`).

use crate::common::{boltzone, json_of};
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::numerics::random::SplitMix64;
use boltzone::table::near::{self, A_MAX, A_MIN, W_MAX, W_MIN};
use boltzone::table::Model;
use boltzone::{FaceLoad, InputError, Material, OuterRadius, SinglePlate};

/// R_o and its estimate of `model`'s holed route at 1e-8, D = 1 (the single plate with its
/// slab data to 1e-9 P: the route layer's knobs stop at 1e-8 P).
fn route(model: Model, a: f64, w: f64, nu: f64) -> (f64, f64) {
    let load = FaceLoad::uniform(a, a + w, 1.0).unwrap();
    let p = SinglePlate::new(
        a,
        OuterRadius::Infinite,
        1.0,
        Material::unit(nu).unwrap(),
        load,
    )
    .unwrap();
    match model {
        Model::TwoPlates => {
            let (h, _) = two_plate_hole_to(&p, 1e-8, &[]).unwrap();
            (h.r_o, h.info.r_o_error)
        }
        Model::SinglePlate => {
            let (search, hole) = boltzone::route::single_plate::hankel_params(1e-8);
            let hole = HoleParams {
                slab_tolerance: 1e-9,
                ..hole
            };
            let (s, _) = single_plate_separation(&p, &search, &hole).unwrap();
            (s.r_o, s.r_o_error)
        }
    }
}

#[test]
fn the_near_tables_hold_their_bars_on_fresh_random_solves() {
    // random points (a seed of their own, not the validations'): two per model keep CI at
    // four solves; the held-out files below are the study
    let mut rng = SplitMix64::new(2026);
    for model in [
        Model::TwoPlates,
        Model::TwoPlates,
        Model::SinglePlate,
        Model::SinglePlate,
    ] {
        let a = rng.log_uniform(A_MIN, A_MAX);
        let w = rng.log_uniform(W_MIN, W_MAX);
        let nu = 0.5 * rng.unit();
        let t = near::separation_radius(model, a, a + w, 1.0, nu, 1e-3).unwrap();
        let (r, e) = route(model, a, w, nu);
        assert!(
            (t.value - r).abs() <= t.error + e,
            "{model:?} A/D {a} w {w} ν {nu}: table {} ± {:.1e}, route {r} ± {e:.1e}",
            t.value,
            t.error
        );
    }
}

/// Every held-out solve of `file` (reference/tables/, made by example 27 `validate`, none of
/// them a build sample) within `model`'s table's bar plus the solve's own estimate; returns
/// the number of points.
fn held_out(model: Model, file: &str) -> usize {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("reference/tables")
        .join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let mut n = 0;
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('a'))
    {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let (a, w, nu, r_o, e) = (v[0], v[1], v[2], v[3], v[4]);
        let t = near::separation_radius(model, a, a + w, 1.0, nu, 1e-3).unwrap();
        let ratio = (t.value - r_o).abs() / (t.error + e);
        assert!(
            ratio <= 1.0,
            "{file}: A/D {a} w {w} ν {nu}: table {} ± {:.1e}, route {r_o} ± {e:.1e}",
            t.value,
            t.error
        );
        n += 1;
    }
    n
}

#[test]
fn the_near_tables_hold_their_bars_on_every_kept_held_out_solve() {
    assert_eq!(
        held_out(Model::TwoPlates, "near_heldout_seed202.csv"),
        10_000
    );
    assert_eq!(held_out(Model::TwoPlates, "near_heldout_1e-8.csv"), 1_600);
    assert_eq!(
        held_out(Model::SinglePlate, "near_single_heldout_1e-8.csv"),
        10_000
    );
}

#[test]
fn outside_the_near_table_the_error_names_the_ratio() {
    let field = |r: Result<boltzone::Value, InputError>| match r {
        Err(InputError::Parameter { field, .. }) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        field(near::separation_radius(
            Model::TwoPlates,
            5.0,
            6.0,
            1.0,
            0.3,
            1e-3
        )),
        "A/D (near table)"
    );
    assert_eq!(
        field(near::separation_radius(
            Model::TwoPlates,
            1.0,
            1.1,
            1.0,
            0.3,
            1e-3
        )),
        "(B − A)/D (near table)"
    );
    assert_eq!(
        field(near::separation_radius(
            Model::TwoPlates,
            1.0,
            2.0,
            1.0,
            0.55,
            1e-3
        )),
        "Poisson's ratio (near table)"
    );
}

#[test]
fn two_by_table_answers_verifies_and_refuses_a_rim_near_the_contact() {
    let out = boltzone(&[
        "two", "--a", "0.1", "--b", "0.22", "--d", "0.1", "--method", "table", "--tol", "1e-2",
        "--verify", "--json",
    ]);
    let j = json_of(&out);
    assert_eq!(j["method"], "table");
    assert_eq!(j["verify"]["within_bars"], true, "{j}");
    // Table 1's rim: the rim table's shift, verified by the holed route with the rim
    let rim = json_of(&boltzone(&[
        "two", "--a", "0.1", "--b", "0.22", "--d", "0.1", "--c", "1.54", "--method", "table",
        "--tol", "1e-2", "--verify", "--json",
    ]));
    assert_eq!(rim["method"], "table");
    assert_eq!(rim["verify"]["within_bars"], true, "{rim}");
    // a rim within 4 D of the contact edge: exit 2 naming --c
    let near = boltzone(&[
        "two", "--a", "0.1", "--b", "0.22", "--d", "0.1", "--c", "0.3", "--method", "table",
    ]);
    assert_eq!(near.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&near.stderr).contains("--c"));
}

#[test]
fn single_by_table_answers_as_the_hankel_route() {
    let run = |extra: &[&str]| {
        let mut args = vec![
            "single", "--a", "0.1", "--b", "0.22", "--d", "0.1", "--json",
        ];
        args.extend_from_slice(extra);
        boltzone(&args)
    };
    let table = json_of(&run(&["--method", "table", "--tol", "1e-4"]));
    let hankel = json_of(&run(&["--method", "hankel", "--tol", "1e-6"]));
    let auto = json_of(&run(&["--method", "auto", "--tol", "1e-4"]));
    assert_eq!(
        (table["method"].as_str(), auto["method"].as_str()),
        (Some("table"), Some("table"))
    );
    assert_eq!(table["converged"], true, "{table}");
    let (t, h) = (&table["r_o"], &hankel["r_o"]);
    let gap = (t.as_f64().unwrap() - h.as_f64().unwrap()).abs();
    let bars = table["r_o_error"].as_f64().unwrap() + hankel["r_o_error"].as_f64().unwrap();
    assert!(gap <= bars, "table {t} hankel {h}: {gap:e} > {bars:e}");
    // a curve asks a solver (a rim: tests/table/rim.rs)
    let curve = json_of(&run(&[
        "--method",
        "auto",
        "--tol",
        "1e-4",
        "--curve",
        "/dev/null",
    ]));
    assert_eq!(curve["method"], "hankel");
}

#[test]
fn a_scene_asks_for_the_tables() {
    let dir = std::env::temp_dir().join(format!("boltzone-near-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "model = \"two-plate\"\nmethod = \"table\"\ntolerance = 1e-2\n[hole]\nradius = 0.1\n\
         [load]\nouter_radius = 0.22\npressure = 1000.0\n[[plates]]\nthickness = 0.1\n",
    )
    .unwrap();
    let j = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
    assert_eq!(j["method"], "table", "{j}");
    // the single plate of the same joint, and with a rim inside its contact zone (refused
    // naming the key)
    let single = std::fs::read_to_string(&scene)
        .unwrap()
        .replace("two-plate", "single-plate");
    std::fs::write(&scene, &single).unwrap();
    let j = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
    assert_eq!(
        (j["method"].as_str(), j["converged"].as_bool()),
        (Some("table"), Some(true)),
        "{j}"
    );
    std::fs::write(
        &scene,
        single.replace("[hole]", "[joint]\nouter_radius = 0.25\n[hole]"),
    )
    .unwrap();
    let rim = boltzone(&["solve", scene.to_str().unwrap(), "--json"]);
    assert_eq!(rim.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&rim.stderr).contains("outer_radius"),
        "{rim:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
