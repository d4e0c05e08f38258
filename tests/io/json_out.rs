//! The provenance every `--json` object carries: `version` (the crate's), `units`
//! (`in-psi-lbf`), `command`, `inputs` (the arguments as understood, defaults filled in) and
//! `seconds` (a scene's result: its own units and inputs; a sweep's wrapper: version, command,
//! seconds); the R_o commands keep `r_o`, `r_o_error` and `converged`. Defaults are checked
//! against the values `--help` documents (E = 28e6 psi, ν = 0.3, --tol 5e-4 for `two`, 1e-10 for
//! `slab`, 1e-6 for `single --method hankel`).

use crate::common::{boltzone, json_of};
use serde_json::Value;

fn stamped(line: &str) -> Value {
    let args: Vec<&str> = line.split_whitespace().collect();
    let v = json_of(&boltzone(&args));
    assert_eq!(v["version"], env!("CARGO_PKG_VERSION"), "{line}");
    assert_eq!(v["units"], "in-psi-lbf", "{line}");
    assert!(v["command"].as_str().unwrap().contains(args[0]), "{line}");
    assert!(v["inputs"].is_object(), "{line}");
    assert!(v["seconds"].as_f64().unwrap() >= 0.0, "{line}");
    v
}

#[test]
fn every_json_object_carries_version_units_inputs_and_timing() {
    let g = "--a 0.1 --b 0.31 --d 0.1";
    for (line, tol) in [
        (format!("slab {g} --json"), 1e-10),
        (format!("single {g} --c 1.54 --json"), 5e-4),
        (format!("single {g} --method hankel --json"), 1e-6),
        (format!("two {g} --c 1.54 --json"), 5e-4),
    ] {
        let v = stamped(&line);
        for key in ["r_o", "r_o_error"] {
            assert!(v[key].as_f64().unwrap() > 0.0, "{line}: {key}");
        }
        assert!(v["converged"].is_boolean(), "{line}");
        let inputs = &v["inputs"];
        assert_eq!(inputs["a"], 0.1);
        assert_eq!(inputs["b"], 0.31);
        assert_eq!(inputs["nu"], 0.3, "{line}: the default ν filled in");
        // the tolerance as understood: the command's default (single: per method)
        assert_eq!(inputs["tol"], tol, "{line}");
        if line.starts_with("two") {
            assert_eq!(inputs["e"], 28e6);
            assert_eq!(inputs["interface"], "frictionless");
            assert_eq!(inputs["element"], "q9");
        }
    }
    // a scene carries its own units and inputs; a sweep's wrapping object the version
    let scenes = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes");
    let v = stamped(&format!("solve {scenes}/table1_row1.toml --json"));
    assert!(v["r_o"].as_f64().unwrap() > 0.0 && v["converged"].is_boolean());
    let args = [
        "solve",
        &format!("{scenes}/m8_aluminium_sweep.toml"),
        "--json",
    ]
    .map(String::from);
    let v = json_of(&boltzone(
        &args.iter().map(String::as_str).collect::<Vec<_>>(),
    ));
    assert_eq!(v["version"], env!("CARGO_PKG_VERSION"));
    assert!(v["command"].as_str().unwrap().contains("solve"));
    assert!(v["seconds"].as_f64().unwrap() >= 0.0 && v["results"].is_array());
    // an Appendix B/C deck and an Appendix D (conductance network) deck
    for name in ["ring.deck", "chain_d.deck"] {
        let deck = format!("{}/tests/data/decks/{name}", env!("CARGO_MANIFEST_DIR"));
        let v = stamped(&format!("deck {deck} --json"));
        assert!(v["decks"].is_array());
        assert_eq!(v["inputs"]["file"], deck.as_str());
    }
}
