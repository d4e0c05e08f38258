//! `boltzone single`: the single-plate model (Fernlund's substitution, a plate 2D thick with a
//! hole, loaded on both faces by a uniform pressure over A..B) and its separation radius R_o.
//! `--method fem` runs [`boltzone::fem::single::single_plate_r_o`] (refinement levels halving the
//! elements at A, B and the previous R_o; error estimate max(|d₃|, |d₂|/4, |d₁|/16) of the last
//! level changes, [`boltzone::numerics::convergence::level_estimate`]); `--method hankel` runs
//! [`boltzone::hankel::hole::single_plate_separation`] (infinite slab + hole correction, and a
//! rim correction when `--c` is given).

use super::args::{Element, Geometry};
use boltzone::fem::single::{single_plate_r_o, FaceCondition, SingleParams};
use boltzone::fem::ElementKind;
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// Which solver computes R_o.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Method {
    /// Axisymmetric finite elements.
    Fem,
    /// Hankel transforms with a hole correction.
    Hankel,
}

/// How the bolt head loads the faces (fem).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Nut {
    /// Uniform bearing pressure over A..B (Table 1).
    Pressure,
    /// Rigid frictionless nut: uniform displacement over A..B (report Fig. 21).
    Rigid,
}

/// Arguments of `boltzone single`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    geom: Geometry,
    /// Plate outer radius C (default: infinite, truncated at B + 30 D).
    #[arg(long)]
    c: Option<f64>,
    /// Solver.
    #[arg(long, value_enum, default_value_t = Method::Fem)]
    method: Method,
    /// Element family (fem).
    #[arg(long, value_enum, default_value_t = Element::Q9)]
    element: Element,
    /// Face loading (fem).
    #[arg(long, value_enum, default_value_t = Nut::Pressure)]
    nut: Nut,
    /// Refinement levels (fem, ≥ 3 for an error estimate).
    #[arg(long, default_value_t = 5)]
    levels: usize,
    /// Corner exponents λ₁, λ₁+1, λ₁+2, λ₂, … whose singular fields enrich the hole fit
    /// (hankel; 0 = Papkovich–Fadle modes only, at most 6).
    #[arg(long, default_value_t = HoleParams::default().corner_terms)]
    corner_terms: usize,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<()> {
    let outer = args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    let load = FaceLoad::uniform(args.geom.a, args.geom.b, 1.0)?;
    let plate = SinglePlate::new(
        args.geom.a,
        outer,
        args.geom.d,
        Material::unit(args.geom.nu)?,
        load,
    )?;
    if args.method == Method::Hankel {
        if args.nut != Nut::Pressure {
            anyhow::bail!(
                "--nut rigid needs --method fem (the Hankel route loads the faces by a pressure)"
            );
        }
        return run_hankel(&args, &plate);
    }
    let kind = ElementKind::from(args.element);
    let loading = match args.nut {
        Nut::Pressure => FaceCondition::Pressure,
        Nut::Rigid => FaceCondition::UniformDisplacement,
    };
    let params = SingleParams {
        loading,
        kind,
        levels: args.levels,
        ..SingleParams::default()
    };
    let (r_o, info) = single_plate_r_o(&plate, &params)?;
    let r_o_over_a = if args.geom.a > 0.0 {
        Some(r_o / args.geom.a)
    } else {
        None
    };
    if args.json {
        let v = serde_json::json!({
            "method": "fem",
            "element": format!("{kind:?}"),
            "loading": format!("{loading:?}"),
            "r_o": r_o,
            "r_o_over_a": r_o_over_a,
            "r_o_error": info.error_estimate,
            "levels": info.levels,
            "observed_order": info.observed_order,
            "nodes": info.nodes,
            "dofs": info.dofs,
            "seconds": info.seconds,
        });
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        println!(
            "single plate 2D thick, FE ({kind:?}), A = {}, B = {}, D = {}, C = {}, nu = {}",
            args.geom.a,
            args.geom.b,
            args.geom.d,
            outer.value(),
            args.geom.nu
        );
        println!("R_o      = {r_o:.6} ± {:.2e}", info.error_estimate);
        if let Some(q) = r_o_over_a {
            println!("R_o / A  = {q:.5}");
        }
        println!(
            "levels   = {:?}\norder    = {}\nmesh     = {} nodes, {} dofs (finest), {:.2} s",
            info.levels,
            info.observed_order
                .map_or("-".into(), |p| format!("{p:.2}")),
            info.nodes,
            info.dofs,
            info.seconds
        );
    }
    Ok(())
}

/// `--method hankel`: R_o of the plate with its hole made traction-free (Hankel route).
fn run_hankel(args: &Args, plate: &SinglePlate) -> anyhow::Result<()> {
    let params = HoleParams {
        corner_terms: args.corner_terms,
        ..HoleParams::default()
    };
    let (sep, hole) = single_plate_separation(plate, &Default::default(), &params)?;
    let r_o_over_a = (args.geom.a > 0.0).then(|| sep.r_o / args.geom.a);
    if args.json {
        let v = serde_json::json!({
            "method": "hankel",
            "r_o": sep.r_o,
            "r_o_over_a": r_o_over_a,
            "r_o_error": sep.error,
            "outer_radius": args.c,
            "hole_terms": hole.terms,
            "hole_corner_terms": hole.corner_terms,
            "hole_residual_max": hole.residual_max,
            "hole_residual_rms": hole.residual_rms,
            "rim_residual_max": hole.rim_residual_max,
            "hole_condition": hole.condition,
            "hole_history": hole.history,
            "evaluations": sep.evaluations + hole.slab_evaluations,
            "seconds": sep.seconds,
        });
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        println!(
            "single plate 2D thick with a hole, Hankel route, A = {}, B = {}, D = {}, C = {}, nu = {}",
            args.geom.a,
            args.geom.b,
            args.geom.d,
            plate.outer_radius().value(),
            args.geom.nu
        );
        println!("R_o      = {:.8} ± {:.2e}", sep.r_o, sep.error);
        if let Some(q) = r_o_over_a {
            println!("R_o / A  = {q:.7}");
        }
        println!(
            "hole     = {} modes + {} corner exponents, residual traction max {:.2e} P, rms {:.2e} P, condition {:.1e}",
            hole.terms, hole.corner_terms, hole.residual_max, hole.residual_rms, hole.condition
        );
        if args.c.is_some() {
            println!(
                "rim      = residual traction max {:.2e} P",
                hole.rim_residual_max
            );
        }
        println!("time     = {:.2} ms", 1e3 * sep.seconds);
    }
    Ok(())
}
