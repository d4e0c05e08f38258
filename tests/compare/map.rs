//! The design map is smooth: on a coarse 6 × 6 map over the full range, R_o/A of both models
//! grows with B/A along every row and falls with A/D down every column, and no point is an
//! isolated outlier (second differences bounded by the centred first difference plus the
//! points' error estimates).

use boltzone::compare::map::{compute, log_spaced, MapParams};
use boltzone::compare::{Comparison, Value};

/// Picks one model's R_o from a comparison.
type Pick = fn(&Comparison) -> Value;

#[test]
fn coarse_map_is_smooth_and_monotone() {
    let n = 6;
    let p = MapParams {
        a_over_d: log_spaced(0.2, 5.0, n),
        b_over_a: log_spaced(1.1, 5.0, n),
        tolerance: 2e-3,
        ..MapParams::default()
    };
    let m = compute(&p, &|| ()).unwrap();
    assert_eq!(m.points.len(), n * n);
    let models: [(&str, Pick); 2] = [("single", |c| c.single), ("two", |c| c.two)];
    for (name, f) in models {
        let at = |i: usize, j: usize| f(m.at(i, j));
        for i in 0..n {
            for j in 0..n {
                let v = at(i, j);
                if j + 1 < n {
                    let w = at(i, j + 1);
                    assert!(
                        w.value - w.error > v.value + v.error,
                        "{name} along B/A at ({i},{j})"
                    );
                }
                if i + 1 < n {
                    let w = at(i + 1, j);
                    assert!(
                        w.value + w.error < v.value - v.error,
                        "{name} along A/D at ({i},{j})"
                    );
                }
            }
        }
        // Outliers: along each axis, |f₋ − 2f + f₊| ≤ |f₊ − f₋| + 2(e₋ + 2e + e₊). On the log
        // grids used here the smooth part of the second difference stays below the centred first
        // difference (R_o/A ≈ B/A + k·D/A: ratio (1 − 1/q)²/(1 − 1/q²) < 1 for grid ratio q);
        // an isolated error δ adds 2δ to the left side only.
        let check = |a: Value, b: Value, c: Value, where_: String| {
            let d2 = (a.value - 2.0 * b.value + c.value).abs();
            let d1 = (c.value - a.value).abs();
            assert!(
                d2 <= d1 + 2.0 * (a.error + 2.0 * b.error + c.error),
                "{name}: outlier at {where_}: {a:?} {b:?} {c:?}"
            );
        };
        for i in 0..n {
            for j in 1..n - 1 {
                check(
                    at(i, j - 1),
                    at(i, j),
                    at(i, j + 1),
                    format!("({i},{j}) along B/A"),
                );
                check(
                    at(j - 1, i),
                    at(j, i),
                    at(j + 1, i),
                    format!("({j},{i}) along A/D"),
                );
            }
        }
    }
    // The CSV has a header and one line per point.
    assert_eq!(m.csv().lines().count(), n * n + 1);
}
