//! Runs example 07 (why the 45° rule overpredicts contact; it checks itself: equilibrium of both
//! models, complementarity, the curve's zero against R_o, the ordering of the radii) and checks
//! the figures it writes are a PNG and an SVG.

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
