//! `boltzone slab`: the single-plate separation radius R_o of the infinite slab 2D thick (no
//! hole) under a uniform face pressure on A ≤ r ≤ B, by Hankel transforms
//! ([`boltzone::hankel::separation`]), and optionally the midplane σ_z/P curve as CSV.
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/hankel/cli.rs` (`json_has_the_keys_and_the_library_value`,
//! `curve_is_written_with_a_header`, `bad_input_names_the_field_and_writes_nothing`).
//!
//! # Cost
//!
//! That of the slab route (`cargo bench --bench hankel`).

use super::args::{Geometry, Units};
use super::check;
use super::exit::{num, sig, Status};
use boltzone::hankel::{Midplane, MidplaneCurve, SeparationParams, Slab};
use boltzone::{FaceLoad, Material};
use std::path::PathBuf;

/// Arguments of `boltzone slab`.
#[derive(Debug, clap::Args, serde::Serialize)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    #[command(flatten)]
    #[serde(flatten)]
    geom: Geometry,
    /// Lengths in (A, B, D and every printed length) and the stress of the curve.
    #[command(flatten)]
    #[serde(flatten)]
    units: Units,
    /// Relative tolerance on R_o.
    #[arg(long, default_value_t = 1e-10, allow_negative_numbers = true)]
    tol: f64,
    /// Print one JSON object instead of text.
    #[arg(long)]
    json: bool,
    /// Write the midplane σ_z at P = 1 (psi, or the --units stress) against r (0 ≤ r ≤
    /// max(3B, B + 6D)) to this CSV file (header `r [in],sigma_z [psi],sigma_z_error [psi]` in
    /// the --units symbols, then `#` provenance lines, then data).
    #[arg(long)]
    curve: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<Status> {
    let start = std::time::Instant::now();
    let g = &args.geom;
    if g.a.is_nan() || g.a <= 0.0 {
        return super::exit::usage(
            "--a",
            g.a,
            "the hole radius A must be positive (R_o is reported as R_o/A)",
        );
    }
    check::annulus(g.a, g.b)?;
    check::positive("--d", "slab half-thickness D (the slab is 2D thick)", g.d)?;
    check::poisson("--nu", g.nu, 0.5)?;
    check::tolerance("--tol", args.tol)?;
    check::domain(g.a, g.b, g.d, check::B_OVER_D_SLAB)?;
    if let Some(path) = &args.curve {
        check::output_path("--curve", path)?;
    }
    let material = Material::unit(args.geom.nu)?;
    let load = FaceLoad::uniform(args.geom.a, args.geom.b, 1.0)?;
    let slab = Slab::new(args.geom.d, material, load)?;
    let params = SeparationParams {
        rel_tol: args.tol,
        ..Default::default()
    };
    let sep = slab.separation_radius(&params)?;
    super::exit::finite("R_o error estimate", sep.r_o_error)?;
    let u = args.units.units;
    let l = u.symbols().0;
    if let Some(path) = &args.curve {
        super::write_output(path, &curve_csv(&slab, &sep, u)?)?;
    }
    if args.json {
        let mut v = serde_json::json!({
            "a": args.geom.a, "b": args.geom.b, "d": args.geom.d, "nu": args.geom.nu,
            "r_o": sep.r_o,
            "r_o_over_a": sep.r_o / args.geom.a,
            "r_o_error": sep.r_o_error,
            "converged": sep.converged,
            "tolerance": args.tol,
            "evaluations": sep.evaluations,
            "seconds": sep.seconds,
            "model": "infinite slab 2D thick, no hole, uniform load on both faces (Hankel transforms)",
            "units": u.name(),
        });
        super::output::stamp(&mut v, &args, start)?;
        super::print_json(&v)?;
    } else {
        println!(
            "infinite slab 2D thick (D = {} {l}), no hole, uniform load on {} ≤ r ≤ {} {l}",
            num(args.geom.d),
            num(args.geom.a),
            num(args.geom.b)
        );
        println!(
            "R_o   = {} {l}  ± {:.1e} {l}{}",
            sig(sep.r_o, 13),
            sep.r_o_error,
            if sep.converged {
                ""
            } else {
                "   NOT converged to --tol (exit 3)"
            }
        );
        println!(
            "R_o/A = {:.12}  ± {:.1e}",
            sep.r_o / args.geom.a,
            sep.r_o_error / args.geom.a
        );
        println!(
            "({} midplane evaluations, {:.2} ms)",
            sep.evaluations,
            1e3 * sep.seconds
        );
    }
    Ok(Status::from_converged(sep.converged))
}

/// The midplane σ_z (P = 1 psi) against r on 0 ≤ r ≤ max(3B, B + 6D), 1001 points, in the one
/// curve layout ([`super::output`]).
fn curve_csv(
    slab: &Slab,
    sep: &boltzone::hankel::SeparationInfo,
    units: boltzone::scene::UnitSystem,
) -> anyhow::Result<String> {
    let (l, st, _) = units.symbols();
    let (b, d) = (slab.load().outer(), slab.half_thickness());
    let r_end = (3.0 * b).max(b + 6.0 * d);
    // interpolated curve, or for very thin slabs (more than MAX_CURVE_PANELS panels of width D)
    // direct evaluation at each radius
    let eval: Box<dyn Fn(f64) -> boltzone::hankel::Estimate> =
        match MidplaneCurve::new(slab, 0.0, r_end, 1e-11) {
            Ok(curve) => Box::new(move |r| curve.eval(r)),
            Err(_) => {
                let m = Midplane::new(slab, r_end, 1e-11)?;
                Box::new(move |r| m.eval(r))
            }
        };
    let notes = [
        format!(
            "method: infinite slab 2D thick without hole (Hankel transforms), D = {d:e} {l}, \
             load on {a:e} <= r <= {b:e} {l} at P = 1 {st} (sigma_z scales with P; compression \
             negative); sigma_z_error = quadrature error estimate",
            a = slab.load().inner()
        ),
        format!(
            "R_o = {:e} {l} +- {:.2e} {l}, converged: {}",
            sep.r_o, sep.r_o_error, sep.converged
        ),
    ];
    let n = 1000;
    let rows: Vec<Vec<f64>> = (0..=n)
        .map(|k| {
            let r = r_end * k as f64 / n as f64;
            let e = eval(r);
            vec![r, e.value, e.error]
        })
        .collect();
    let cols = [
        format!("r [{l}]"),
        format!("sigma_z [{st}]"),
        format!("sigma_z_error [{st}]"),
    ];
    let cols: Vec<&str> = cols.iter().map(String::as_str).collect();
    Ok(super::output::curve_csv_in(units, &cols, &notes, &rows))
}
