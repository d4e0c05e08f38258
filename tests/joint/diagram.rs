//! The joint diagram (`two --bolt … --plot FILE` → FILE-joint, a scene's `[outputs] plot` with
//! a `[bolt]`): its numbers against the run's JSON, and the two front ends' figures equal.

use crate::common::{boltzone, json_of};

/// The first number after `key` in `text`.
fn number_after(text: &str, key: &str) -> f64 {
    let at = text
        .find(key)
        .unwrap_or_else(|| panic!("no {key:?} in the figure"))
        + key.len();
    let tail: String = text[at..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || ".e-+".contains(*c))
        .collect();
    tail.parse()
        .unwrap_or_else(|e| panic!("{tail:?} after {key:?}: {e}"))
}

#[test]
fn the_m10_joint_diagram_shows_its_preload_compliances_and_load_factor() {
    let dir = std::env::temp_dir().join(format!("boltzone-diagram-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plot = dir.join("m10.svg");
    let mut line = crate::front_ends::LINE.to_vec();
    line.extend(["--plot", plot.to_str().unwrap()]);
    let v = json_of(&boltzone(&line));
    let svg = std::fs::read_to_string(dir.join("m10-joint.svg")).unwrap();
    let (f_m, d_s) = (
        v["preload"].as_f64().unwrap(),
        v["bolt_compliance"].as_f64().unwrap(),
    );
    let phi = v["load_factor"]["value"].as_f64().unwrap();
    let d_p = v["member_compliance"]["value"].as_f64().unwrap();
    // the route layer's Φ (its own δ_P/(δ_S + δ_P)) to the five digits the title prints
    assert!(
        (number_after(&svg, "(δ_S + δ_P) = ") - phi).abs() <= 5e-6,
        "Φ = {phi}"
    );
    // F_M and f_SM = δ_S F_M, f_SM + f_PM to the printed digits
    let rel = |x: f64, y: f64, digits: i32| (x / y - 1.0).abs() <= 10f64.powi(-digits);
    assert!(rel(number_after(&svg, "F_M = "), f_m, 5));
    assert!(rel(number_after(&svg, "f_SM = δ_S F_M = "), d_s * f_m, 4));
    assert!(rel(
        number_after(&svg, "f_SM + f_PM = "),
        (d_s + d_p) * f_m,
        4
    ));
    // the example scene with a plot draws the same joint diagram, byte for byte
    let scene = dir.join("m10.toml");
    let text = std::fs::read_to_string(crate::front_ends::SCENE).unwrap();
    let scene_plot = dir.join("scene.svg");
    std::fs::write(
        &scene,
        format!("{text}plot = \"{}\"\n", scene_plot.display()),
    )
    .unwrap();
    json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
    let from_scene = std::fs::read_to_string(dir.join("scene-joint.svg")).unwrap();
    assert_eq!(from_scene, svg);
    std::fs::remove_dir_all(&dir).unwrap();
}
