//! `boltzone two --method table|auto`: R_o of two equal plates with a hole (or none), infinite
//! or with a free rim `--c` at least 4 D beyond R_o (the rim table's shift),
//! from the tables built offline by the semi-analytic route ([`boltzone::table::lookup`]),
//! in microseconds, with its bar; `--verify` also runs one solve by the holed route at --tol
//! and prints both with their difference against the summed bars.
//!
//! # Accuracy
//!
//! The tables' own (`tests/table/`); the command's answer against the FE and the route:
//! `tests/table/two_plates.rs`.
//!
//! # Cost
//!
//! A lookup (about a microsecond) and the process's start; with `--verify` the holed route's
//! solve (seconds at 1e-8).

use super::exit::{sig, Status};
use super::two_args::Args;
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::route::two_plate::{self, HankelSolver};
use boltzone::{Material, SinglePlate, Value};

/// Answers `q` (checked arguments whose plan is the tables) from the tables.
pub fn run(
    args: &Args,
    q: &two_plate::Question,
    start: std::time::Instant,
) -> anyhow::Result<Status> {
    let r = two_plate::table_answer(q).map_err(|b| anyhow::anyhow!("{:?} {}", b.key, b.reason))?;
    let g = &args.geom;
    let verify = match args.verify {
        true => Some(verify(args, q)?),
        false => None,
    };
    let difference = verify.map(|v: Value| (r.value - v.value, r.error + v.error));
    if args.json {
        let mut v = serde_json::json!({
            "method": "table",
            "r_o": r.value,
            "r_o_error": r.error,
            "converged": r.converged,
            "tolerance": args.tol,
            "interface": "symmetric (equal plates, infinite, uniform pressure)",
            "units": args.units.units.name(),
            "bearing_pressure": super::two_question::pressure(args),
        });
        if g.a > 0.0 {
            v["r_o_over_a"] = (r.value / g.a).into();
        }
        if let (Some(s), Some((diff, bars))) = (verify, difference) {
            v["verify"] = serde_json::json!({
                "method": "hankel",
                "r_o": s.value,
                "r_o_error": s.error,
                "converged": s.converged,
                "difference": diff,
                "within_bars": diff.abs() <= bars,
            });
        }
        super::two_question::print_json(v, args, start)?;
    } else {
        let l = args.units.length();
        println!(
            "{}",
            super::two_question::r_o_line(
                args,
                r,
                (10, 10),
                "  NOT converged to --tol (exit 3): the tables' bar is above it"
            )
        );
        println!("method: table (built offline by the 1e-8 semi-analytic route; boltzone::table)");
        if let (Some(s), Some((diff, bars))) = (verify, difference) {
            println!(
                "verify: Hankel route R_o = {} ± {:.1e} {l}; table − route = {diff:+.2e} {l} \
                 ({} the summed bars {bars:.1e})",
                sig(s.value, 10),
                s.error,
                if diff.abs() <= bars {
                    "within"
                } else {
                    "OUTSIDE"
                }
            );
        }
        super::two_question::print_rules(args, r);
    }
    Ok(Status::from_converged(r.converged))
}

/// One solve of `q` by the holed route at --tol, with its rim if it has one (the receding
/// contact without a hole).
fn verify(args: &Args, q: &two_plate::Question) -> anyhow::Result<Value> {
    let g = &args.geom;
    let m = Material::new(args.e(), g.nu)?;
    match two_plate::hankel_solver(q.joint) {
        HankelSolver::Holed => {}
        HankelSolver::Pair => {
            let layer = boltzone::hankel::receding::Layer::new(g.d, m, q.joint.load().clone())?;
            let params = boltzone::hankel::receding::RecedingParams::default();
            let c = layer.receding_contact(&params)?;
            return Ok(Value::with_tolerance(c.r_o, c.info.r_o_error, args.tol));
        }
        HankelSolver::Rim(_) => {
            anyhow::bail!("internal: the tables answer a rim only on plates with a hole")
        }
    }
    let plate = SinglePlate::new(g.a, q.joint.outer_radius(), g.d, m, q.joint.load().clone())?;
    let (out, _) = two_plate_hole_to(&plate, args.tol, &[])?;
    Ok(Value {
        converged: out.meets(args.tol),
        ..Value::with_tolerance(out.r_o, out.info.r_o_error, args.tol)
    })
}
