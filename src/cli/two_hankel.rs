//! `boltzone two --method hankel|auto`: the two-plate model with the hole by the semi-analytic
//! route ([`boltzone::hankel::receding::holed`]): equal plates, frictionless (exact for equal
//! plates), infinite or with a free rim --c (beyond B + D: the rim's bending correction of
//! `hankel::receding::holed::rim`), pressed by a pressure profile; R_o with its error estimate, and with
//! `--curve` the interface pressure on A ≤ r ≤ R_o in the FE's CSV layout.
//!
//! # Accuracy
//!
//! That of [`boltzone::hankel::receding::holed`] (`tests/hankel/two_plate_hole.rs`); the flags it
//! refuses: `two_method_hankel_refuses_what_it_cannot_do` in the same file.
//!
//! # Cost
//!
//! The holed route's with the knobs for --tol ([`two_plate_hole_to`]: tighter knobs only where
//! those fall short, none of Table 1's rows), per Table 1
//! geometry (load 1.5–2.5; module `hankel::receding::holed`'s Cost): 0.06–0.11 s
//! of CPU at --tol 1e-3, 0.35–0.77 s at 1e-6 (all twelve converged), with --c 1.54 1.0–2.0 s at
//! 1e-6; 1.4–2.2 s at 1e-8 (every row converged there; load 9–12, before the hole tables);
//! timed by example 19.

use super::exit::{declined, sig, Status};
use super::two_args::Args;
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::route::two_plate::{self, Key};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use clap::ValueEnum;

/// Why the Hankel routes do not take these arguments: (flag, value, reason), the route layer's
/// [`two_plate::hankel_blocker`] with its input named by the flag. Arguments whose joint
/// cannot be built are left to the other checks.
pub fn unsupported(args: &Args) -> Option<(&'static str, String, String)> {
    let joint = super::two_question::joint(args).ok()?;
    let b = two_plate::hankel_blocker(&super::two_question::question(args, &joint))?;
    Some(named(args, b))
}

/// Why the tables do not take these arguments (the route layer's [`two_plate::table_answer`]),
/// as [`unsupported`].
pub fn table_unsupported(args: &Args) -> Option<(&'static str, String, String)> {
    let joint = super::two_question::joint(args).ok()?;
    let q = super::two_question::question(args, &joint);
    two_plate::table_answer(&q).err().map(|b| named(args, b))
}

/// The blocker `b` named by its flag and the flag's value.
fn named(args: &Args, b: two_plate::Blocker) -> (&'static str, String, String) {
    let g = &args.geom;
    let given = || "given".to_string();
    let (flag, value) = match b.key {
        Key::LowerThickness => ("--d2", args.d2.unwrap_or(g.d).to_string()),
        Key::LowerModulus => ("--e2", args.e2.unwrap_or(args.e()).to_string()),
        Key::LowerPoisson => ("--nu2", args.nu2.unwrap_or(g.nu).to_string()),
        Key::Poisson => ("--nu", g.nu.to_string()),
        Key::LoadProfile => (
            "--load",
            args.load
                .to_possible_value()
                .map_or_else(String::new, |v| v.get_name().to_string()),
        ),
        Key::Interface => (
            "--interface",
            args.interface
                .to_possible_value()
                .map_or_else(String::new, |v| v.get_name().to_string()),
        ),
        Key::OuterRadius => ("--c", args.c.map_or_else(given, |c| c.to_string())),
        Key::HoleRadius => ("--a", g.a.to_string()),
        Key::LoadOuterRadius => ("--b", g.b.to_string()),
        Key::NutOuterRadius => ("--b2", args.b2.map_or_else(given, |b| b.to_string())),
        Key::NutDisplacement => (
            "--nut-displacement",
            args.nut_displacement.map_or_else(given, |n| n.to_string()),
        ),
        Key::OuterEdge => ("--fixed-edge", given()),
        Key::Curve => ("--curve", given()),
        Key::Field | Key::Temperature => ("--field/--plot/--report", given()),
        Key::Conductance => ("--conductance", given()),
        Key::Stiffness => ("--stiffness", given()),
        Key::Tolerance => ("--tol", args.tol.to_string()),
    };
    (flag, value, format!("{}; use --method fem", b.reason))
}

/// Points of the `--curve` (plus one).
const CURVE_POINTS: usize = 100;

/// Runs the Hankel route on checked arguments with bearing pressure `load`.
pub fn run(args: &Args, load: FaceLoad, start: std::time::Instant) -> anyhow::Result<Status> {
    let g = &args.geom;
    let plate = SinglePlate::new(
        g.a,
        args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite),
        g.d,
        Material::new(args.e(), g.nu)?,
        load,
    )?;
    // every flag was checked: what the route rejects now is a geometry beyond its reach, a
    // limit of the method (exit 1), not bad input
    // the curve: CURVE_POINTS + 1 radii from A to R_o, denser toward R_o (q ~ √(R_o − r))
    let at: Vec<f64> = match &args.out.curve {
        Some(_) => (0..=CURVE_POINTS)
            .map(|k| 1.0 - (1.0 - k as f64 / CURVE_POINTS as f64).powi(2))
            .collect(),
        None => Vec::new(),
    };
    let (out, curve) = two_plate_hole_to(&plate, args.tol, &at).map_err(declined)?;
    if two_plate::fall_back(args.method, false, out.info.hole_resolved) {
        return Err(declined(two_plate::UNRESOLVED));
    }
    let converged = out.meets(args.tol);
    if let Some(path) = &args.out.curve {
        let method = "Hankel route with the hole (boltzone::hankel::receding::holed), \
                      interface A <= r <= R_o";
        let r_o = (out.r_o, out.info.r_o_error);
        super::write_output(
            path,
            &super::two_curve::curve_csv(&curve, method, r_o, converged, args),
        )?;
    }
    if args.json {
        let v = serde_json::json!({
            "method": "hankel",
            "r_o": out.r_o,
            "r_o_over_a": out.r_o / g.a,
            "r_o_error": out.info.r_o_error,
            "converged": converged,
            "tolerance": args.tol,
            "interface": "symmetric (one plate on a rigid frictionless plane)",
            "hankel": out.info,
            "seconds": out.info.seconds,
            "units": args.units.units.name(),
        });
        super::two_question::print_json(v, args, start)?;
    } else {
        let l = args.units.length();
        println!(
            "R_o = {} ± {:.1e} {l}   (R_o/A = {}, 2R_o = {} {l}){}",
            sig(out.r_o, 10),
            out.info.r_o_error,
            sig(out.r_o / g.a, 10),
            sig(2.0 * out.r_o, 10),
            if converged {
                ""
            } else if !out.info.hole_resolved {
                "  NOT converged to --tol (exit 3): the hole modes stopped short of their \
                 residual target, so the estimate is not trusted (narrow load on a small hole?)"
            } else {
                "  NOT converged to --tol (exit 3)"
            }
        );
        println!(
            "method: Hankel (bilateral holed plate + crack field + hole correction); hole residual \
             traction {:.1e} P (bilateral {:.1e} P); {} contact radii tried; {:.3} s",
            out.info.residual_max,
            out.info.bilateral_residual,
            out.info.solves,
            out.info.seconds
        );
        let r_o = boltzone::Value {
            value: out.r_o,
            error: out.info.r_o_error,
            converged,
        };
        super::two_question::print_rules(args, r_o);
        if let Some(rim) = out.info.rim {
            println!(
                "rim C = {} {l}: R_o - R_o(infinite plate) = {:+.4e} {l} (bending correction; its \
                 self-equilibrated residue bounded by {:.1e} {l}, included)",
                sig(rim.outer_radius, 10),
                out.r_o - rim.r_o_infinite,
                rim.decay_bound
            );
        }
    }
    Ok(Status::from_converged(converged))
}
