//! One question, one answer: the same joint through different front ends gets the same numbers
//! from the route layer, bit for bit where the inputs are the same numbers — `two` and
//! `table1`'s row, `two` and a scene in each unit system, the scene of Table 1's first row and
//! `table1`'s — and the scene of Table 1's first
//! row asked to 1e-5 and 1e-6 answers through the default route (`auto`, the semi-analytic
//! route below the finite elements' 2e-5 floor).

use crate::common::{boltzone, json_of};
use serde_json::Value;

/// `r_o`, `r_o_error` and each rule's radius and error of an answer, as bits.
fn fingerprint(r_o: &Value, r_o_error: &Value, rules: &Value) -> Vec<u64> {
    let mut v = vec![
        r_o.as_f64().unwrap().to_bits(),
        r_o_error.as_f64().unwrap().to_bits(),
    ];
    for r in rules.as_array().unwrap() {
        v.push(r["radius"].as_f64().unwrap().to_bits());
        v.push(r["error_percent"]["value"].as_f64().unwrap().to_bits());
        v.push(r["error_percent"]["error"].as_f64().unwrap().to_bits());
    }
    v
}

#[test]
fn two_and_table1_give_the_same_bits() {
    let rows = json_of(&boltzone(&["table1", "--json"]));
    // the first and the last row (thick and thin plates)
    for row in [&rows[0], &rows[11]] {
        let ours = &row["ours"];
        let g = &ours["geometry"];
        let f = |k: &str| g[k].as_f64().unwrap().to_string();
        let (a, b, d, c, nu) = (f("a"), f("b"), f("d"), f("c"), f("nu"));
        let two = json_of(&boltzone(&[
            "two", "--a", &a, "--b", &b, "--d", &d, "--c", &c, "--nu", &nu, "--method", "fem",
            "--json",
        ]));
        // table1's route (the FE: `two`'s auto would answer from the tables)
        let t = &ours["two"];
        assert_eq!(
            fingerprint(&two["r_o"], &two["r_o_error"], &two["rules"]),
            fingerprint(&t["value"], &t["error"], &ours["rules"]),
            "{g}"
        );
        assert_eq!(two["method"], ours["two_method"], "{g}");
    }
}

/// An M8 bolt through two 6 mm aluminium plates in each unit system: (units, A, B, D, C, E,
/// force), the numbers a user types in that system (not conversions of each other).
const M8_JOINTS: [[&str; 7]; 3] = [
    [
        "in-psi-lbf",
        "0.177",
        "0.256",
        "0.236",
        "1.575",
        "1.0e7",
        "2248",
    ],
    ["mm-MPa-N", "4.5", "6.5", "6", "40", "70000", "10000"],
    [
        "m-Pa-N", "0.0045", "0.0065", "0.006", "0.04", "7.0e10", "10000",
    ],
];

/// `two` and a scene with the same numbers in the same unit system solve the same
/// floating-point joint (a scene solves in its own units): the same bits in every system, by
/// each route (the finite elements with a rim, the tables and the semi-analytic route of an
/// infinite joint), with the modulus given and taken from the library by name.
#[test]
fn two_and_a_scene_in_the_same_units_give_the_same_bits() {
    let dir = std::env::temp_dir().join(format!("boltzone-one-question-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for [units, a, b, d, c, e, force] in M8_JOINTS {
        // (the scene's [joint] and material, two's flags, the tolerance)
        let cases: [(String, Vec<&str>, &str); 3] = [
            (
                format!("[[plates]]\nthickness = {d}\nmaterial = {{ E = {e}, nu = 0.33 }}\n[joint]\nouter_radius = {c}\n"),
                vec!["--c", c, "--e", e, "--nu", "0.33"],
                "5e-4",
            ),
            (
                format!("[[plates]]\nthickness = {d}\nmaterial = \"aluminium-6061-t6\"\n"),
                vec!["--material", "aluminium-6061-t6"],
                "5e-4",
            ),
            (
                format!("[[plates]]\nthickness = {d}\nmaterial = \"aluminium-6061-t6\"\n"),
                vec!["--material", "aluminium-6061-t6"],
                "1e-6",
            ),
        ];
        for (plates, flags, tol) in cases {
            let scene = dir.join("joint.toml");
            std::fs::write(
                &scene,
                format!(
                    "units = \"{units}\"\nmodel = \"two-plate\"\ntolerance = {tol}\n\
                     [hole]\nradius = {a}\n[load]\nouter_radius = {b}\nforce = {force}\n{plates}"
                ),
            )
            .unwrap();
            let solve = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
            let mut line = vec![
                "two", "--units", units, "--a", a, "--b", b, "--d", d, "--force", force, "--tol",
                tol, "--json",
            ];
            line.extend(&flags);
            let two = json_of(&boltzone(&line));
            let what = format!("{units} {flags:?} tol {tol}: method {}", two["method"]);
            assert_eq!(
                fingerprint(&two["r_o"], &two["r_o_error"], &two["rules"]),
                fingerprint(&solve["r_o"], &solve["r_o_error"], &solve["rules"]),
                "{what}"
            );
            assert_eq!(two["method"], solve["method"], "{what}");
            assert_eq!(two["converged"], solve["converged"], "{what}");
            assert_eq!(two["nut_deflection"], solve["nut_deflection"], "{what}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A scene of `table1`'s first and last rows' geometry (in inches, its numbers as `table1 --json`
/// prints them: C = 15.4 A is 1.5400000000000003 in) and `table1`'s row: the same bits.
#[test]
fn table1_rows_and_their_scenes_give_the_same_bits() {
    let rows = json_of(&boltzone(&["table1", "--json"]));
    let dir = std::env::temp_dir().join(format!("boltzone-table1-scene-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for row in [&rows[0], &rows[11]] {
        let ours = &row["ours"];
        let g = &ours["geometry"];
        let f = |k: &str| g[k].as_f64().unwrap().to_string();
        let scene = dir.join("row.toml");
        std::fs::write(
            &scene,
            format!(
                "model = \"two-plate\"\nmethod = \"fem\"\n[hole]\nradius = {}\n[load]\nouter_radius = {}\n\
                 pressure = 1000.0\n[[plates]]\nthickness = {}\n\
                 material = {{ E = 28.0e6, nu = {} }}\n[joint]\nouter_radius = {}\n",
                f("a"),
                f("b"),
                f("d"),
                f("nu"),
                f("c")
            ),
        )
        .unwrap();
        let solve = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
        let t = &ours["two"];
        assert_eq!(
            fingerprint(&solve["r_o"], &solve["r_o_error"], &solve["rules"]),
            fingerprint(&t["value"], &t["error"], &ours["rules"]),
            "{g}"
        );
        assert_eq!(solve["method"], ours["two_method"], "{g}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn table1_row1_scene_at_1e5_and_1e6_answers_through_the_default_route() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("examples/scenes/table1_row1.toml"))
        .unwrap()
        .replace("method = \"auto\"\n", "");
    let dir = std::env::temp_dir().join(format!("boltzone-row1-tight-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // at 1e-5 the tables' bar (the rim table's shift included) meets it, at 1e-6 the route
    for (tol, method) in [("1e-5", "table"), ("1e-6", "hankel")] {
        let path = dir.join(format!("row1_{tol}.toml"));
        std::fs::write(
            &path,
            text.replace("tolerance = 5e-4", &format!("tolerance = {tol}")),
        )
        .unwrap();
        let out = boltzone(&["solve", path.to_str().unwrap(), "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{tol}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v = json_of(&out);
        assert_eq!(v["method"], method, "{tol}");
        let tol: f64 = tol.parse().unwrap();
        assert!(v["r_o_error"].as_f64().unwrap() <= tol * v["r_o"].as_f64().unwrap());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn materials_by_name_on_two_equal_a_scene_with_those_names() {
    let dir = std::env::temp_dir().join(format!("boltzone-named-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("joint.toml");
    // steel over aluminium: the scene looks the names up itself
    std::fs::write(
        &scene,
        "units = \"m-Pa-N\"\n[hole]\nradius = 0.0045\n[load]\nouter_radius = 0.0065\n\
         force = 10000.0\n[[plates]]\nthickness = 0.006\nmaterial = \"steel-1018\"\n\
         [[plates]]\nthickness = 0.006\nmaterial = \"aluminium-6061-t6\"\n\
         [joint]\nouter_radius = 0.04\n",
    )
    .unwrap();
    let solve = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
    let two = json_of(&boltzone(&[
        "two",
        "--units",
        "m-Pa-N",
        "--a",
        "0.0045",
        "--b",
        "0.0065",
        "--d",
        "0.006",
        "--c",
        "0.04",
        "--material",
        "steel-1018",
        "--material2",
        "aluminium-6061-t6",
        "--force",
        "10000",
        "--json",
    ]));
    assert_eq!(
        fingerprint(&two["r_o"], &two["r_o_error"], &two["rules"]),
        fingerprint(&solve["r_o"], &solve["r_o_error"], &solve["rules"])
    );
    // the E and ν the CLI took are the ones `boltzone materials --json` lists
    let lib = json_of(&boltzone(&["materials", "--json"]));
    let find = |n: &str| {
        lib["materials"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["name"] == n)
            .cloned()
            .unwrap()
    };
    let (steel, al) = (find("steel-1018"), find("aluminium-6061-t6"));
    assert_eq!(two["inputs"]["e"], steel["youngs_modulus"]);
    assert_eq!(two["inputs"]["nu"], steel["poisson_ratio"]);
    assert_eq!(two["inputs"]["e2"], al["youngs_modulus"]);
    assert_eq!(two["inputs"]["nu2"], al["poisson_ratio"]);
    std::fs::remove_dir_all(&dir).unwrap();
    for (args, flag) in [
        (vec!["--material", "unobtainium"], "--material"),
        (vec!["--material2", "steel"], "--material2"),
    ] {
        let mut a = vec!["two", "--a", "0.1", "--b", "0.31", "--d", "0.1"];
        a.extend(args);
        let out = boltzone(&a);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(flag) && err.contains("steel-304"), "{err}");
    }
    let out = boltzone(&[
        "two",
        "--a",
        "0.1",
        "--b",
        "0.31",
        "--d",
        "0.1",
        "--material",
        "steel-304",
        "--e",
        "1e7",
    ]);
    assert_eq!(out.status.code(), Some(2));
}
