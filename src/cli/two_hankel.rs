//! `boltzone two --method hankel|auto`: the two-plate model with the hole by the semi-analytic
//! route ([`boltzone::hankel::receding::holed`]): equal plates, frictionless (exact for equal
//! plates), infinite or with a free rim --c (beyond B + D: the rim's bending correction of
//! `hankel::receding::rim_holed`), pressed by a pressure profile; R_o with its error estimate, and with
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
//! geometry (2026-11-25, load 1.5–2.5; module `hankel::receding::holed`'s Cost): 0.06–0.11 s
//! of CPU at --tol 1e-3, 0.35–0.77 s at 1e-6 (all twelve converged), with --c 1.54 1.0–2.0 s at
//! 1e-6; 1.4–2.2 s at 1e-8 (every row converged there; load 9–12, before the hole tables);
//! timed by example 19.

use super::exit::{declined, sig, Status};
use super::two_args::{Args, Method};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::hankel::receding::{MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// Why the Hankel route does not apply to these arguments: (flag, value, reason).
pub fn unsupported(args: &Args) -> Option<(&'static str, String, &'static str)> {
    let g = &args.geom;
    let why = "needs --method fem (the Hankel route: infinite plates pressed by a pressure, R_o \
               only; with a hole two equal plates, without one (--a 0) any two plates in \
               frictionless contact)";
    let differs = |x: Option<f64>, y: f64| x.is_some_and(|v| v != y);
    let unequal = [
        ("--d2", args.d2, differs(args.d2, g.d)),
        ("--e2", args.e2, differs(args.e2, args.e())),
        ("--nu2", args.nu2, differs(args.nu2, g.nu)),
    ];
    let refusal = if g.a <= 0.0 {
        super::two_pair::unsupported(args, why)
    } else {
        unequal
            .into_iter()
            .find(|u| u.2)
            .map(|(flag, value, _)| (flag, format!("{value:?}"), why))
    };
    if refusal.is_some() {
        return refusal;
    }
    if g.a > 0.0 && g.a < MIN_A_OVER_D * g.d {
        return Some((
            "--a",
            g.a.to_string(),
            "is below the Hankel route's smallest hole (A at least 0.04 plate thicknesses: \
             smaller holes left residual tractions of 1e1-1e4 P on the hole); use --method fem \
             or --a 0 (the receding contact, within A² of it)",
        ));
    }
    if g.a > 0.0 && g.b > MAX_B_OVER_D * g.d {
        return Some((
            "--b",
            g.b.to_string(),
            "is beyond the Hankel route's reach with a hole (B at most 16 plate thicknesses: \
             its cost grows like (B/D)², 4.7 s and 0.6 GB at 16, 18 s and 2.0 GB at 32); use \
             --method fem",
        ));
    }
    if let Some(c) = args.c {
        if g.a <= 0.0 && !super::two_pair::equal_plates(args) {
            return Some((
                "--c",
                c.to_string(),
                "needs --method fem with unequal plates (the Hankel route's finite rim takes \
                 two equal plates, with or without a hole)",
            ));
        }
        if g.b > MAX_B_OVER_D_RIM * g.d {
            return Some((
                "--b",
                g.b.to_string(),
                "is beyond the Hankel route's reach with a finite rim --c (B at most 8 plate \
                 thicknesses: the rim's cost grows like (B/D)², with a hole 10.5 s at 8, 35 s \
                 at 16; without one 1.6 s at 8, 9.9 s at 16, 55 s at 32); use --method fem",
            ));
        }
        if c <= g.b + g.d {
            return Some((
                "--c",
                c.to_string(),
                "must exceed --b by more than --d for the Hankel route's finite rim (its rim \
                 residue decays over C - R_o); use --method fem",
            ));
        }
    }
    if let Some(n) = args.nut_displacement {
        return Some(("--nut-displacement", n.to_string(), why));
    }
    if args.fixed_edge {
        return Some(("--fixed-edge", "given".into(), why));
    }
    if args.out.field.is_some() || args.out.plot.is_some() || args.report.is_some() {
        return Some(("--field/--plot/--report", "given".into(), why));
    }
    None
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
    if args.method == Method::Auto && !out.info.hole_resolved {
        return Err(declined(boltzone::scene::two_hankel::UNRESOLVED));
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
        let mut v = serde_json::json!({
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
        super::output::stamp(&mut v, &args.inputs()?, start)?;
        super::print_json(&v)?;
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
