//! `boltzone two`: the two-plate model (report Chapter II.B), solved by
//! [`boltzone::contact::two_plate`]: separation radius R_o with its error, and on request the
//! interface pressure p(r), gap g(r) and (welded) shear τ(r) as CSV.

use anyhow::Context;
use boltzone::contact::two_plate::{
    solve, EdgeSupport, InterfaceModel, Loading, TwoPlateParams, TwoPlateSolution,
};
use boltzone::fem::ElementKind;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Peak, Plate};
use clap::ValueEnum;
use std::f64::consts::PI;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Interface model between unequal or dissimilar plates.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum Interface {
    /// u and w tied inside the contact zone (the report's model).
    Welded,
    /// Only w tied, unilaterally; no shear.
    Frictionless,
}

/// Shape of the bearing pressure under head and nut.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum Shape {
    /// Uniform pressure on A..B.
    Uniform,
    /// Triangular, peak at A (report Fig. 20(a)).
    PeakA,
    /// Triangular, peak at B (report Fig. 20(b)).
    PeakB,
}

/// Element type.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub enum Element {
    /// Biquadratic 9-node quadrilateral.
    Q9,
    /// Bilinear quadrilateral.
    Q4,
    /// Bilinear quadrilateral with B-bar.
    Q4bbar,
    /// The report's four-triangle quadrilateral.
    Cst4,
}

/// Arguments of `boltzone two`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Hole radius A (in).
    #[arg(long)]
    a: f64,
    /// Outer radius B of the bearing annulus (in).
    #[arg(long)]
    b: f64,
    /// Thickness D of the upper plate (in); the lower plate too unless --d2 is given.
    #[arg(long)]
    d: f64,
    /// Thickness of the lower plate (in).
    #[arg(long)]
    d2: Option<f64>,
    /// Outer radius C of the plates (in); infinite if omitted.
    #[arg(long)]
    c: Option<f64>,
    /// Poisson's ratio.
    #[arg(long, default_value_t = 0.3)]
    nu: f64,
    /// Young's modulus E (psi; 304 steel by default).
    #[arg(long, default_value_t = 28.0e6)]
    e: f64,
    /// Poisson's ratio of the lower plate (default: --nu).
    #[arg(long)]
    nu2: Option<f64>,
    /// Young's modulus of the lower plate (default: --e).
    #[arg(long)]
    e2: Option<f64>,
    /// Mean bearing pressure P (psi).
    #[arg(long, default_value_t = 1.0, conflicts_with = "force")]
    p: f64,
    /// Bolt force (lb): sets P = force / (π(B² − A²)).
    #[arg(long)]
    force: Option<f64>,
    /// Pressure profile under head and nut.
    #[arg(long, value_enum, default_value_t = Shape::Uniform)]
    load: Shape,
    /// Instead of a pressure, a uniform displacement (in) of each face under the nut (Fig. 21).
    #[arg(long)]
    nut_displacement: Option<f64>,
    /// Fix the outer edge r = C (Fig. 20(c)).
    #[arg(long)]
    fixed_edge: bool,
    /// Interface model for unequal or dissimilar plates (equal plates are exact either way).
    #[arg(long, value_enum, default_value_t = Interface::Welded)]
    interface: Interface,
    /// Element type (q9: the only one whose R_o error estimate is reliable; the linear ones are
    /// cheaper but can miss the tolerance by a factor of three).
    #[arg(long, value_enum, default_value_t = Element::Q9)]
    element: Element,
    /// Wanted relative error of R_o.
    #[arg(long, default_value_t = 5e-4)]
    tol: f64,
    /// Write r, p(r), g(r), τ(r) of the finest mesh to this CSV file.
    #[arg(long)]
    curve: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<()> {
    let upper_mat = Material::new(args.e, args.nu)?;
    let lower_mat = Material::new(args.e2.unwrap_or(args.e), args.nu2.unwrap_or(args.nu))?;
    let p = match args.force {
        Some(f) => f / (PI * (args.b * args.b - args.a * args.a)),
        None => args.p,
    };
    let load = match args.load {
        Shape::Uniform => FaceLoad::uniform(args.a, args.b, p)?,
        Shape::PeakA => FaceLoad::triangular(args.a, args.b, p, Peak::AtA)?,
        Shape::PeakB => FaceLoad::triangular(args.a, args.b, p, Peak::AtB)?,
    };
    let joint = Joint::new(
        args.a,
        args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite),
        Plate::new(args.d, upper_mat)?,
        Plate::new(args.d2.unwrap_or(args.d), lower_mat)?,
        load,
    )?;
    let params = TwoPlateParams {
        element: match args.element {
            Element::Q9 => ElementKind::Q9,
            Element::Q4 => ElementKind::Q4,
            Element::Q4bbar => ElementKind::Q4Bbar,
            Element::Cst4 => ElementKind::Cst4,
        },
        interface: match args.interface {
            Interface::Welded => InterfaceModel::Welded,
            Interface::Frictionless => InterfaceModel::Frictionless,
        },
        loading: args
            .nut_displacement
            .map_or(Loading::Pressure, Loading::NutDisplacement),
        edge: if args.fixed_edge {
            EdgeSupport::Fixed
        } else {
            EdgeSupport::Free
        },
        tolerance: args.tol,
        ..Default::default()
    };
    let s = solve(&joint, &params)?;
    if let Some(path) = &args.curve {
        write_curve(path, &s).with_context(|| format!("writing {}", path.display()))?;
    }
    let last = s.info.levels.last().expect("one level");
    if args.json {
        let out = serde_json::json!({
            "r_o": s.r_o,
            "r_o_over_a": s.r_o / args.a,
            "r_o_error": s.r_o_error,
            "converged": s.info.converged,
            "interface": s.info.model,
            "nodes": last.nodes,
            "dofs": last.dofs,
            "levels": s.info.levels,
            "rate": s.info.rate,
            "nut_deflection": s.nut_deflection,
            "time_s": s.info.time,
        });
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        println!(
            "R_o = {:.6} ± {:.1e} in   (R_o/A = {:.5}, 2R_o = {:.5} in){}",
            s.r_o,
            s.r_o_error,
            s.r_o / args.a,
            2.0 * s.r_o,
            if s.info.converged {
                ""
            } else {
                "  NOT converged to --tol"
            }
        );
        println!(
            "interface: {}; {} levels, finest mesh {} nodes / {} unknowns, observed rate {}; {:.3} s",
            s.info.model,
            s.info.levels.len(),
            last.nodes,
            last.dofs,
            s.info.rate.map_or("—".into(), |r| format!("{r:.2}")),
            s.info.time
        );
        println!("deflection under the nut: {:.4e} in", s.nut_deflection);
    }
    Ok(())
}

/// Writes r, p, g as CSV through a temporary file renamed into place.
fn write_curve(path: &Path, s: &TwoPlateSolution) -> anyhow::Result<()> {
    let tmp = path.with_extension("csv.tmp");
    {
        let mut f = std::io::BufWriter::new(std::fs::File::create(&tmp)?);
        writeln!(
            f,
            "# boltzone two: interface of the finest mesh; model: {}",
            s.info.model
        )?;
        writeln!(
            f,
            "# r = radius, p = interface pressure (compression > 0), g = gap between the plates, \
             tau = interface shear stress on the upper plate (welded model; 0 otherwise)"
        )?;
        writeln!(f, "r,p,g,tau")?;
        for (((r, p), g), t) in s.radius.iter().zip(&s.pressure).zip(&s.gap).zip(&s.shear) {
            writeln!(f, "{r:.10e},{p:.10e},{g:.10e},{t:.10e}")?;
        }
        f.flush()?;
    }
    std::fs::rename(&tmp, path)?;
    Ok(())
}
