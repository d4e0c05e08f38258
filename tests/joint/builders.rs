//! Joints and command lines that several of this crate's tests build.

use boltzone::{FaceLoad, Joint, Material, OuterRadius};
use std::f64::consts::PI;

/// Two equal plates `d` thick of `material`, the head's unit pressure on A..B₁, the nut's face
/// A..B₂ carrying the same force; outer radius `c` (None: infinite).
pub fn own_faces(a: f64, b1: f64, b2: f64, d: f64, c: Option<f64>, material: Material) -> Joint {
    let j = Joint::symmetric(a, b1, d, material).unwrap();
    let j = match c {
        Some(c) => j.with_outer_radius(OuterRadius::Finite(c)).unwrap(),
        None => j,
    };
    let nut = FaceLoad::uniform(a, b2, j.load().total_force() / (PI * (b2 * b2 - a * a)));
    let own = j.clone().with_nut_load(nut.unwrap()).unwrap();
    // (the library's shorthand builds the same joint)
    assert_eq!(j.with_nut_outer_radius(b2).unwrap(), own);
    own
}

/// `two` in `units` on two equal plates `d` thick, outer radius `c`, modulus `e`, followed by
/// `rest`.
pub fn two_line<'a>(units: &'a str, [d, c, e]: [&'a str; 3], rest: &[&'a str]) -> Vec<&'a str> {
    let mut line = vec!["two", "--units", units, "--d", d, "--c", c, "--e", e];
    line.extend(rest);
    line
}
