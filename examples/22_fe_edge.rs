//! Example 22: R_o per FE level against the exact routes, with the gap-shape estimate and with
//! the fitted contact edge (issue 36).
//!
//! Equal infinite plates (one plate on a frictionless rigid plane by symmetry), without a hole
//! against the receding contact (`hankel::receding`, ~1e-12) and with a hole against the holed
//! semi-analytic route at its 1e-8 tier. For each plate the levels of one FE study (the mesh
//! graded at the level's estimate of the chosen kind), and per level: h/D, the relative error
//! of R_o by the gap shape ([`boltzone::contact::separation`]) and by the fitted edge
//! ([`boltzone::contact::edge_fit`]), their ratios over a level, and the observed order of the
//! last three levels.
//!
//! Arguments: `[levels] [plates]` (default 8 levels, 10 plates: 6 without a hole, 4 with); the
//! plates are drawn at random (seeded) with B/D ∈ [0.3, 3], ν ∈ [0.01, 0.49], A/D ∈ [0.3, 1].
//! `BOLTZONE_QUICK=1` runs 4 levels and the study at 1e-4 on two plates (the test suite does).
//!
//! Then each plate's study with `fitted_edge` at 1e-4, 1e-5 and 1e-6: its error against its
//! estimate and its time.
//!
//! Self-check (error): every reference converged; every level's fitted R_o exists; every
//! fitted study within its estimate.

use anyhow::ensure;
use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::hankel::receding::{Layer, RecedingParams};
use boltzone::numerics::random::SplitMix64;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate, SinglePlate};

/// One infinite plate pair: hole A, load outer radius B, thickness D = 1, Poisson ratio ν.
#[derive(Debug, Clone, Copy)]
pub struct Case {
    /// Hole radius A (0: none).
    pub a: f64,
    /// Load outer radius B.
    pub b: f64,
    /// Poisson ratio.
    pub nu: f64,
}

impl Case {
    /// The equal infinite plates of the case.
    pub fn joint(&self) -> anyhow::Result<Joint> {
        let plate = Plate::new(1.0, Material::unit(self.nu)?)?;
        let load = FaceLoad::uniform(self.a, self.b, 1.0)?;
        Ok(Joint::new(
            self.a,
            OuterRadius::Infinite,
            plate,
            plate,
            load,
        )?)
    }
}

/// The exact R_o of `case` (receding contact without a hole, the holed route with one).
pub fn exact(case: &Case) -> anyhow::Result<f64> {
    let m = Material::unit(case.nu)?;
    let load = FaceLoad::uniform(case.a, case.b, 1.0)?;
    if case.a == 0.0 {
        let r = Layer::new(1.0, m, load)?.receding_contact(&RecedingParams::default())?;
        ensure!(
            r.info.r_o_error < 1e-9 * r.r_o,
            "receding contact not converged"
        );
        Ok(r.r_o)
    } else {
        let plate = SinglePlate::new(case.a, OuterRadius::Infinite, 1.0, m, load)?;
        let (out, _) = two_plate_hole_to(&plate, 1e-7, &[])?;
        ensure!(out.meets(1e-7), "holed route short of 1e-7: {:?}", case);
        Ok(out.r_o)
    }
}

/// (h, the level's R_o, gap-fit root, edge-force root) per level of one FE study of `levels`
/// levels (the roots NaN unless `fitted`: the default study computes none).
pub fn levels(
    case: &Case,
    levels: usize,
    fitted: bool,
) -> anyhow::Result<Vec<(f64, f64, f64, f64)>> {
    let s = solve(
        &case.joint()?,
        &TwoPlateParams {
            tolerance: 1e-13,
            min_levels: levels,
            max_levels: levels,
            fitted_edge: fitted,
            ..Default::default()
        },
    )?;
    s.info
        .levels
        .iter()
        .map(|l| {
            // (the default study reads no fitted edge: NaN there)
            let fit = l.r_o_fit.unwrap_or(f64::NAN);
            let force = l.r_o_fit_force.unwrap_or(f64::NAN);
            ensure!(!fitted || force.is_finite(), "no fitted edge on a level");
            Ok((l.h, l.r_o, fit, force))
        })
        .collect()
}

/// The fitted study of `case` at `tol`: (R_o, its estimate, converged, seconds).
pub fn study(case: &Case, tol: f64) -> anyhow::Result<(f64, f64, bool, f64)> {
    let s = solve(
        &case.joint()?,
        &TwoPlateParams {
            tolerance: tol,
            fitted_edge: true,
            ..Default::default()
        },
    )?;
    Ok((s.r_o, s.r_o_error, s.converged, s.info.seconds))
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok();
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let (n_levels, n_plates) = if quick {
        (4, 2)
    } else {
        (
            args.first().copied().unwrap_or(8),
            args.get(1).copied().unwrap_or(10),
        )
    };
    let levels_too = n_levels > 0;
    let mut rng = SplitMix64::new(36);
    for p in 0..n_plates {
        let holed = p % 5 >= 3;
        let case = Case {
            a: if holed { 0.3 + 0.7 * rng.unit() } else { 0.0 },
            b: 0.0,
            nu: 0.01 + 0.48 * rng.unit(),
        };
        let case = Case {
            b: case.a + 0.3 + 2.7 * rng.unit(),
            ..case
        };
        let r = exact(&case)?;
        println!(
            "plate {p}: A {:.4} B {:.4} ν {:.3}, exact R_o {r:.12}",
            case.a, case.b, case.nu
        );
        let tols: &[f64] = if quick { &[1e-4] } else { &[1e-4, 1e-5, 1e-6] };
        for &tol in tols {
            let (v, e, conv, secs) = study(&case, tol)?;
            println!(
                "  fitted study at {tol:e}: error {:+.2e} R_o, estimate {:.2e} R_o, within {:.2}, converged {conv}, {secs:.2} s",
                (v - r) / r,
                e / r,
                (v - r).abs() / e
            );
            ensure!((v - r).abs() <= e, "the fitted study beyond its estimate");
        }
        if levels_too {
            for fitted in [false, true] {
                let lv = levels(&case, n_levels, fitted)?;
                println!(
                    "  mesh graded at the {} estimate:",
                    if fitted { "fitted" } else { "gap-shape" }
                );
                let mut prev: Option<(f64, f64)> = None;
                let mut prev_force: Option<f64> = None;
                for &(h, gap, fit, force) in &lv {
                    let (eg, ef, eq) = ((gap - r) / r, (fit - r) / r, (force - r) / r);
                    let ratio = prev.map_or(String::new(), |(pg, pf)| {
                        format!("  ratios {:6.2} {:6.2}", pg / eg, pf / ef)
                    });
                    println!(
                    "    h/D {h:.5}  gap {eg:+.3e}  fitted {ef:+.3e}  force {eq:+.3e}  f/q {:+.3}{ratio}",
                    ef / eq
                );
                    prev = Some((eg, ef));
                    if let Some(pq) = prev_force {
                        println!("      Richardson of the force root {:+.3e}", 2.0 * eq - pq);
                    }
                    prev_force = Some(eq);
                }
            }
        }
    }
    Ok(())
}
