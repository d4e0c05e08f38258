//! Tolerances out of reach stop early (issue 17 fuzz): `fem::single` gives up a tolerance that
//! the levels left cannot reach even at twice the fastest shrink of its estimate seen
//! (`fem::single::FASTEST_ESTIMATE_RATE`), as the two-plate study does.

use crate::fuzz::run;
use std::time::Duration;

fn go(args: &[&str]) -> crate::fuzz::Run {
    let args: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    run(&args, Duration::from_secs(60))
}

#[test]
fn an_unreachable_single_plate_tolerance_stops_at_three_levels() {
    // (1e-15: below every route's reach, above f64's epsilon, which --tol refuses below)
    // was: every level of the tight-tolerance grading solved, table1 --tol 1e-320 9.7 s and
    // 266 MB (4.4 s before the grading shrank from D/8), over 30 s under the fuzz's load
    let r = go(&[
        "single", "--a", "0.1", "--b", "0.22", "--d", "0.1", "--tol", "1e-15", "--json",
    ]);
    assert_eq!(r.code, Some(3), "{}", r.stderr);
    let v: serde_json::Value = serde_json::from_str(&r.stdout).unwrap();
    assert_eq!(v["converged"], false);
    assert_eq!(v["levels"].as_array().map(Vec::len), Some(3));
    // a reachable tight one still refines to convergence
    let r = go(&[
        "single", "--a", "0.1", "--b", "0.22", "--d", "0.1", "--tol", "1e-6", "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&r.stdout).unwrap();
    assert!(v["levels"].as_array().map_or(0, Vec::len) > 5, "{v}");
    let r = go(&["table1", "--tol", "1e-15", "--json"]);
    assert_eq!(r.code, Some(3), "{}", r.stderr);
    assert!(r.cpu_seconds < 30.0, "{:.1} s CPU", r.cpu_seconds);
    // the CPU clock the fuzz's limit reads does read: twelve rows refined to the FE's floor take
    // seconds of it (7.5 s measured), as much as a wall clock on an idle machine
    assert!(
        r.cpu_seconds > 1.0 && r.cpu_seconds <= r.seconds * 1.05 + 0.05,
        "{:.2} s CPU, {:.2} s wall",
        r.cpu_seconds,
        r.seconds
    );
}
