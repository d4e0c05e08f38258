//! The heat maps' ticks, contour lines and colour scales: ticks against hand-listed round numbers,
//! marching squares against the exact level lines of a linear function (which it reproduces
//! exactly), a signed panel's colour bar symmetric about 0 (read from the SVG), and `map`'s
//! axes ticked at round values (no 5.01).

use super::py::{boltzone_ok, temp_dir};
use super::svg_util::texts;
use boltzone::plot::contour::{axis_label, contour_segments, log_ticks, nice_ticks, tick_label};
use boltzone::plot::{diverging, svg_string, HeatMapFigure, HeatPanel};

#[test]
fn ticks_are_round_numbers() {
    assert_eq!(nice_ticks(0.0, 1.0, 6), vec![0.0, 0.2, 0.4, 0.6, 0.8, 1.0]);
    assert_eq!(nice_ticks(2.3, 7.4, 3), vec![4.0, 6.0]);
    assert_eq!(
        nice_ticks(0.13, 0.71, 7),
        vec![0.2, 0.3, 0.4, 0.5, 0.6, 0.7]
    );
    assert_eq!(log_ticks(0.2, 5.0), vec![0.2, 0.5, 1.0, 2.0, 5.0]);
    // fewer than three of 1, 2, 5: every integer mantissa
    assert_eq!(log_ticks(1.1, 5.0), vec![2.0, 3.0, 4.0, 5.0]);
    assert_eq!(tick_label(0.30000000000000004, 0.1), "0.3");
    assert_eq!(tick_label(-0.0, 0.05), "0.00");
    assert_eq!(axis_label(-1e-20, 0.25), "0");
    assert_eq!(axis_label(2e-8, 1.2e-7), "2e-8");
    assert_eq!(axis_label(1.5e-8, 3e-8), "1.5e-8");
    // the decimals each value needs, whatever step the axis took (example 07's r/A: 1.5, 2)
    assert_eq!(axis_label(1.5, 5.0), "1.5");
    assert_eq!(axis_label(2.0, 5.0), "2");
    assert_eq!(axis_label(0.30000000000000004, 1.0), "0.3");
}

#[test]
fn contours_of_a_linear_field_lie_on_its_level_lines() {
    // a non-uniform grid; z = x + 2y is linear, so edge interpolation is exact
    let x: Vec<f64> = (0..9).map(|i| (i as f64).powf(1.3) * 0.1).collect();
    let y: Vec<f64> = (0..7).map(|j| (j as f64).sqrt() * 0.4).collect();
    let z: Vec<f64> = x
        .iter()
        .flat_map(|&xi| y.iter().map(move |&yj| xi + 2.0 * yj))
        .collect();
    for level in [0.3, 1.0, 1.7, 2.9] {
        let segs = contour_segments(&x, &y, &z, level);
        assert!(!segs.is_empty(), "level {level}");
        for (p, q) in &segs {
            for (u, v) in [p, q] {
                assert!(
                    (u + 2.0 * v - level).abs() < 1e-13,
                    "({u}, {v}) off level {level}"
                );
            }
        }
        // a straight level line crossing the grid: its pieces join into one chain whose
        // length is the line's length inside the grid's hull (x + 2y = c, both within range)
        let length: f64 = segs.iter().map(|(p, q)| (q.0 - p.0).hypot(q.1 - p.1)).sum();
        let (x_max, y_max) = (x[8], y[6]);
        let y_lo = ((level - x_max) / 2.0).max(0.0);
        let y_hi = (level / 2.0).min(y_max);
        let exact = (y_hi - y_lo) * 5f64.sqrt();
        assert!(
            (length - exact).abs() < 1e-12,
            "level {level}: {length} vs {exact}"
        );
    }
}

#[test]
fn a_signed_panel_gets_a_diverging_scale_centred_on_zero() {
    // white in the middle, blue below, red above
    let (lo, mid, hi) = (diverging(0.0), diverging(0.5), diverging(1.0));
    assert_eq!((mid.0, mid.1, mid.2), (247, 247, 247));
    assert!(lo.2 > lo.0 && hi.0 > hi.2);
    let x = vec![1.0, 2.0, 4.0];
    let y = vec![1.0, 3.0];
    let fig = |z: Vec<f64>| HeatMapFigure {
        x: x.clone(),
        y: y.clone(),
        x_label: "x".into(),
        y_label: "y".into(),
        panels: vec![HeatPanel {
            title: "e".into(),
            z,
        }],
    };
    // values in [−7, 10]: the bar spans ±10, so −10 is labelled though no value reaches it
    let svg = svg_string(&fig(vec![-7.0, -2.0, 0.5, 3.0, 6.0, 10.0]), (800, 400)).unwrap();
    let t = texts(&svg);
    for want in ["-10", "-5", "0", "5", "10"] {
        assert!(
            t.iter().any(|s| s == want),
            "no colour-bar label {want} in {t:?}"
        );
    }
    // one-signed values keep a one-sided bar: no negative label
    let svg = svg_string(&fig(vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]), (800, 400)).unwrap();
    assert!(!texts(&svg).iter().any(|s| s.starts_with('-')));
}

#[test]
fn map_axes_are_ticked_at_round_values() {
    let dir = temp_dir("fig-map");
    let svg = dir.join("m.svg");
    boltzone_ok(
        "map --a-over-d 0.3,1,3 --b-over-a 1.3,2,4 --tol 1e-2 --svg",
        &[&svg],
    );
    let t = texts(&std::fs::read_to_string(&svg).unwrap());
    // A/D cells span 0.3/√(10/3)… 3·√3: round ticks 0.2, 0.5, 1, 2, 5 inside
    for want in ["0.2", "0.5", "1", "2", "5"] {
        assert!(t.iter().any(|s| s == want), "no tick {want}");
    }
    // no label with more digits than a round number shows (the old 5.01, 1.39)
    assert!(
        !t.iter()
            .any(|s| s.parse::<f64>().is_ok() && s.len() > 4 && !s.starts_with('-')),
        "{t:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
