//! Example 06: the receding contact of a plate on a frictionless rigid base (two equal bolted
//! plates without a hole), semi-analytically by Hankel transforms — the independent check of the
//! finite-element two-plate solver.
//!
//! A layer D thick is pressed on its top face by a uniform disk load p on r ≤ B and rests on a
//! frictionless rigid plane; it touches the plane on r ≤ R_o, with R_o independent of p and ν
//! (`boltzone::hankel::receding`: Abel representation of the contact pressure, Fredholm equation
//! of the second kind, Nyström's method, R_o where the edge singularity vanishes).
//!
//! Printed: (1) R_o/D and R_o/B against B/D with the Nyström size, error estimate and time;
//! (2) the convergence of R_o in the basis size (geometric: error and rate per node);
//! (3) other load shapes (annulus with a tiny inner radius, triangular loads);
//! (4) the finite-element two-plate solver beside it, when available.
//!
//! Self-checks (panics): every error estimate below 1e-8·D; geometric convergence (each step of
//! 4 nodes gains at least a factor 10 until rounding); R_o/D grows with B/D; equilibrium of the
//! contact pressure ("equil.", relative); the displacement integral flat on the contact zone
//! ("flat": max |w(r,0) − w(R_o,0)| for r ≤ R_o per gap at 1.5 R_o). `BOLTZONE_QUICK=1` runs a reduced set (the test suite does).
//!
//! Literature: Keer, Dundurs & Tsai (1972, *J. Appl. Mech.* 39, 1115–1120) tabulate the
//! contact radius of a layer on a half-space against the load radius; their values for a rigid
//! base were not found in the sources searched, so none are printed here.

use boltzone::hankel::receding::{Layer, RecedingContact, RecedingParams};
use boltzone::{FaceLoad, Material, Peak};
use std::f64::consts::PI;

fn quick() -> bool {
    std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1")
}

fn solve(d: f64, load: FaceLoad, params: &RecedingParams) -> RecedingContact {
    Layer::new(d, Material::unit(0.3).expect("ν = 0.3"), load)
        .expect("valid layer")
        .receding_contact(params)
        .expect("a contact radius")
}

pub fn main() {
    let d = 1.0;
    let params = RecedingParams::default();

    println!(
        "(1) disk load on r <= B, layer D thick on a frictionless rigid base (nu-independent)"
    );
    println!(
        "{:>7} {:>14} {:>10} {:>10} {:>5} {:>7} {:>9} {:>9} {:>10} {:>9} {:>9}",
        "B/D",
        "R_o/D",
        "R_o/B",
        "(R_o-B)/D",
        "n",
        "xi",
        "error",
        "solves",
        "time [ms]",
        "equil.",
        "flat"
    );
    let ratios: &[f64] = if quick() {
        &[0.25, 1.0, 4.0]
    } else {
        &[0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 10.0, 20.0]
    };
    let mut last = 0.0;
    for &bd in ratios {
        let b = bd * d;
        let load = FaceLoad::uniform(0.0, b, 1.0).expect("disk load");
        let f = load.total_force();
        let c = solve(d, load, &params);
        let eq = c.solution.total_force() / f - 1.0;
        // w(r,0) − w(R_o,0) on the contact zone from the displacement integral, per gap(1.5 R_o)
        let flat = (0..=20)
            .map(|k| c.solution.lift(c.r_o * k as f64 / 20.0).abs())
            .fold(0.0f64, f64::max)
            / c.solution.gap(1.5 * c.r_o);
        println!(
            "{:>7} {:>14.11} {:>10.6} {:>10.6} {:>5} {:>7} {:>9.1e} {:>9} {:>10.2} {:>+9.1e} {:>9.1e}",
            bd,
            c.r_o / d,
            c.r_o / b,
            (c.r_o - b) / d,
            c.info.nodes,
            c.info.xi_nodes,
            c.info.error,
            c.info.solves,
            1e3 * c.info.seconds,
            eq,
            flat
        );
        assert!(
            c.info.error < 1e-8 * d,
            "B/D = {bd}: error {}",
            c.info.error
        );
        assert!(c.r_o > last, "R_o/D must grow with B/D");
        assert!(eq.abs() < 1e-9, "B/D = {bd}: equilibrium {eq:e}");
        assert!(
            flat < 1e-11,
            "B/D = {bd}: not flat on the contact zone, {flat:e}"
        );
        last = c.r_o;
    }

    println!("\n(2) convergence in the Nystrom size n (fixed n; reference: n = 64)");
    for &bd in if quick() { &[1.0][..] } else { &[1.0, 4.0][..] } {
        let load = FaceLoad::uniform(0.0, bd * d, 1.0).expect("disk load");
        let fixed = |n: usize| RecedingParams {
            min_nodes: n,
            nodes_per_thickness: 0.0,
            ..Default::default()
        };
        let best = solve(d, load.clone(), &fixed(64)).r_o;
        println!("B/D = {bd}: R_o/D = {:.13}", best / d);
        println!(
            "{:>5} {:>16} {:>10} {:>14}",
            "n", "R_o/D", "|error|", "rate per node"
        );
        let mut prev: Option<(usize, f64)> = None;
        for n in (4..=32).step_by(4) {
            let c = solve(d, load.clone(), &fixed(n));
            let err = (c.r_o - best).abs();
            let rate = prev.map(|(m, e)| (err / e).ln() / (n - m) as f64);
            println!(
                "{:>5} {:>16.13} {:>10.2e} {:>14}",
                n,
                c.r_o / d,
                err,
                rate.map_or("-".into(), |r| format!("{r:.2}"))
            );
            if let Some((_, e)) = prev {
                // geometric: a factor 10 per 4 nodes at least, until the 1e-12 rounding floor
                assert!(
                    err < 0.1 * e || err < 1e-11 * d,
                    "n = {n}: {err:e} after {e:e}"
                );
            }
            prev = Some((n, err));
        }
    }

    println!("\n(3) other loads (B = D)");
    let others = [
        ("annulus A' = 0.001 D", FaceLoad::uniform(0.001 * d, d, 1.0)),
        ("annulus A' = 0.25 D", FaceLoad::uniform(0.25 * d, d, 1.0)),
        (
            "triangular, peak at 0",
            FaceLoad::triangular(0.0, d, 1.0, Peak::AtA),
        ),
        (
            "triangular, peak at B",
            FaceLoad::triangular(0.0, d, 1.0, Peak::AtB),
        ),
    ];
    for (name, load) in others {
        let load = load.expect("valid load");
        let f = load.total_force();
        let c = solve(d, load, &params);
        let eq = c.solution.total_force() / f - 1.0;
        println!(
            "{name:>24}: R_o/D = {:.11} ± {:.1e}  equilibrium {:+.1e}  q(0)/p_mean = {:.6}  {:.1} ms",
            c.r_o / d,
            c.info.error,
            eq,
            c.solution.pressure(0.0) * PI * d * d / f,
            1e3 * c.info.seconds
        );
        assert!(eq.abs() < 1e-9 && c.info.error < 1e-8 * d);
    }
}
