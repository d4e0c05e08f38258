//! `boltzone deck` (issue 12): the guide's commands, the JSON contract, `--emit` → run round
//! trip through files, and the exit codes (2 with line, columns and field on a bad deck).

use crate::common::boltzone;

#[test]
fn readme_command_runs_the_example_decks() {
    // the guide, "1970 card decks": its first command, and that the guide still holds it
    let readme = std::fs::read_to_string("docs/guide.md").unwrap();
    assert!(readme.contains("cargo run --release -- deck tests/data/decks/ring.deck "));
    let out = boltzone(&["deck", "tests/data/decks/ring.deck"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("END OF JOB (2 decks)"));
    assert!(text.contains("SIG(R)") && text.contains("[F/L^2]"));
    // the held ring's σ_r = σ_θ = −E α ΔT/(1 − ν) = −1.5e7·1.5e-5·100/0.75 = −3e4
    assert!(text.contains("-3.0000e4"), "{text}");
}

#[test]
fn json_contract_and_emit_round_trip() {
    let dir = std::env::temp_dir().join(format!("boltzone_deck_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("plate.deck");
    let p = path.to_str().unwrap();
    let out = boltzone(&[
        "deck", "--emit", p, "--a", "0.1", "--b", "0.31", "--c", "0.7", "--d", "0.1", "--p", "1000",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = boltzone(&["deck", p, "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let deck = &v["decks"][0];
    assert!(deck["title"].as_str().unwrap().starts_with("SINGLE PLATE"));
    for key in ["n", "r", "z", "u", "w"] {
        assert!(deck["nodes"][0][key].is_number(), "{key}");
    }
    for key in ["n", "r", "z", "sigma_r", "sigma_z", "sigma_t", "tau_rz"] {
        assert!(deck["elements"][0][key].is_number(), "{key}");
    }
    // element 4 is the top one of the first column, under the face pressure: compressive
    assert!(deck["elements"][3]["sigma_z"].as_f64().unwrap() < 0.0);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_decks_and_flags_exit_2_naming_line_and_field() {
    let dir = std::env::temp_dir().join(format!("boltzone_deck_bad_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.deck");
    let good = std::fs::read_to_string("tests/data/decks/ring.deck").unwrap();
    std::fs::write(
        &path,
        good.replace(
            "    1    1    2    5    4    1",
            "    1    1    2    5    X    1",
        ),
    )
    .unwrap();
    let out = boltzone(&["deck", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("line 10, columns 21-25 (element node L = \"X\")"),
        "{err}"
    );
    // an Appendix B deck read as Appendix D: its first bad card is named
    let out = boltzone(&["deck", "tests/data/decks/ring.deck", "--appendix", "d"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("line "));
    let out = boltzone(&[
        "deck",
        "--emit",
        dir.join("no/such/dir.deck").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn appendix_d_decks_run_through_the_deck_command() {
    // the same file with the format given and detected
    let path = "tests/data/decks/chain_d.deck";
    let text = std::fs::read_to_string(path).unwrap();
    let library = boltzone::heat::deck::parse_network_decks(&text).unwrap();
    for args in [
        vec!["deck", path, "--json"],
        vec!["deck", path, "--appendix", "d", "--json"],
    ] {
        let out = boltzone(&args);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let decks = v["decks"].as_array().unwrap();
        assert_eq!(decks.len(), library.len());
        for (d, lib) in decks.iter().zip(&library) {
            let solved = lib.solve().unwrap();
            assert_eq!(d["title"], lib.title.as_str());
            assert!(d["residual"].as_f64().unwrap().is_finite());
            let nodes = d["nodes"].as_array().unwrap();
            assert_eq!(nodes.len(), lib.network.n());
            let want = serde_json::to_value(&solved).unwrap();
            for (k, n) in nodes.iter().enumerate() {
                assert_eq!(n["n"].as_u64(), Some(k as u64 + 1));
                assert_eq!(n["t"], want["nodes"][k]["t"]);
            }
        }
    }
}
