//! Runs the hole-correction example on a small size so it cannot go stale (its full run is the
//! convergence study).

#[allow(dead_code)]
#[path = "../examples/05_hole_correction_convergence.rs"]
mod ex05;

#[test]
fn hole_convergence_example_runs_small() {
    // N up to 16 (the modes-only rate fit then has two points, N = 8 and 16; the enriched one
    // N = 4…16 above the data's 1e-8 floor), Table 1's first two rows.
    ex05::run(16, 2).unwrap();
}
