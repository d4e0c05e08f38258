//! `boltzone two --method hankel|auto --a 0 --c C`: two equal plates without a hole, each ending
//! at a free rim r = C, by the semi-analytic receding contact with the rim's bending correction
//! ([`boltzone::hankel::receding::rim::rim_contact`]); the same conventions as the holed rim
//! (module `two_hankel`): C beyond B + D, JSON `hankel.rim` with the holed rim's keys (less the
//! hole's), a text line for the rim's shift of R_o, exit 0 or 3 by `converged`. R_o of the
//! infinite plates (the shift's origin) is the receding contact of the pair
//! ([`boltzone::hankel::receding::Pair`], module `two_pair`).
//!
//! # Accuracy
//!
//! That of [`boltzone::hankel::receding::rim`] (`tests/hankel/two_plate_rim_hankel.rs`); the
//! command against the FE meshed to C, the C⁻² approach to C = ∞ and the refusals:
//! `tests/cli/rim_no_hole.rs`.
//!
//! # Cost
//!
//! One rim solve (two Nyström systems per trial radius) and one receding solve of the pair:
//! 0.1–0.3 s at B ≈ D (timed by `tests/cli/rim_no_hole.rs`); with `--curve` the rim solve runs
//! twice (the curve's radii need R_o).

use super::exit::{sig, Status};
use super::two_args::Args;
use boltzone::hankel::receding::rim::rim_contact;
use boltzone::hankel::receding::{Pair, RecedingParams};
use boltzone::{FaceLoad, Material, Plate};

/// Runs the route on checked arguments (equal plates, `--a 0`, `--c` beyond B + D: checked by
/// [`super::two_hankel::unsupported`]) with bearing pressure `load`.
pub fn run(
    args: &Args,
    c: f64,
    load: FaceLoad,
    start: std::time::Instant,
) -> anyhow::Result<Status> {
    let g = &args.geom;
    let material = Material::new(args.e(), g.nu)?;
    let params = RecedingParams::default();
    let plate = Plate::new(g.d, material)?;
    // every flag was checked: what the route rejects now is beyond its reach (exit 1)
    let beyond = super::exit::declined;
    let (out, _) = rim_contact(g.d, material, &load, c, &params, args.tol, &[]).map_err(beyond)?;
    let infinite = Pair::new(plate, plate, load.clone())
        .receding_contact(&params)
        .map_err(beyond)?;
    let (r_o, error) = (out.r_o, out.info.r_o_error);
    let converged = error <= args.tol * r_o;
    if let Some(path) = &args.out.curve {
        let at = super::two_pair::curve_radii(r_o);
        let (_, curve) =
            rim_contact(g.d, material, &load, c, &params, args.tol, &at).map_err(beyond)?;
        let method = "Hankel, receding contact with the rim's bending correction \
                      (boltzone::hankel::receding::rim), interface 0 <= r <= R_o";
        let text = super::two_curve::curve_csv(&curve, method, (r_o, error), converged, args);
        super::write_output(path, &text)?;
    }
    let i = &out.info;
    let l = args.units.length();
    if !args.json {
        super::two_pair::print_r_o(args, r_o, error, converged);
        println!(
            "method: Hankel (receding contact with the rim's bending correction, no hole); {} \
             Nystrom points, {} systems solved; {:.3} s",
            i.nodes,
            2 * i.solves,
            start.elapsed().as_secs_f64()
        );
        println!(
            "rim C = {} {l}: R_o - R_o(infinite plate) = {:+.4e} {l} (bending correction; its \
             self-equilibrated residue bounded by {:.1e} {l}, included)",
            sig(c, 10),
            r_o - infinite.r_o,
            i.decay_bound
        );
        return Ok(Status::from_converged(converged));
    }
    let hankel = serde_json::json!({
        "nodes": i.nodes,
        "solves": i.solves,
        "r_o_coarse": i.r_o_coarse,
        "rim": {
            "outer_radius": c,
            "r_o_infinite": infinite.r_o,
            "curvature": out.curvature,
            "rim_moment": out.rim_moment,
            "rim_force": out.rim_force,
            "decay_bound": i.decay_bound,
            "r_o_fewer_nodes": i.r_o_coarse,
        },
    });
    let interface = "frictionless (receding contact of two equal plates, no hole, rim C)";
    let result = (r_o, error, converged, start.elapsed().as_secs_f64());
    super::two_pair::print_json(args, start, result, interface, hankel)
}
