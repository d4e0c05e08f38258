//! Brent's method and the scan for the first upward crossing against known roots.

use boltzone::numerics::root::{brent, first_upward_root};
use std::convert::Infallible;

#[test]
fn brent_finds_wallis_root_superlinearly() {
    // x³ − 2x − 5 = 0 (Wallis's equation): x = 2.0945514815423265…
    let mut evals = 0;
    let mut f = |x: f64| {
        evals += 1;
        Ok::<f64, Infallible>(x * x * x - 2.0 * x - 5.0)
    };
    let Ok(r) = brent(&mut f, 2.0, -1.0, 3.0, 16.0, 1e-15, 100);
    assert!((r.x - 2.094_551_481_542_326_5).abs() < 1e-15, "{}", r.x);
    // the stopping half-width: tol/2 plus the rounding floor 2ε|x|, doubled at most
    assert!(
        r.half_width <= 1e-15 + 4.0 * f64::EPSILON * r.x.abs(),
        "{}",
        r.half_width
    );
    // bisection alone would need ~50 evaluations for 1e-15 on [2, 3]
    assert!(evals <= 12, "{evals} evaluations");
}

#[test]
fn first_upward_root_skips_downward_crossings_and_reports_failure() {
    // J₀ falls through its first zero 2.404825557695773 and rises through its second,
    // 5.520078110286311 (DLMF Table 10.21.1)
    let mut f = |x: f64| Ok::<f64, Infallible>(libm::j0(x));
    let Ok(r) = first_upward_root(&mut f, (0.0, 1.0), 0.5, 20.0, 1e-14, 100);
    let x = r.map_or(f64::NAN, |r| r.x);
    assert!((x - 5.520_078_110_286_311).abs() < 1e-13, "{x}");
    // no upward crossing on [0, 4]
    let Ok(r) = first_upward_root(&mut f, (0.0, 1.0), 0.5, 4.0, 1e-14, 100);
    assert!(r.is_none());
}
