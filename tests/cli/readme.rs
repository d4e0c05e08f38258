//! Every `boltzone …` and `cargo run --release -- …` command in the ```sh blocks of README.md
//! and of every page of the guide (`docs/*.md`) runs and exits 0, in a temporary directory (so the files it writes land there); the README's
//! placeholder inputs (`scene.toml`, `rows.csv`) are made from Table 1's first row. Skipped with
//! a note: `cargo test`, `cargo install`, `cargo bench`, `bash .ci/run`, `serve` (a server that
//! runs until stopped: `tests/figures/server.rs`) and the examples (each example runs at its
//! quick size in `tests/examples/`). Only `map`'s grid is made smaller
//! (`--n 4`): its 16 points took 1.0 s here, so the README's 1600 would take about 100 s, and
//! they are the same solver as `two`. A README line that is none of these fails the test, so
//! that new commands are run too.

use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// The command lines of the ```sh blocks of README.md and every page of docs/, without comments
/// and blank lines.
fn readme_commands() -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![dir.join("README.md")];
    let mut docs: Vec<_> = std::fs::read_dir(dir.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    let text = files
        .iter()
        .map(|f| std::fs::read_to_string(f).unwrap())
        .collect::<Vec<_>>()
        .join("\n");
    let mut out = Vec::new();
    let mut inside = false;
    for line in text.lines() {
        let t = line.trim();
        if t.starts_with("```") {
            inside = !inside && t == "```sh";
            continue;
        }
        if !inside || t.is_empty() || t.starts_with('#') {
            continue;
        }
        let cmd = match t.find(" #") {
            Some(k) => t[..k].trim(),
            None => t,
        };
        out.push(cmd.to_string());
    }
    out
}

/// The arguments of `boltzone` for a README line, or None (with the reason) for a line that
/// is not run here.
fn boltzone_args(line: &str) -> Result<Vec<String>, &'static str> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let rest = match words.as_slice() {
        ["cargo", "run", "--release", "--", "serve", ..] | ["boltzone", "serve", ..] => {
            return Err("a server that runs until stopped (tests/figures/server.rs)")
        }
        ["boltzone", rest @ ..] => rest,
        ["cargo", "run", "--release", "--", rest @ ..] => rest,
        ["cargo", "run", "--release"] => &[],
        ["cargo", "run", "--release", "--example", ..] => {
            return Err("an example (run at its quick size by tests/examples)")
        }
        ["cargo", "test", ..] => return Err("the test suite itself"),
        ["cargo", "install", ..] => return Err("installs into ~/.cargo/bin"),
        ["cargo", "bench", ..] => return Err("a benchmark (minutes)"),
        ["bash", ".ci/run", ..] => return Err("the CI script"),
        ["python", ..] => return Err("a Python command (python/tests/test_docs.py runs it)"),
        _ => panic!("README line neither run nor skipped by tests/cli/readme.rs: {line}"),
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut args: Vec<String> = rest
        .iter()
        .map(|a| {
            // the repository's files (a deck) by their absolute path
            let p = root.join(a);
            if !a.starts_with('-') && a.contains('/') && p.is_file() {
                p.display().to_string()
            } else {
                a.to_string()
            }
        })
        .collect();
    if args.first().map(String::as_str) == Some("map") {
        if let Some(k) = args.iter().position(|a| a == "--n") {
            args[k + 1] = "4".into();
        }
    }
    Ok(args)
}

#[test]
fn every_readme_command_runs() {
    let dir = std::env::temp_dir().join(format!("boltzone-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // the README's placeholders for the user's own files: Table 1's first row as `scene.toml`
    // and two bearing radii as `rows.csv`
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::copy(
        root.join("examples/scenes/table1_row1.toml"),
        dir.join("scene.toml"),
    )
    .unwrap();
    std::fs::write(dir.join("rows.csv"), "load.outer_radius\n0.31\n0.35\n").unwrap();
    let commands = readme_commands();
    assert!(commands.len() > 20, "README's sh blocks: {commands:?}");
    let mut ran = 0;
    for line in &commands {
        let args = match boltzone_args(line) {
            Ok(a) => a,
            Err(why) => {
                eprintln!("skipped: {line}  ({why})");
                continue;
            }
        };
        let t0 = Instant::now();
        let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
            .args(&args)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "README: {line}\nexit {:?}\n{}",
            out.status.code(),
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(!out.stdout.is_empty() || !out.stderr.is_empty(), "{line}");
        eprintln!("ran in {:.2} s: {line}", t0.elapsed().as_secs_f64());
        ran += 1;
    }
    assert!(ran >= 20, "only {ran} README commands ran");
    // what the README says the commands write
    for f in [
        "mid.csv",
        "pair.csv",
        "pair.vtu",
        "single.csv",
        "single.vtu",
        "plate.deck",
    ] {
        assert!(dir.join(f).is_file(), "{f} was not written");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
