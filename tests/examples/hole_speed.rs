//! Runs example 14 (time against achieved R_o error, profile vs direct slab sampling) on a small
//! size so it cannot go stale; it checks itself (every actual error within its estimate plus
//! the reference's uncertainty, the two routes' R_o within their data errors).

#[allow(dead_code)]
#[path = "../examples/14_hole_speed.rs"]
mod ex17;

#[test]
fn hole_speed_example_runs_small() {
    // Table 1's first two rows, reference N = 32 (from 16), one timing each.
    ex17::run(2, 16, 1).unwrap();
}
