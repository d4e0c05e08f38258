//! Scene files (`boltzone::scene`, `boltzone solve`): the example scenes against the library
//! calls they wrap, one joint in three unit systems, located errors, and seeded mutated scenes.

#[path = "../common/mod.rs"]
mod common;

mod builder;
mod chapter6;
mod command_units;
mod errors;
mod examples;
mod field;
mod from_heat;
mod fuzz;
mod guide_keys;
mod heat;
mod joint_units;
mod outputs;
mod temperature;
mod thermal_single;
mod two_hankel;
mod two_hankel_no_hole;
mod units;

use std::path::PathBuf;

/// The text of `examples/scenes/NAME.toml`.
pub fn example(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/scenes")
        .join(format!("{name}.toml"));
    std::fs::read_to_string(&path).unwrap()
}

/// A fresh empty directory under the target directory for one test's files.
pub fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("scene_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
