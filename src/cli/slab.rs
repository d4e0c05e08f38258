//! `boltzone slab`: the single-plate separation radius R_o of the infinite slab 2D thick (no
//! hole) under a uniform face pressure on A ≤ r ≤ B, by Hankel transforms
//! ([`boltzone::hankel::separation`]), and optionally the midplane σ_z/P curve as CSV.

use super::args::Geometry;
use anyhow::Context;
use boltzone::hankel::{Midplane, MidplaneCurve, SeparationParams, Slab};
use boltzone::{FaceLoad, Material};
use std::io::Write;
use std::path::PathBuf;

/// Arguments of `boltzone slab`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    geom: Geometry,
    /// Relative tolerance on R_o.
    #[arg(long, default_value_t = 1e-10)]
    tol: f64,
    /// Print one JSON object instead of text.
    #[arg(long)]
    json: bool,
    /// Write the midplane σ_z/P against r/A (0 ≤ r ≤ max(3B, B + 6D)) to this CSV file.
    #[arg(long)]
    curve: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<()> {
    let material = Material::unit(args.geom.nu)?;
    let load = FaceLoad::uniform(args.geom.a, args.geom.b, 1.0)?;
    if args.geom.a <= 0.0 {
        anyhow::bail!(
            "hole radius A = {} must be positive (R_o is reported as R_o/A)",
            args.geom.a
        );
    }
    let slab = Slab::new(args.geom.d, material, load)?;
    let params = SeparationParams {
        rel_tol: args.tol,
        ..Default::default()
    };
    let sep = slab.separation_radius(&params)?;
    if let Some(path) = &args.curve {
        write_curve(&slab, args.geom.a, path)
            .with_context(|| format!("writing {}", path.display()))?;
    }
    if args.json {
        let v = serde_json::json!({
            "a": args.geom.a, "b": args.geom.b, "d": args.geom.d, "nu": args.geom.nu,
            "r_o": sep.r_o,
            "r_o_over_a": sep.r_o / args.geom.a,
            "r_o_error": sep.error,
            "evaluations": sep.evaluations,
            "seconds": sep.seconds,
            "model": "infinite slab 2D thick, no hole, uniform load on both faces (Hankel transforms)",
        });
        println!("{v}");
    } else {
        println!(
            "infinite slab 2D thick (D = {} in), no hole, uniform load on {} ≤ r ≤ {} in",
            args.geom.d, args.geom.a, args.geom.b
        );
        println!("R_o   = {:.12} in  ± {:.1e}", sep.r_o, sep.error);
        println!(
            "R_o/A = {:.12}  ± {:.1e}",
            sep.r_o / args.geom.a,
            sep.error / args.geom.a
        );
        println!(
            "({} midplane evaluations, {:.2} ms)",
            sep.evaluations,
            1e3 * sep.seconds
        );
    }
    Ok(())
}

/// Writes the curve to a temporary file beside `path`, then renames it (nothing half-written).
fn write_curve(slab: &Slab, a: f64, path: &std::path::Path) -> anyhow::Result<()> {
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
    let tmp = path.with_extension("csv.tmp");
    {
        let mut f = std::io::BufWriter::new(std::fs::File::create(&tmp)?);
        writeln!(f, "# midplane sigma_z/P of the infinite slab (no hole), D = {d} in, A = {a} in, B = {b} in; compression negative")?;
        writeln!(f, "r_over_a,sigma_z_over_p,error_over_p")?;
        let n = 1000;
        for k in 0..=n {
            let r = r_end * k as f64 / n as f64;
            let e = eval(r);
            writeln!(f, "{},{},{:.1e}", r / a, e.value, e.error)?;
        }
        f.flush()?;
    }
    std::fs::rename(&tmp, path)?;
    Ok(())
}
