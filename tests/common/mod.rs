//! Helpers shared by the integration-test crates (a crate's `main.rs` includes this with
//! `#[path = "../common/mod.rs"] mod common;`, its modules use `crate::common`).
#![allow(dead_code)]

use boltzone::hankel::Slab;
use boltzone::{FaceLoad, Material};
use std::process::{Command, Output};

/// The no-hole slab of half-thickness `d` under unit uniform pressure on `a ≤ r ≤ b`, ν = 0.3.
pub fn uniform_slab(a: f64, b: f64, d: f64) -> Slab {
    Slab::new(
        d,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(a, b, 1.0).unwrap(),
    )
    .unwrap()
}

/// Runs the `boltzone` binary with `args`.
pub fn boltzone(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .unwrap()
}

/// Panics with the run's stderr unless it succeeded.
pub fn succeeded(out: &Output) {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The JSON object a successful run printed (panics with its stderr otherwise).
pub fn json_of(out: &Output) -> serde_json::Value {
    succeeded(out);
    serde_json::from_slice(&out.stdout).unwrap()
}
