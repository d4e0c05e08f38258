//! Every scene key the parser takes is in the user guide's "Scene keys" table with a unit
//! column and a default column (`docs/guide.md`). The keys are not listed here: the parser names
//! them itself, in the error it gives for an unknown key in each table (serde's "expected one of
//! …"), so a key added to `src/scene/` without a guide row fails this test.

use boltzone::scene::Scene;
use std::collections::BTreeMap;

/// The guide's scene-key rows: key → (unit, default).
fn guide_rows() -> BTreeMap<String, (String, String)> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/guide.md");
    let text = std::fs::read_to_string(path).unwrap();
    let start = text
        .find("## Scene keys")
        .expect("the guide has a Scene keys section");
    let section = &text[start..];
    let end = section[3..].find("\n## ").map_or(section.len(), |k| k + 3);
    section[..end]
        .lines()
        .filter_map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            let key = cells.get(1)?.strip_prefix('`')?.strip_suffix('`')?;
            Some((
                key.to_string(),
                (cells.get(2)?.to_string(), cells.get(3)?.to_string()),
            ))
        })
        .collect()
}

/// The keys the parser names for the table at `prefix` (`""` for the top level), read from the
/// error an unknown key there gives.
fn parser_keys(table_header: &str) -> Vec<String> {
    let text = format!("{table_header}zzz_not_a_key = 1\n");
    let err = Scene::parse(&text).unwrap_err().to_string();
    let expected = err
        .split_once("expected")
        .unwrap_or_else(|| panic!("{table_header}: {err}"))
        .1;
    expected
        .split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

#[test]
fn every_scene_key_is_in_the_guide_with_its_unit_and_default() {
    let rows = guide_rows();
    let tables = [
        ("", ""),
        ("[hole]\n", "hole."),
        ("[load]\n", "load."),
        ("[[plates]]\n", "plates[i]."),
        ("[joint]\n", "joint."),
        ("[outputs]\n", "outputs."),
        ("[heat]\n", "heat."),
        ("[temperature]\n", "temperature."),
        ("[bolt]\n", "bolt."),
        ("[washer]\n", "washer."),
        ("[preload]\n", "preload."),
    ];
    let mut checked = 0;
    for (header, prefix) in tables {
        let keys = parser_keys(header);
        assert!(!keys.is_empty(), "{header}");
        for k in keys {
            let full = format!("{prefix}{k}");
            // a table at the top level is documented by its keys (hole.radius, …)
            let is_table =
                prefix.is_empty() && rows.keys().any(|r| r.starts_with(&format!("{k}.")));
            let is_array =
                prefix.is_empty() && rows.keys().any(|r| r.starts_with(&format!("{k}[i].")));
            if is_table || is_array {
                continue;
            }
            let (unit, default) = rows.get(&full).unwrap_or_else(|| {
                panic!("scene key `{full}` is not in docs/guide.md's Scene keys")
            });
            assert!(!unit.is_empty(), "`{full}`: no unit in the guide");
            assert!(!default.is_empty(), "`{full}`: no default in the guide");
            checked += 1;
        }
    }
    // the parser knows 35 leaf keys today; fewer would mean a table was not read
    assert!(checked >= 30, "only {checked} keys checked");
}
