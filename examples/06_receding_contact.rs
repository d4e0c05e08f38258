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
//! (4) the finite-element two-plate solver (`contact::two_plate`) beside it: FE at outer radii
//! C = 8, 16, 32 R_o (its plate is finite; the C-effect is O((R_o/C)²), see
//! tests/contact/receding_vs_fe.rs), the ratio of successive differences (≈ 4 for C⁻²), the
//! C⁻²-extrapolated FE value and its difference from ours; FE's extrapolated R_o for several ν
//! (the exact R_o does not depend on ν); then pressure and gap curves.
//!
//! Self-checks (panics): every error estimate below 1e-8·D; geometric convergence (each step of
//! 4 nodes gains at least a factor 10 until rounding); R_o/D grows with B/D; equilibrium of the
//! contact pressure ("equil.", relative); the displacement integral flat on the contact zone
//! ("flat": max |w(r,0) − w(R_o,0)| for r ≤ R_o per gap at 1.5 R_o); FE within issue 4's
//! 0.05 % of R_o after the C-extrapolation. `BOLTZONE_QUICK=1` runs a reduced set (the test
//! suite does).
//!
//! Literature: Keer, Dundurs & Tsai (1972, *J. Appl. Mech.* 39, 1115–1120) tabulate the
//! contact radius of a layer on a half-space against the load radius; their values for a rigid
//! base were not found in the sources searched, so none are printed here.
//!
//! Builds on: example 01 (the slab's kernels) and 04 (the FE two-plate model it checks).

use boltzone::contact::two_plate::{solve as solve_fe, TwoPlateParams, TwoPlateSolution};
use boltzone::hankel::receding::{Layer, RecedingContact, RecedingParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Peak, Plate};
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
            c.info.r_o_error,
            c.info.solves,
            1e3 * c.info.seconds,
            eq,
            flat
        );
        assert!(
            c.info.r_o_error < 1e-8 * d,
            "B/D = {bd}: error {}",
            c.info.r_o_error
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
            c.info.r_o_error,
            eq,
            c.solution.pressure(0.0) * PI * d * d / f,
            1e3 * c.info.seconds
        );
        assert!(eq.abs() < 1e-9 && c.info.r_o_error < 1e-8 * d);
    }

    fe_comparison(d);
}

/// FE two-plate solution of the plate `d` thick under `load` (hole radius = the load's inner
/// radius), outer radius `c`, tolerance 1e-5 on R_o, ν = 0.3. It refines until its level
/// estimate is below the 2e-5 of R_o that every two-plate estimate carries
/// (`contact::two_plate`), and so says "not converged" at 1e-5.
fn fe(load: &FaceLoad, d: f64, c: f64) -> TwoPlateSolution {
    fe_nu(load, d, c, 0.3)
}

/// [`fe`] with Poisson's ratio `nu`, converged or not.
fn fe_nu(load: &FaceLoad, d: f64, c: f64, nu: f64) -> TwoPlateSolution {
    let plate = Plate::new(d, Material::unit(nu).expect("valid ν")).expect("plate");
    let joint = Joint::new(
        load.inner(),
        OuterRadius::Finite(c),
        plate,
        plate,
        load.clone(),
    )
    .expect("joint");
    let params = TwoPlateParams {
        tolerance: 1e-5,
        ..Default::default()
    };
    solve_fe(&joint, &params).expect("FE contact solution")
}

fn fe_comparison(d: f64) {
    println!(
        "\n(4) FE two-plate solver (symmetric model, Q9, tolerance 1e-5) at C = 8, 16, 32 R_o"
    );
    println!(
        "{:>5} {:>13} {:>13} {:>13} {:>13} {:>6} {:>13} {:>9} {:>8}",
        "B/D",
        "Hankel R_o/D",
        "FE C=8R",
        "FE C=16R",
        "FE C=32R",
        "ratio",
        "FE C->inf",
        "diff/R_o",
        "FE [s]"
    );
    let ratios: &[f64] = if quick() { &[1.0] } else { &[0.5, 1.0, 2.0] };
    let mut last = None;
    for &bd in ratios {
        let load = FaceLoad::uniform(0.0, bd * d, 1.0).expect("disk load");
        let h = solve(d, load.clone(), &RecedingParams::default());
        let r = h.r_o;
        let fes: Vec<TwoPlateSolution> = [8.0, 16.0, 32.0]
            .iter()
            .map(|k| fe(&load, d, k * r))
            .collect();
        let v: Vec<f64> = fes.iter().map(|s| s.r_o).collect();
        let ratio = (v[0] - r) / (v[1] - r);
        let r_inf = v[2] + (v[2] - v[1]) / 3.0;
        let time: f64 = fes.iter().map(|s| s.info.seconds).sum();
        println!(
            "{:>5} {:>13.9} {:>13.9} {:>13.9} {:>13.9} {:>6.2} {:>13.9} {:>+9.1e} {:>8.2}",
            bd,
            r / d,
            v[0] / d,
            v[1] / d,
            v[2] / d,
            ratio,
            r_inf / d,
            (r_inf - r) / r,
            time
        );
        println!(
            "      FE error estimates: {:.1e} {:.1e} {:.1e}; Hankel {:.1e}",
            fes[0].r_o_error, fes[1].r_o_error, fes[2].r_o_error, h.info.r_o_error
        );
        assert!(
            (r_inf - r).abs() < 5e-4 * r,
            "B/D = {bd}: FE and Hankel differ beyond 0.05 %"
        );
        last = fes.into_iter().last().map(|s| (h, s, load));
    }
    if !quick() {
        // the exact R_o does not depend on ν (the layer kernels do not): the FE's should not
        let load = FaceLoad::uniform(0.0, d, 1.0).expect("disk load");
        let r = solve(d, load.clone(), &RecedingParams::default()).r_o;
        println!("\nB = D: FE R_o extrapolated from C = 16, 32 R_o against nu (Hankel: {:.9} for all nu)", r / d);
        for nu in [0.0, 0.3, 0.45] {
            let s: Vec<TwoPlateSolution> = [16.0, 32.0]
                .iter()
                .map(|k| fe_nu(&load, d, k * r, nu))
                .collect();
            let r_inf = s[1].r_o + (s[1].r_o - s[0].r_o) / 3.0;
            println!(
                "  nu = {nu:4}: FE {:.9}  diff/R_o {:+.1e}  (FE estimates {:.1e} {:.1e}, converged {})",
                r_inf / d,
                (r_inf - r) / r,
                s[0].r_o_error,
                s[1].r_o_error,
                s[0].converged && s[1].converged
            );
        }
    }
    let (h, s, load) = last.expect("one geometry");
    let mean = load.mean_pressure();
    println!(
        "\npressure q/p_mean and gap/(p_mean D/E) on the interface, B/D = {}, FE at C = 32 R_o",
        load.outer() / d
    );
    println!(
        "(FE: nodal force over tributary area, so 0 at the axis node of a solid plate; gap: half"
    );
    println!(" the FE's two-plate gap, i.e. one plate's lift)");
    println!(
        "{:>8} {:>12} {:>12} {:>12} {:>12}",
        "r/R_o", "q Hankel", "q FE", "gap Hankel", "gap FE"
    );
    for k in [0.0, 0.25, 0.5, 0.75, 0.9, 0.97, 1.03, 1.1, 1.3, 1.6, 2.0] {
        let r = k * h.r_o;
        // FE's symmetric-model gap is between two plates: twice one plate's lift
        println!(
            "{:>8.2} {:>12.6} {:>12.6} {:>12.4e} {:>12.4e}",
            k,
            h.solution.pressure(r) / mean,
            s.pressure_at(r) / mean,
            h.solution.gap(r) / (mean * d),
            0.5 * s.gap_at(r) / (mean * d)
        );
    }
}
