//! `boltzone two --method hankel|auto --a 0`: two infinite plates without a hole, equal or
//! unequal (`--d2`, `--e2`, `--nu2`) in frictionless contact, by the semi-analytic receding
//! contact of the two plates in series ([`boltzone::hankel::receding::Pair`]): R_o with its
//! error estimate, and with `--curve` the interface pressure on 0 ≤ r ≤ R_o in the FE's CSV
//! layout. Equal plates carry no interface shear (symmetry), so any `--interface` is exact for
//! them; unequal plates need `--interface frictionless`.
//!
//! # Accuracy
//!
//! That of [`boltzone::hankel::receding::Pair`] (`tests/hankel/receding_pair.rs`); the command:
//! `tests/hankel/pair_cli.rs` (the library value, exit codes, the flags it refuses).
//!
//! # Cost
//!
//! One receding-contact solve ([`boltzone::hankel::receding::pair`]): 0.1–0.2 s at B ≈ D,
//! seconds at B ≈ 8 thicknesses of the thinner plate.

use super::exit::{sig, Status};
use super::two_args::Args;
use boltzone::hankel::receding::{Pair, RecedingParams};
use boltzone::{FaceLoad, Material, Plate};

/// Points of the `--curve` (plus one).
const CURVE_POINTS: usize = 100;

/// The `--curve`'s radii on [0, R_o], denser toward R_o (q ~ √(R_o − r)).
pub fn curve_radii(r_o: f64) -> Vec<f64> {
    (0..=CURVE_POINTS)
        .map(|k| r_o * (1.0 - (1.0 - k as f64 / CURVE_POINTS as f64).powi(2)))
        .collect()
}

/// The text output's first lines: R_o, its estimate, 2R_o, in the length unit, and the rules of
/// thumb beside it.
pub fn print_r_o(args: &Args, r_o: f64, error: f64, converged: bool) {
    let value = boltzone::Value {
        value: r_o,
        error,
        converged,
    };
    let l = args.units.length();
    let note = if converged {
        ""
    } else {
        "  NOT converged to --tol (exit 3)"
    };
    println!(
        "R_o = {} ± {error:.1e} {l}   (2R_o = {} {l}){note}",
        sig(r_o, 10),
        sig(2.0 * r_o, 10),
    );
    super::two_question::print_rules(args, value);
}

/// Runs the route on checked arguments with bearing pressure `load`.
pub fn run(args: &Args, load: FaceLoad, start: std::time::Instant) -> anyhow::Result<Status> {
    let g = &args.geom;
    let upper = Plate::new(g.d, Material::new(args.e(), g.nu)?)?;
    let lower = Plate::new(
        args.d2.unwrap_or(g.d),
        Material::new(args.e2.unwrap_or(args.e()), args.nu2.unwrap_or(g.nu))?,
    )?;
    // every flag was checked: what the route rejects now is beyond its reach (exit 1)
    let out = Pair::new(upper, lower, load)
        .receding_contact(&RecedingParams::default())
        .map_err(super::exit::declined)?;
    let (r_o, error) = (out.r_o, out.info.r_o_error);
    let converged = error <= args.tol * r_o;
    if let Some(path) = &args.out.curve {
        let curve: Vec<(f64, f64)> = curve_radii(r_o)
            .into_iter()
            .map(|r| (r, out.solution.pressure(r)))
            .collect();
        let method = "Hankel, receding contact of the two plates in series \
                      (boltzone::hankel::receding::Pair), interface 0 <= r <= R_o";
        let text = super::two_curve::curve_csv(&curve, method, (r_o, error), converged, args);
        super::write_output(path, &text)?;
    }
    let i = &out.info;
    if !args.json {
        print_r_o(args, r_o, error, converged);
        println!(
            "method: Hankel (receding contact of the two plates in series, no hole); {} Nystrom \
             points, {} systems solved; {:.3} s",
            i.nodes, i.solves, i.seconds
        );
        return Ok(Status::from_converged(converged));
    }
    let hankel = serde_json::json!({
        "nodes": i.nodes,
        "xi_nodes": i.xi_nodes,
        "solves": i.solves,
        "r_o_coarse": i.r_o_coarse,
        "min_pressure": i.min_pressure,
        "min_gap": i.min_gap,
    });
    let interface = "frictionless (receding contact of the two plates, no hole)";
    let result = (r_o, error, converged, i.seconds);
    print_json(args, start, result, interface, hankel)
}

/// Prints the JSON record of a no-hole Hankel run: `result` = (R_o, its estimate, converged,
/// seconds), `hankel` the route's record; the exit status by `converged`.
pub fn print_json(
    args: &Args,
    start: std::time::Instant,
    result: (f64, f64, bool, f64),
    interface: &str,
    hankel: serde_json::Value,
) -> anyhow::Result<Status> {
    let (r_o, error, converged, seconds) = result;
    let v = serde_json::json!({
        "method": "hankel",
        "r_o": r_o,
        "r_o_error": error,
        "converged": converged,
        "tolerance": args.tol,
        "interface": interface,
        "hankel": hankel,
        "seconds": seconds,
        "units": args.units.units.name(),
    });
    super::two_question::print_json(v, args, start)?;
    Ok(Status::from_converged(converged))
}
