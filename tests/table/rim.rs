//! The tables with a free rim (`boltzone::table::rim`): the single plate's slope floor the bound
//! divides by against the route's slopes, the rimmed answers against the Hankel route with the
//! rim, and the command line.

use crate::common::{boltzone, json_of};
use boltzone::hankel::hole::single_plate_separation;
use boltzone::numerics::random::SplitMix64;
use boltzone::route::{single_plate, Method};
use boltzone::table::near::{A_MAX, A_MIN, W_MAX, W_MIN};
use boltzone::table::rim::SINGLE_PLATE_SLOPE_MIN;
use boltzone::table::Model;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

fn plate(a: f64, b: f64, nu: f64, c: OuterRadius) -> SinglePlate {
    let load = FaceLoad::uniform(a, b, 1.0).unwrap();
    SinglePlate::new(a, c, 1.0, Material::unit(nu).unwrap(), load).unwrap()
}

#[test]
fn the_slope_floor_is_below_the_routes_slopes_at_the_domains_corners() {
    // the narrowest load carries the least force: the smallest slopes are at small A/D and w
    // (example 30's survey); every corner of the near domain, and the far one's smallest load
    let (search, hole) = single_plate::hankel_params(1e-6);
    let mut smallest = f64::INFINITY;
    for nu in [0.0, 0.25, 0.499] {
        let mut corners = vec![(0.01, 2.0)];
        for a in [A_MIN, A_MAX] {
            corners.extend([W_MIN, W_MAX].map(|w| (a, a + w)));
        }
        for (a, b) in corners {
            let (s, _) =
                single_plate_separation(&plate(a, b, nu, OuterRadius::Infinite), &search, &hole)
                    .unwrap();
            assert!(
                s.slope > SINGLE_PLATE_SLOPE_MIN,
                "A/D {a} B/D {b} ν {nu}: {}",
                s.slope
            );
            smallest = smallest.min(s.slope);
        }
    }
    // the margin the floor was set with: half the smallest
    assert!(SINGLE_PLATE_SLOPE_MIN <= 0.5 * smallest, "{smallest}");
}

#[test]
fn rimmed_table_answers_hold_against_the_hankel_route_with_the_rim() {
    // random plates (their own seed) with the rim 4..12 D beyond R_o, where the bound goes from
    // larger than the table's bar to far below it; the route bounds or fits the rim itself
    let mut rng = SplitMix64::new(35);
    let (search, hole) = single_plate::hankel_params(1e-8);
    let mut served = 0;
    for _ in 0..8 {
        let (a, w, nu) = (
            rng.log_uniform(A_MIN, A_MAX),
            rng.log_uniform(W_MIN, W_MAX),
            0.5 * rng.unit(),
        );
        let infinite = plate(a, a + w, nu, OuterRadius::Infinite);
        let mut q = single_plate::Question {
            method: Method::Table,
            plate: Some(&infinite),
            tolerance: 1e-4,
            ..Default::default()
        };
        let far = single_plate::table_answer(&q).unwrap();
        let c = far.value + 4.0 + 8.0 * rng.unit();
        let rimmed = plate(a, a + w, nu, OuterRadius::Finite(c));
        q.plate = Some(&rimmed);
        let t = single_plate::table_answer(&q).unwrap();
        assert_eq!(t.value, far.value);
        assert!(t.error > far.error, "the rim's bound joins the bar");
        let (r, _) = single_plate_separation(&rimmed, &search, &hole).unwrap();
        assert!(
            (t.value - r.r_o).abs() <= t.error + r.r_o_error,
            "A/D {a} w {w} ν {nu} C {c}: table {} ± {:.1e}, route {} ± {:.1e}",
            t.value,
            t.error,
            r.r_o,
            r.r_o_error
        );
        served += usize::from(t.converged);
    }
    assert!(served > 0, "some rims are far enough to meet 1e-4");
}

#[test]
fn single_with_a_rim_answers_from_the_tables_and_a_rim_at_the_contact_is_refused() {
    // Table 1's first row with its rim C = 1.54 in
    let args = [
        "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--c", "1.54",
    ];
    let run = |method: &str| {
        let mut a = args.to_vec();
        a.extend(["--method", method, "--tol", "1e-5", "--json"]);
        json_of(&boltzone(&a))
    };
    let (t, h) = (run("table"), run("hankel"));
    assert_eq!(t["method"], "table");
    let (rt, et) = (t["r_o"].as_f64().unwrap(), t["r_o_error"].as_f64().unwrap());
    let (rh, eh) = (h["r_o"].as_f64().unwrap(), h["r_o_error"].as_f64().unwrap());
    assert!(
        (rt - rh).abs() <= et + eh,
        "table {rt} ± {et}, hankel {rh} ± {eh}"
    );
    assert_eq!(run("auto")["method"], "table");
    // a rim inside the infinite plate's contact zone: exit 2 naming --c
    let out = boltzone(&[
        "single", "--a", "0.1", "--b", "0.31", "--d", "0.1", "--c", "0.35", "--method", "table",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--c") && err.contains("0.35"), "{err}");
}

#[test]
fn two_plates_rimmed_table_answers_hold_against_the_holed_route_with_the_rim() {
    use boltzone::hankel::receding::holed::two_plate_hole_to;
    use boltzone::table::{lookup, rim};
    // Table 1's first row (A = D = 0.1 in, B = 0.31 in, C = 1.54 in) and three random plates
    // of their own seed, the rim 4..40 D beyond R_o
    let mut rng = SplitMix64::new(3135);
    let mut cases = vec![(0.1, 0.31, 0.1, 0.3, 1.54)];
    for _ in 0..3 {
        let a = rng.log_uniform(A_MIN, A_MAX);
        let w = rng.log_uniform(W_MIN, rim::W_MAX_TWO);
        let nu = 0.5 * rng.unit();
        let inf = lookup::separation_radius(Model::TwoPlates, a, a + w, 1.0, nu, 1.0).unwrap();
        cases.push((
            a,
            a + w,
            1.0,
            nu,
            inf.value + rng.log_uniform(rim::U_MIN, 40.0),
        ));
    }
    for (a, b, d, nu, c) in cases {
        let inf = lookup::separation_radius(Model::TwoPlates, a, b, d, nu, 1.0).unwrap();
        let shift = rim::two_plates_rim_shift(a, b, d, nu, c, inf.value).unwrap();
        assert!(shift.value > 0.0, "a free rim pulls R_o in");
        let (value, bar) = (inf.value - shift.value, inf.error + shift.error);
        let load = FaceLoad::uniform(a, b, 1.0).unwrap();
        let m = Material::unit(nu).unwrap();
        let p = SinglePlate::new(a, OuterRadius::Finite(c), d, m, load).unwrap();
        let (h, _) = two_plate_hole_to(&p, 1e-8, &[]).unwrap();
        assert!(
            (value - h.r_o).abs() <= bar + h.info.r_o_error,
            "A {a} B {b} D {d} ν {nu} C {c}: table {value} ± {bar:.1e}, route {} ± {:.1e}",
            h.r_o,
            h.info.r_o_error
        );
    }
    // a rim within 4 D of R_o is beyond the law's reach
    let inf = lookup::separation_radius(Model::TwoPlates, 0.1, 0.31, 0.1, 0.3, 1.0).unwrap();
    assert!(rim::two_plates_rim_shift(0.1, 0.31, 0.1, 0.3, inf.value + 0.3, inf.value).is_err());
}
