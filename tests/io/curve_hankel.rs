//! `single --method hankel --curve FILE`: the midplane σ_z of the semi-analytic route, checked
//! (1) by equilibrium — 2π∫σ_z r dr over the midplane carries the bolt force, −P·π(B² − A²) —
//! within the trapezoid rule's error on the exported points (bounded by the rule on every other
//! point) plus the error bound the file states; (2) against the FE curve of the same plate: the
//! FE curve converges to it as the FE tolerance tightens (its largest deviation falls from tol
//! 1e-3 to 1e-5), and the two routes' R_o agree within both error bars.

use super::py::{boltzone_ok, csv_columns, force_and_bound, temp_dir};
use crate::common::{boltzone, json_of};
use std::f64::consts::PI;

const PLATE: &str = "single --a 0.1 --b 0.31 --d 0.1 --c 1.54";

fn curve(path: &std::path::Path) -> (Vec<f64>, Vec<f64>) {
    let (_, rows) = csv_columns(&std::fs::read_to_string(path).unwrap());
    (
        rows.iter().map(|r| r[0]).collect(),
        rows.iter().map(|r| r[1]).collect(),
    )
}

/// Cubic Lagrange interpolation of (x, y) at t (the four nearest points).
fn cubic(x: &[f64], y: &[f64], t: f64) -> f64 {
    let i = x
        .partition_point(|&v| v < t)
        .saturating_sub(2)
        .min(x.len() - 4);
    (i..i + 4)
        .map(|j| {
            let l: f64 = (i..i + 4)
                .filter(|&k| k != j)
                .map(|k| (t - x[k]) / (x[j] - x[k]))
                .product();
            l * y[j]
        })
        .sum()
}

#[test]
fn hankel_curve_carries_the_bolt_force_and_the_fe_curve_converges_to_it() {
    let dir = temp_dir("curve-hankel");
    let h = dir.join("h.csv");
    boltzone_ok(&format!("{PLATE} --method hankel --curve"), &[&h]);
    let text = std::fs::read_to_string(&h).unwrap();
    let bound: f64 = text
        .lines()
        .find_map(|l| l.strip_prefix("# sigma_z error bound: "))
        .and_then(|l| l.split(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    let (r, s) = curve(&h);
    // equilibrium: the midplane carries the load P = 1 psi over A..B (compression negative)
    let pr: Vec<f64> = r.iter().zip(&s).map(|(r, s)| r * s).collect();
    let (force, quad) = force_and_bound(&r, &pr);
    let f = -PI * (0.31f64.powi(2) - 0.1f64.powi(2));
    // the tail beyond the last radius (B + 8D): |σ_z| there, spread over the rest of the plate
    let tail = s.last().unwrap().abs() * PI * (1.54f64.powi(2) - r.last().unwrap().powi(2));
    let allowed = quad + bound * PI * (r.last().unwrap().powi(2) - 0.01) + tail;
    eprintln!("2π∫σ_z r dr = {force:.8} lbf, want {f:.8}; quadrature bound {quad:.1e}, allowed {allowed:.1e}");
    assert!((force - f).abs() <= allowed, "{force} vs {f} ± {allowed}");
    assert!(allowed < 1e-3 * f.abs());
    // the FE curve converges to it: largest deviation at the FE nodes (Hankel curve interpolated
    // by cubics: 4th-order, far below the deviations)
    let mut dev = Vec::new();
    for tol in ["1e-3", "1e-5"] {
        let fe = dir.join(format!("fe{tol}.csv"));
        boltzone_ok(&format!("{PLATE} --tol {tol} --curve"), &[&fe]);
        let (rf, sf) = curve(&fe);
        let d = rf
            .iter()
            .zip(&sf)
            .filter(|(x, _)| **x <= *r.last().unwrap())
            .map(|(x, y)| (y - cubic(&r, &s, *x)).abs())
            .fold(0.0, f64::max);
        eprintln!("FE tol {tol}: largest deviation from the Hankel curve {d:.2e} psi");
        dev.push(d);
    }
    assert!(
        dev[1] < dev[0],
        "FE does not approach the Hankel curve: {dev:?}"
    );
    // the routes' R_o within both error bars
    let v = |m: &str| {
        let mut a: Vec<&str> = PLATE.split_whitespace().collect();
        a.extend(["--json", "--method", m, "--tol", "1e-4"]);
        json_of(&boltzone(&a))
    };
    let (hk, fe) = (v("hankel"), v("fem"));
    let (rh, eh) = (
        hk["r_o"].as_f64().unwrap(),
        hk["r_o_error"].as_f64().unwrap(),
    );
    let (rf, ef) = (
        fe["r_o"].as_f64().unwrap(),
        fe["r_o_error"].as_f64().unwrap(),
    );
    assert!(
        (rh - rf).abs() <= eh + ef,
        "R_o: Hankel {rh} ± {eh}, FE {rf} ± {ef}"
    );
    // the curve's sign change sits at the Hankel R_o (within one grid step)
    let k = (1..r.len())
        .find(|&k| r[k] > 0.31 && s[k - 1] < 0.0 && s[k] >= 0.0)
        .unwrap();
    assert!(
        r[k - 1] <= rh + eh && rh - eh <= r[k],
        "crossing {}..{} vs {rh}",
        r[k - 1],
        r[k]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
