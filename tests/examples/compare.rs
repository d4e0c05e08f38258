//! Runs example 07 (why the 45° rule overpredicts contact; it checks itself: equilibrium of both
//! models, complementarity, the curve's zero against R_o, the ordering of the radii) and checks
//! the figures it writes are a PNG and an SVG. Runs example 13 (design-map speed) on five map
//! points: both models' error estimates hold against tight references.

#[path = "../examples/07_teach_45_degree_rule.rs"]
mod ex07;

#[test]
fn example_07_teaches_the_45_degree_rule() {
    let dir = std::env::temp_dir().join(format!("boltzone_ex07_{}", std::process::id()));
    let s = ex07::run(&dir).unwrap();
    assert!(s.two < s.single && s.single < s.cone45);
    let png = std::fs::read(&s.files[1]).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let svg = std::fs::read_to_string(&s.files[0]).unwrap();
    assert!(svg.contains("<svg") && svg.contains("45° rule"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[path = "../examples/13_map_speed.rs"]
#[allow(dead_code)]
mod ex17;

#[test]
fn map_error_estimates_cover_the_actual_errors_at_the_corners_and_a_table1_point() {
    // Example 13 fails itself if an estimate exceeds the tolerance or an actual error (against
    // a run converged 50 times tighter) exceeds its estimate plus the reference's estimate.
    // The four corners of the map's range and Table 1's narrowest load (A/D 1, B/A 1.3, where
    // Richardson steps once went wrong).
    let points = [(0.2, 1.1), (0.2, 5.0), (5.0, 1.1), (5.0, 5.0), (1.0, 1.3)];
    let runs = ex17::run(&points, 1e-3).unwrap();
    for r in &runs {
        for m in [r.single, r.two] {
            assert!(m.estimate <= 1e-3 && m.actual <= m.estimate + m.reference_estimate);
            assert!(m.levels >= 3);
        }
    }
}
