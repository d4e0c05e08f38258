//! `two --method hankel --a 0 --c C`: two equal plates without a hole ending at a free rim C, by
//! the receding contact with the rim's bending correction (`hankel::receding::rim`), held to
//! what shares no code with it: the FE two-plate model meshed to C (within both estimates, the
//! rim's shift of R_o many times their sum); R_o(C) → R_o(∞) like C⁻² (observed rate); the
//! holed rim's JSON keys; the refusals (exit 2 naming `--c`).

use crate::fuzz::{run, Run};
use std::time::Duration;

/// B = D = 1, uniform load on the disk r ≤ B, ν = 0.3.
const DISK: [&str; 9] = ["two", "--a", "0", "--b", "1", "--d", "1", "--nu", "0.3"];

fn go(extra: &[&str]) -> Run {
    let args: Vec<String> = DISK.iter().chain(extra).map(|s| s.to_string()).collect();
    run(&args, Duration::from_secs(60))
}

/// The JSON of a run that exited 0.
fn json(r: &Run) -> serde_json::Value {
    assert_eq!(r.code, Some(0), "{}{}", r.stdout, r.stderr);
    serde_json::from_str(&r.stdout).unwrap_or_else(|e| panic!("{e}: {}", r.stdout))
}

/// (R_o, its estimate) of `--method method --c c` (None: C = ∞) at `tol`.
fn r_o(method: &str, c: Option<&str>, tol: &str) -> (f64, f64, serde_json::Value) {
    let mut a = vec!["--method", method, "--tol", tol, "--json"];
    if let Some(c) = c {
        a.extend(["--c", c]);
    }
    let v = json(&go(&a));
    let r = v["r_o"].as_f64().unwrap();
    (r, v["r_o_error"].as_f64().unwrap(), v)
}

#[test]
fn agrees_with_the_fe_meshed_to_the_rim() {
    // C = 5D: the rim moves R_o by ~1e-2 D; the FE at --tol 1e-4 (auto takes the FE above 3e-5)
    let (fe, fe_err, v) = r_o("auto", Some("5"), "1e-4");
    // auto above 3e-5 is the FE (its record: the mesh's dofs, no Hankel record)
    assert!(
        v["dofs"].as_u64().is_some() && v.get("hankel").is_none(),
        "{v}"
    );
    let (h, h_err, v) = r_o("hankel", Some("5"), "1e-6");
    assert_eq!(v["converged"], true);
    let (inf, _, _) = r_o("hankel", None, "1e-6");
    let rim = &v["hankel"]["rim"];
    assert_eq!(rim["r_o_infinite"].as_f64(), Some(inf));
    assert_eq!(rim["outer_radius"].as_f64(), Some(5.0));
    let shift = h - inf;
    println!(
        "C = 5 D: Hankel R_o = {h:.9} ± {h_err:.1e} D, FE {fe:.9} ± {fe_err:.1e} D, \
         |FE − Hankel| = {:.2e} D, rim shift {shift:+.3e} D",
        (fe - h).abs()
    );
    assert!((fe - h).abs() <= fe_err + h_err);
    // the agreement is the rim's: the shift is many times both bars
    assert!(shift.abs() > 10.0 * (fe_err + h_err), "{shift}");
}

#[test]
fn approaches_the_infinite_plate_like_c_to_the_minus_two() {
    let (inf, inf_err, _) = r_o("hankel", None, "1e-8");
    let shifts: Vec<f64> = ["6", "12", "24"]
        .iter()
        .map(|c| {
            let (h, err, v) = r_o("hankel", Some(c), "1e-8");
            assert_eq!(v["hankel"]["rim"]["r_o_infinite"].as_f64(), Some(inf));
            // each shift resolved: far above both estimates
            assert!(
                (h - inf).abs() > 100.0 * (err + inf_err),
                "C = {c}: {h} {inf}"
            );
            h - inf
        })
        .collect();
    let rates: Vec<f64> = shifts.windows(2).map(|s| (s[0] / s[1]).log2()).collect();
    println!("shifts R_o(C) − R_o(∞) at C = 6, 12, 24 D: {shifts:?} D; observed rates {rates:.4?}");
    // R_o(C) − R_o(∞) ~ −k/C² (the rim moment's log bending): the rate tends to 2
    assert!(shifts.iter().all(|s| *s < 0.0));
    assert!(
        (rates[1] - 2.0).abs() < (rates[0] - 2.0).abs().max(0.02),
        "{rates:?}"
    );
    assert!((rates[1] - 2.0).abs() < 0.05, "{rates:?}");
}

#[test]
fn json_keys_and_text_line_are_the_holed_rims() {
    let args: Vec<String> = [
        "two", "--a", "0.5", "--b", "1", "--d", "1", "--c", "5", "--method", "hankel", "--tol",
        "1e-3", "--json",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let holed = json(&run(&args, Duration::from_secs(60)));
    let (_, _, v) = r_o("hankel", Some("5"), "1e-3");
    let keys = |v: &serde_json::Value| {
        let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
        k.sort();
        k
    };
    assert_eq!(keys(&v["hankel"]["rim"]), keys(&holed["hankel"]["rim"]));
    // auto below 3e-5 takes this route (above it the FE: agrees_with_the_fe_meshed_to_the_rim)
    let (h, _, auto) = r_o("auto", Some("5"), "1e-6");
    assert_eq!(auto["method"], "hankel");
    assert_eq!(auto["hankel"]["rim"]["outer_radius"].as_f64(), Some(5.0));
    assert_eq!(Some(h), r_o("hankel", Some("5"), "1e-6").2["r_o"].as_f64());
    let text = go(&["--method", "hankel", "--c", "5"]);
    assert_eq!(text.code, Some(0), "{}", text.stderr);
    assert!(
        text.stdout
            .contains("rim C = 5.000000000 in: R_o - R_o(infinite plate) = -"),
        "{}",
        text.stdout
    );
}

#[test]
fn a_rim_within_b_plus_d_or_unequal_plates_or_wide_loads_exit_2_naming_the_flag() {
    for (b, extra, flag) in [
        ("1", &["--c", "2"][..], "--c"),
        ("1", &["--c", "1.5"], "--c"),
        ("1", &["--c", "5", "--d2", "0.5"], "--c"),
        // beyond MAX_B_OVER_D_RIM = 8 (55 s of CPU at B/D = 32): refused before computing
        ("9", &["--c", "14"], "--b"),
    ] {
        let args: Vec<String> = [
            "two", "--a", "0", "--b", b, "--d", "1", "--method", "hankel",
        ]
        .iter()
        .chain(extra)
        .map(|s| s.to_string())
        .collect();
        let r = run(&args, Duration::from_secs(60));
        assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
        assert!(
            r.stderr.contains(flag) && r.stderr.contains("--method fem"),
            "{}",
            r.stderr
        );
    }
}

#[test]
fn a_tolerance_beyond_reach_exits_3_with_the_result() {
    let r = go(&["--method", "hankel", "--c", "5", "--tol", "1e-15", "--json"]);
    assert_eq!(r.code, Some(3), "{}", r.stderr);
    let v: serde_json::Value = serde_json::from_str(&r.stdout).unwrap();
    assert_eq!(v["converged"], false);
    assert!(v["r_o"].as_f64().unwrap() > 1.0);
}

#[test]
fn the_curve_carries_the_load() {
    // ∫q r dr over [0, R_o] = ∫p r dr = B²/2 (P = 1, B = 1): equilibrium of the interface,
    // by the trapezoid rule on the curve's points and on every other one (the difference is
    // the quadrature's error scale)
    let dir = std::env::temp_dir().join(format!("boltzone-rim-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("rim.csv");
    let r = go(&[
        "--method",
        "hankel",
        "--c",
        "5",
        "--curve",
        path.to_str().unwrap(),
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let text = std::fs::read_to_string(&path).unwrap();
    let points: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('r'))
        .map(|l| {
            let mut f = l.split(',').map(|x| x.parse::<f64>().unwrap());
            (f.next().unwrap(), f.next().unwrap())
        })
        .collect();
    let trapezoid = |step: usize| -> f64 {
        let p: Vec<&(f64, f64)> = points.iter().step_by(step).collect();
        p.windows(2)
            .map(|w| 0.5 * (w[1].0 - w[0].0) * (w[0].1 * w[0].0 + w[1].1 * w[1].0))
            .sum()
    };
    let (fine, coarse) = (trapezoid(1), trapezoid(2));
    println!("∫q r dr = {fine:.6} (every other point {coarse:.6}), load 0.5");
    assert!(
        (fine - 0.5).abs() <= (fine - coarse).abs(),
        "{fine} {coarse}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
