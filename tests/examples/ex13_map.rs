//! Example 13's `map` mode on its quick map: the 3 × 1 map (A/D 0.5, 1, 2 at B/A 2.2) by the FE
//! and by the Hankel routes. The example fails itself if a converged value's estimate exceeds the
//! tolerance or if the FE and Hankel values of a model differ by more than the sum of their
//! estimates (the two routes share no code).

#[test]
fn ex13_map_by_method_fe_and_hankel_agree_within_their_estimates() {
    let (single, two) = super::ex13::by_method(&[0.5, 1.0, 2.0], &[2.2], 1e-3, false).unwrap();
    assert!(single > 0.0 && single <= 1.0, "single plate: {single}");
    assert!(two > 0.0 && two <= 1.0, "two plates: {two}");
}
