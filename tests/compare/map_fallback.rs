//! The design map's `auto` falling back to the finite elements where the two-plate Hankel route
//! is tried and does not converge (`compare::route::two`): a point within the route's reach at
//! a tolerance below 3e-5 (`AUTO_BELOW`, so `auto` really tries the route) whose rim lies close
//! to the load. Measured with `two --method hankel|fem --tol 2.9e-5` (release, load ~6 on 2
//! cores), A = 0.1, B/A = 1.1, C = 6A: at A/D = 1 (C − B = 4.9 D) the route converges, estimate
//! 1.2e-6 in R_o = 0.1535 (2.8 s); at A/D = 0.5 (C − B = 2.45 D) its estimate is 8.1e-5 in
//! R_o = 0.2282, 3.5e-4 of R_o (2.7 s), and the FE's 6.8e-6 (1.8 s).

use super::map_method::column;
use boltzone::compare::map::{compute, MapParams, METHOD_COLUMNS};
use boltzone::compare::{two_hankel_reach, two_takes_hankel, Method, Route};

/// Below `AUTO_BELOW` = 3e-5: `auto` tries the two-plate Hankel route.
const TOL: f64 = 2.9e-5;

/// B/A = 1.1, C/A = 6 at the rows `a_over_d`, tolerance [`TOL`].
fn map(a_over_d: &[f64], method: Method) -> MapParams {
    MapParams {
        tolerance: TOL,
        ..super::map_method::map(a_over_d, &[1.1], 6.0, method)
    }
}

#[test]
fn auto_takes_the_fe_where_the_two_plate_route_does_not_converge() {
    let auto = compute(&map(&[1.0, 0.5], Method::Auto), &|| ()).unwrap();
    for c in &auto.points {
        // both points within reach, below AUTO_BELOW: auto tries the route at both
        assert!(two_hankel_reach(&c.geometry).is_ok(), "{:?}", c.geometry);
        assert!(two_takes_hankel(Method::Auto, TOL, true));
    }
    let csv = auto.csv();
    assert!(csv.lines().next().unwrap().ends_with(METHOD_COLUMNS));
    assert_eq!(column(&csv, "two_method"), ["hankel", "fem"]);
    let (kept, fell_back) = (auto.at(0, 0), auto.at(1, 0));
    assert_eq!(kept.two_method, Route::Hankel);
    assert!(kept.two.converged && kept.two.error <= TOL * kept.two.value);
    // the route at the second point, as `--method hankel` keeps it: tried, not converged
    let hankel = compute(&map(&[0.5], Method::Hankel), &|| ()).unwrap();
    let h = hankel.at(0, 0);
    assert_eq!(h.two_method, Route::Hankel);
    assert!(
        !h.two.converged && h.two.error > TOL * h.two.value,
        "{:?}",
        h.two
    );
    // auto's value there is the FE's, bit for bit, in the struct and in the CSV
    let fem = compute(&map(&[0.5], Method::Fem), &|| ()).unwrap();
    let f = fem.at(0, 0);
    assert_eq!(f.two_method, Route::Fem);
    assert_eq!(fell_back.two, f.two);
    let fem_csv = fem.csv();
    for name in ["two_r_o_over_a", "two_error", "two_converged"] {
        assert_eq!(column(&csv, name)[1], column(&fem_csv, name)[0], "{name}");
    }
    // and the FE (no code shared with the route) lies within both error bars of the route's
    // unconverged answer: the fallback trades the wider bar for the narrower one
    println!(
        "A/D 0.5, B/A 1.1, C/A 6: Hankel {:.9} ± {:.1e}, FE {:.9} ± {:.1e} (R_o/A)",
        h.two.value / h.geometry.a,
        h.two.error / h.geometry.a,
        f.two.value / f.geometry.a,
        f.two.error / f.geometry.a
    );
    assert!((h.two.value - f.two.value).abs() <= h.two.error + f.two.error);
    assert!(f.two.error < h.two.error);
}
