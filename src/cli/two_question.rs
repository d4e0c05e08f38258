//! What `boltzone two`'s arguments ask, in the library's terms, for every route of the command
//! (modules `two`, `two_hankel`, `two_pair`, `two_rim`): the joint, the route layer's question,
//! the rules of thumb beside an answer, and the plausibility warnings named by flag.
//!
//! # Accuracy
//!
//! No numerics: translations of the flags (`tests/compare/one_question.rs`: `two` and the
//! other front ends give the same bits).
//!
//! # Cost
//!
//! None beyond the route layer's.

use super::exit::{num, usage};
use super::print::rules_line;
use super::two_args::{Args, Interface, Shape};
use boltzone::contact::two_plate::{InterfaceModel, Loading};
use boltzone::route::{rules_beside, sanity, two_plate};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Peak, Plate, Value};
use std::f64::consts::PI;

/// The bearing pressure P of the arguments (--p, or --force spread over the bearing face).
pub(super) fn pressure(args: &Args) -> f64 {
    match args.force {
        Some(f) => f / (PI * (args.geom.b * args.geom.b - args.geom.a * args.geom.a)),
        None => args.p,
    }
}

/// The joint of checked arguments (the --units lengths and stresses).
pub(super) fn joint(args: &Args) -> anyhow::Result<Joint> {
    let upper_mat = Material::new(args.e(), args.geom.nu)?;
    let lower_mat = Material::new(
        args.e2.unwrap_or(args.e()),
        args.nu2.unwrap_or(args.geom.nu),
    )?;
    let (a, b, p) = (args.geom.a, args.geom.b, pressure(args));
    let load = match args.load {
        Shape::Uniform => FaceLoad::uniform(a, b, p)?,
        Shape::PeakA => FaceLoad::triangular(a, b, p, Peak::AtA)?,
        Shape::PeakB => FaceLoad::triangular(a, b, p, Peak::AtB)?,
    };
    let joint = Joint::new(
        a,
        args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite),
        Plate::new(args.geom.d, upper_mat)?,
        Plate::new(args.d2.unwrap_or(args.geom.d), lower_mat)?,
        load,
    )?;
    // the nut's own face (the head's profile and force over A..B₂)
    Ok(match args.b2 {
        Some(b2) => joint.with_nut_outer_radius(b2)?,
        None => joint,
    })
}

/// The rules of thumb beside `r_o` (the route layer's [`rules_beside::beside`], the 30° cone
/// third) for the arguments' B, D, D₂, C.
pub(super) fn rules(args: &Args, r_o: Value) -> rules_beside::Rules {
    let g = &args.geom;
    let c = args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    rules_beside::beside((g.b, g.d, args.d2.unwrap_or(g.d), c), 30.0, r_o)
}

/// Adds the rules of thumb beside the JSON answer `out` (its `r_o`, `r_o_error`, `converged`):
/// keys `rules` ([{name, half_angle_degrees, radius, truncated, error_percent}]) and, where a
/// rule does not apply, `rules_left_out` ([{name, reason}]).
pub(super) fn add_rules(out: &mut serde_json::Value, args: &Args) -> anyhow::Result<()> {
    let r_o = Value {
        value: out["r_o"].as_f64().unwrap_or(f64::NAN),
        error: out["r_o_error"].as_f64().unwrap_or(f64::NAN),
        converged: out["converged"].as_bool().unwrap_or(false),
    };
    if let (serde_json::Value::Object(m), serde_json::Value::Object(r)) =
        (out, serde_json::to_value(rules(args, r_o))?)
    {
        m.extend(r);
    }
    Ok(())
}

/// Prints the JSON answer `v` of a semi-analytic or table route with the rules of thumb beside
/// its R_o ([`add_rules`]) and the run's stamp (version, command, inputs, seconds since `start`).
pub(super) fn print_json(
    mut v: serde_json::Value,
    args: &Args,
    start: std::time::Instant,
) -> anyhow::Result<()> {
    add_rules(&mut v, args)?;
    super::output::stamp(&mut v, &args.inputs()?, start)?;
    super::print_json(&v)
}

/// Prints the rules of thumb beside `r_o`, one line (text output).
pub(super) fn print_rules(args: &Args, r_o: Value) {
    println!("{}", rules_line(&rules(args, r_o), args.units.length()));
}

/// Prints the plausibility warnings `w` on stderr naming their flags, or with `--strict`
/// refuses the first as bad input (exit 2).
pub(super) fn warn(args: &Args, w: &[sanity::Warning]) -> anyhow::Result<()> {
    for w in w {
        let (flag, value) = match w.slip {
            sanity::Slip::Modulus { plate: 0 } => ("--e", args.e()),
            sanity::Slip::Modulus { .. } => ("--e2", args.e2.unwrap_or(args.e())),
            sanity::Slip::Pressure => match args.force {
                Some(f) => ("--force", f),
                None => ("--p", args.p),
            },
            sanity::Slip::Deflection => ("--p/--force/--e", pressure(args)),
        };
        let value = num(value);
        if args.strict {
            return usage(flag, value, &format!("{} (--strict)", w.message));
        }
        eprintln!("warning: {flag} = {value}: {}", w.message);
    }
    Ok(())
}

/// The route layer's question of the arguments on their `joint`.
pub(super) fn question<'a>(args: &Args, joint: &'a Joint) -> two_plate::Question<'a> {
    two_plate::Question {
        joint,
        interface: match args.interface {
            Interface::Welded => InterfaceModel::Welded,
            Interface::Frictionless => InterfaceModel::Frictionless,
            Interface::Friction => InterfaceModel::Friction {
                mu: args.mu.unwrap_or(0.0),
            },
        },
        loading: args
            .nut_displacement
            .map_or(Loading::Pressure, Loading::NutDisplacement),
        fixed_edge: args.fixed_edge,
        thermal: false,
        field: args.out.field.is_some() || args.out.plot.is_some() || args.report.is_some(),
        conductance: args.heat.conductance,
        stiffness: args.bolt.stiffness || args.bolt.bolt.is_some(),
        curve: args.out.curve.is_some(),
        method: args.method,
        tolerance: args.tol,
    }
}

/// The answer's first text line: R_o ± error (R_o to `digits.0` significant digits), R_o/A
/// (with a hole) and 2R_o (to `digits.1`), and `missed` after it when not converged.
pub(super) fn r_o_line(args: &Args, r_o: Value, digits: (usize, usize), missed: &str) -> String {
    let l = args.units.length();
    let a = args.geom.a;
    let over_a = match a > 0.0 {
        true => format!("R_o/A = {}, ", super::exit::sig(r_o.value / a, digits.1)),
        false => String::new(),
    };
    format!(
        "R_o = {} ± {:.1e} {l}   ({over_a}2R_o = {} {l}){}",
        super::exit::sig(r_o.value, digits.0),
        r_o.error,
        super::exit::sig(2.0 * r_o.value, digits.1),
        if r_o.converged { "" } else { missed }
    )
}
