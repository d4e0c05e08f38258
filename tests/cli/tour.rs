//! The user guide's "A short tour" (`docs/guide.md`) names every folder of the project once and no folder that is not
//! there: its table's first column is compared with the folders on disk (`src/` and its
//! subfolders, and the top-level folders a newcomer opens: `reference/`, `assets/`, `tests/`,
//! `examples/`, `benches/`, `docs/`). Its numbered-examples range is compared with `examples/` too, and
//! the sequence has no gap.

use std::collections::BTreeSet;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The tour table's folder column (`src/cli/`), without the `src/*.rs` row.
fn tour_folders() -> BTreeSet<String> {
    let text = std::fs::read_to_string(root().join("docs/guide.md")).unwrap();
    let start = text
        .find("## A short tour")
        .expect("the guide has a short tour");
    let section = &text[start..];
    let end = section[3..].find("\n## ").map_or(section.len(), |k| k + 3);
    section[..end]
        .lines()
        .filter_map(|l| l.strip_prefix("| `"))
        .filter_map(|l| l.split('`').next())
        .filter(|f| f.ends_with('/'))
        .map(|f| f.trim_end_matches('/').to_string())
        .collect()
}

fn folders_under(dir: &Path, prefix: &str, out: &mut BTreeSet<String>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let e = e.unwrap();
        if e.file_type().unwrap().is_dir() {
            let name = format!("{prefix}/{}", e.file_name().to_string_lossy());
            folders_under(&e.path(), &name, out);
            out.insert(name);
        }
    }
}

#[test]
fn tour_names_every_folder_once() {
    let mut on_disk = BTreeSet::new();
    folders_under(&root().join("src"), "src", &mut on_disk);
    for top in [
        "reference",
        "assets",
        "tests",
        "examples",
        "benches",
        "docs",
    ] {
        assert!(root().join(top).is_dir(), "{top}/ missing");
        on_disk.insert(top.to_string());
    }
    let tour = tour_folders();
    let missing: Vec<_> = on_disk.difference(&tour).collect();
    let stale: Vec<_> = tour.difference(&on_disk).collect();
    assert!(
        missing.is_empty(),
        "folders not in the guide's tour: {missing:?}"
    );
    assert!(stale.is_empty(), "tour rows with no folder: {stale:?}");
}

#[test]
fn examples_are_numbered_without_gaps_as_the_tour_says() {
    let mut numbers: Vec<u32> = std::fs::read_dir(root().join("examples"))
        .unwrap()
        .filter_map(|e| {
            let name = e.unwrap().file_name().to_string_lossy().into_owned();
            let stem = name.strip_suffix(".rs")?;
            stem.split('_').next()?.parse().ok()
        })
        .collect();
    numbers.sort_unstable();
    let expected: Vec<u32> = (1..=numbers.len() as u32).collect();
    assert_eq!(
        numbers, expected,
        "examples/NN_*.rs must run 01, 02, … without gaps"
    );
    let text = std::fs::read_to_string(root().join("docs/guide.md")).unwrap();
    let range = format!("numbered programs 01–{:02}", numbers.len());
    assert!(
        text.contains(&range),
        "the guide's tour should say \"{range}\""
    );
}
