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
//! `survey [levels] [plates] [q4]`: per level only the two fitted-edge roots (edge force, and K
//! fitted to the reactions of the last five closed nodes), their Richardson values 2R_k −
//! R_{k−1}, the ratios of successive errors, and the observed order of each root over the last
//! two levels (`q4`: the levels with Q4 elements instead of Q9). `check [plates] [tol …]`: the fitted study of random plates (seed 3636, at most
//! 12 levels) at each tolerance (default 1e-5 1e-6) against the exact routes, with counts.
//! `pair [plates] [tol …]`: the same for unequal, dissimilar plates without a hole (both
//! plates meshed; D₂/D₁ ∈ [0.5, 2], E₂/E₁ ∈ [0.3, 3], each ν ∈ [0.01, 0.49], B/D₁ ∈ [0.3, 3];
//! seed 3737) against the receding contact of the two plates in series
//! (`hankel::receding::Pair`, certified to 1e-9).
//!
//! Plates whose reference is not certified (receding contact to 1e-9, holed route to 1e-7) are
//! skipped and counted. Self-check (error): every level's fitted R_o exists; every fitted
//! study within its estimate.

use anyhow::ensure;
use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::fem::ElementKind;
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::hankel::receding::{Layer, Pair, RecedingParams};
use boltzone::numerics::convergence::order_between;
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

/// The exact R_o of `case` (receding contact without a hole, the holed route with one); None
/// when the route does not certify 1e-9 (receding) or 1e-7 (holed) — such plates are skipped
/// and counted.
pub fn exact(case: &Case) -> anyhow::Result<Option<f64>> {
    let m = Material::unit(case.nu)?;
    let load = FaceLoad::uniform(case.a, case.b, 1.0)?;
    if case.a == 0.0 {
        let r = Layer::new(1.0, m, load)?.receding_contact(&RecedingParams::default())?;
        Ok((r.info.r_o_error < 1e-9 * r.r_o).then_some(r.r_o))
    } else {
        let plate = SinglePlate::new(case.a, OuterRadius::Infinite, 1.0, m, load)?;
        let (out, _) = two_plate_hole_to(&plate, 1e-7, &[])?;
        Ok(out.meets(1e-7).then_some(out.r_o))
    }
}

/// (h, the level's R_o, gap-fit root, edge-force root, reaction-fit root) of one level.
pub type LevelRoots = (f64, f64, f64, f64, f64);

/// The [`LevelRoots`] of each level of one FE study of `levels` levels with `element` (the
/// roots NaN unless `fitted`: the default study computes none; with Q4 a level whose window
/// holds too few trial edges around the edge has none either, NaN).
pub fn levels(
    case: &Case,
    levels: usize,
    fitted: bool,
    element: ElementKind,
) -> anyhow::Result<Vec<LevelRoots>> {
    let s = solve(
        &case.joint()?,
        &TwoPlateParams {
            element,
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
            let reaction = l.r_o_fit_reaction.unwrap_or(f64::NAN);
            ensure!(
                !fitted || force.is_finite() || element != ElementKind::Q9,
                "no fitted edge on a level"
            );
            Ok((l.h, l.r_o, fit, force, reaction))
        })
        .collect()
}

/// The fitted study of `joint` at `tol` with at most `max_levels` levels: (R_o, its estimate,
/// converged, levels, seconds).
pub fn study_joint(
    joint: &Joint,
    tol: f64,
    max_levels: usize,
) -> anyhow::Result<(f64, f64, bool, usize, f64)> {
    let s = solve(
        joint,
        &TwoPlateParams {
            tolerance: tol,
            fitted_edge: true,
            max_levels,
            ..Default::default()
        },
    )?;
    Ok((
        s.r_o,
        s.r_o_error,
        s.converged,
        s.info.levels.len(),
        s.info.seconds,
    ))
}

/// The fitted study of `case` at `tol`: (R_o, its estimate, converged, seconds).
pub fn study(case: &Case, tol: f64) -> anyhow::Result<(f64, f64, bool, f64)> {
    let (r, e, c, _, t) = study_joint(&case.joint()?, tol, 9)?;
    Ok((r, e, c, t))
}

/// The `n`-th random plate of the survey (seeded; every fifth … the 3rd and 4th of each five
/// hold a hole).
pub fn random_case(rng: &mut SplitMix64, p: usize) -> Case {
    let holed = p % 5 >= 3;
    let a = if holed { 0.3 + 0.7 * rng.unit() } else { 0.0 };
    let nu = 0.01 + 0.48 * rng.unit();
    Case {
        a,
        b: a + 0.3 + 2.7 * rng.unit(),
        nu,
    }
}

/// `check N [tol …]`: the fitted study of N random plates at each tolerance (default 1e-5 and
/// 1e-6, at most 12 levels) against the exact routes ([`tally`]).
fn check(n: usize, tols: &[f64]) -> anyhow::Result<()> {
    let mut rng = SplitMix64::new(3636);
    tally(n, tols, |p| {
        let case = random_case(&mut rng, p);
        let label = format!("A {:.3} B {:.3} ν {:.3}", case.a, case.b, case.nu);
        Ok((label, case.joint()?, exact(&case)?))
    })
}

/// `pair N [tol …]`: the fitted study of N random unequal, dissimilar plates without a hole
/// against `Pair`'s receding contact ([`tally`]).
fn pair(n: usize, tols: &[f64]) -> anyhow::Result<()> {
    let mut rng = SplitMix64::new(3737);
    tally(n, tols, |_| {
        let d2 = 0.5 * 4f64.powf(rng.unit());
        let e2 = 0.3 * 10f64.powf(rng.unit());
        let (nu1, nu2) = (0.01 + 0.48 * rng.unit(), 0.01 + 0.48 * rng.unit());
        let b = 0.3 + 2.7 * rng.unit();
        let upper = Plate::new(1.0, Material::new(1.0, nu1)?)?;
        let lower = Plate::new(d2, Material::new(e2, nu2)?)?;
        let load = FaceLoad::uniform(0.0, b, 1.0)?;
        let r =
            Pair::new(upper, lower, load.clone()).receding_contact(&RecedingParams::default())?;
        let joint = Joint::new(0.0, OuterRadius::Infinite, upper, lower, load)?;
        let label = format!("B {b:.3} ν {nu1:.3} D2 {d2:.3} E2 {e2:.3} ν2 {nu2:.3}");
        Ok((
            label,
            joint,
            (r.info.r_o_error < 1e-9 * r.r_o).then_some(r.r_o),
        ))
    })
}

/// The fitted study (at most 12 levels) of the `n` joints `draw` gives (label, joint, its
/// certified exact R_o or None: skipped and counted) at each tolerance: per study the error
/// over its estimate, and per tolerance the counts converged and within, the largest ratio,
/// the levels and times. An error when any study lies beyond its estimate.
fn tally(
    n: usize,
    tols: &[f64],
    mut draw: impl FnMut(usize) -> anyhow::Result<(String, Joint, Option<f64>)>,
) -> anyhow::Result<()> {
    let mut rows: Vec<Vec<(f64, bool, usize, f64)>> = vec![Vec::new(); tols.len()];
    let mut skipped = 0;
    for p in 0..n {
        let (label, joint, r) = draw(p)?;
        let Some(r) = r else {
            skipped += 1;
            println!("plate {p}: {label}: reference not certified, skipped");
            continue;
        };
        for (k, &tol) in tols.iter().enumerate() {
            let (v, e, conv, lv, secs) = study_joint(&joint, tol, 12)?;
            let ratio = (v - r).abs() / e;
            println!(
                "plate {p} {label} tol {tol:e}: error {:+.2e} R_o, estimate {:.2e} R_o, ratio {ratio:.2}, converged {conv}, {lv} levels, {secs:.2} s",
                (v - r) / r, e / r
            );
            rows[k].push((ratio, conv, lv, secs));
        }
    }
    println!("{skipped} plates skipped (reference not certified)");
    for (k, &tol) in tols.iter().enumerate() {
        let v = &rows[k];
        let within = v.iter().filter(|x| x.0 <= 1.0).count();
        let conv = v.iter().filter(|x| x.1).count();
        let worst = v.iter().map(|x| x.0).fold(0.0, f64::max);
        let mean_levels = v.iter().map(|x| x.2 as f64).sum::<f64>() / v.len() as f64;
        let secs: Vec<f64> = v.iter().map(|x| x.3).collect();
        let mean_secs = secs.iter().sum::<f64>() / secs.len() as f64;
        let max_secs = secs.iter().copied().fold(0.0, f64::max);
        println!(
            "tol {tol:e}: {} studies, {conv} converged, {within} within their estimate, largest error/estimate {worst:.2}, mean levels {mean_levels:.1}, mean {mean_secs:.2} s, max {max_secs:.2} s",
            v.len()
        );
    }
    ensure!(
        rows.iter().flatten().all(|x| x.0 <= 1.0),
        "a fitted study beyond its estimate"
    );
    Ok(())
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok();
    let raw: Vec<String> = std::env::args().skip(1).collect();
    let mode = raw.first().map(String::as_str);
    let survey = mode == Some("survey");
    // `q4` among the arguments: the levels with Q4 elements (default Q9)
    let element = if raw.iter().any(|a| a == "q4") {
        ElementKind::Q4
    } else {
        ElementKind::Q9
    };
    if mode == Some("check") || mode == Some("pair") {
        let n = match raw.get(1) {
            Some(a) => a
                .parse()
                .map_err(|e| anyhow::anyhow!("PLATES = {a:?}: {e} (a count)"))?,
            None => 40,
        };
        let mut tols = raw[2.min(raw.len())..]
            .iter()
            .map(|a| match a.parse::<f64>() {
                Ok(t) if t > 0.0 && t < 1.0 => Ok(t),
                _ => Err(anyhow::anyhow!("TOL = {a:?}: not a tolerance in (0, 1)")),
            })
            .collect::<anyhow::Result<Vec<f64>>>()?;
        if tols.is_empty() {
            tols = vec![1e-5, 1e-6];
        }
        return if mode == Some("check") {
            check(n, &tols)
        } else {
            pair(n, &tols)
        };
    }
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
    let mut orders: Vec<(f64, f64)> = Vec::new();
    for p in 0..n_plates {
        let case = random_case(&mut rng, p);
        let Some(r) = exact(&case)? else {
            println!("plate {p}: {case:?}: reference not certified, skipped");
            continue;
        };
        println!(
            "plate {p}: A {:.4} B {:.4} ν {:.3}, exact R_o {r:.12}",
            case.a, case.b, case.nu
        );
        let tols: &[f64] = if quick {
            &[1e-4]
        } else if survey {
            &[]
        } else {
            &[1e-4, 1e-5, 1e-6]
        };
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
        if levels_too && survey {
            let lv = levels(&case, n_levels, true, element)?;
            let n = lv.len();
            if n >= 3 {
                let e = |i: usize| (lv[i].3 - r).abs();
                let q = |i: usize| (lv[i].4 - r).abs();
                orders.push((
                    order_between(lv[n - 2].0, e(n - 2), lv[n - 1].0, e(n - 1)),
                    order_between(lv[n - 2].0, q(n - 2), lv[n - 1].0, q(n - 1)),
                ));
            }
            let mut prev: Option<(f64, f64)> = None;
            let mut prev_x: Option<(f64, f64)> = None;
            for &(h, _, _, force, reaction) in &lv {
                let (ef, er) = ((force - r) / r, (reaction - r) / r);
                let (xf, xr) = prev.map_or((f64::NAN, f64::NAN), |(pf, pr)| {
                    (2.0 * ef - pf, 2.0 * er - pr)
                });
                let ratios = prev.map_or(String::new(), |(pf, pr)| {
                    format!("  ratios {:6.2} {:6.2}", pf / ef, pr / er)
                });
                let xratios = prev_x.map_or(String::new(), |(pf, pr)| {
                    format!("  x-ratios {:6.2} {:6.2}", pf / xf, pr / xr)
                });
                println!("    h/D {h:.5}  force {ef:+.3e}  reaction {er:+.3e}  rich {xf:+.3e} {xr:+.3e}{ratios}{xratios}");
                if prev.is_some() {
                    prev_x = Some((xf, xr));
                }
                prev = Some((ef, er));
            }
            continue;
        }
        if levels_too {
            for fitted in [false, true] {
                let lv = levels(&case, n_levels, fitted, element)?;
                println!(
                    "  mesh graded at the {} estimate:",
                    if fitted { "fitted" } else { "gap-shape" }
                );
                let mut prev: Option<(f64, f64)> = None;
                let mut prev_force: Option<f64> = None;
                for &(h, gap, fit, force, _) in &lv {
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
    if !orders.is_empty() {
        println!(
            "observed order over the last two levels on {} plates: force root {}, reaction fit {}",
            orders.len(),
            lo_hi(&orders, 0),
            lo_hi(&orders, 1)
        );
    }
    Ok(())
}

/// The smallest and largest finite value of component `k` of `v`, as "lo … hi" ("none" when
/// no value is finite: a root missing on a level).
fn lo_hi(v: &[(f64, f64)], k: usize) -> String {
    let (lo, hi) = v
        .iter()
        .map(|x| if k == 0 { x.0 } else { x.1 })
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    if lo <= hi {
        format!("{lo:.3} … {hi:.3}")
    } else {
        "none".into()
    }
}
