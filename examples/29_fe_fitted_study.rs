//! Example 29: the route layer's FE study (`route::two_plate::Question::fem_params`, the
//! fitted contact edge below `AUTO_BELOW`) on random joints of each interface kind, each run
//! checked against an exact route meant to be at least 100 times tighter than the asked
//! tolerance (runs whose exact route's estimate is not are counted and printed):
//!
//! - equal plates, frictionless, welded and friction (μ 0.05–0.6; equal plates are symmetric
//!   about the interface, so all three are the same problem): the holed Hankel route
//!   ([`two_plate_hole_to`]) at 1e-8 on the same joint (hole, rim C = ∞ or finite, load
//!   shape uniform, peak-a or peak-b); the three must give the same R_o bit for bit;
//! - unequal, dissimilar plates, frictionless, with a hole far inside (R_o − A ≥ 8 times the
//!   thicker plate): the two-plate receding contact [`Pair`] of the disk load 0..B, whose
//!   error is below 1e-10 (the hole's self-equilibrated disturbance decays like
//!   e^(−2.1 (R_o − A)/D), `docs/tables.md`, so it is below 1e-8 D there).
//!
//! Per kind it prints the runs, how many converged, how many lie within their bar
//! (|FE − exact| ≤ FE bar + the exact route's estimate), the largest ratio and the times; it
//! fails if any run lies outside its bar.
//!
//! Run: `cargo run --release --example 29_fe_fitted_study -- N SEED TOL` (N joints of each
//! kind). Quick (`BOLTZONE_QUICK=1`): one joint of each kind at 1e-5.

use boltzone::contact::two_plate::{solve, InterfaceModel};
use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::hankel::receding::{Pair, RecedingParams};
use boltzone::numerics::random::SplitMix64;
use boltzone::route::two_plate::Question;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Peak, Plate, SinglePlate};
use std::time::Instant;

/// The tally of one interface kind.
#[derive(Default)]
struct Tally {
    runs: usize,
    converged: usize,
    within: usize,
    worst: f64,
    seconds: Vec<f64>,
    /// Runs whose exact route did not reach tol/100 (counted, and still checked).
    loose: usize,
}

impl Tally {
    fn add(&mut self, fe: (f64, f64, bool, f64), exact: (f64, f64), tol: f64) -> f64 {
        let ratio = (fe.0 - exact.0).abs() / (fe.1 + exact.1);
        self.runs += 1;
        self.loose += usize::from(exact.1 > 0.01 * tol * exact.0);
        self.converged += usize::from(fe.2);
        self.within += usize::from(ratio <= 1.0);
        self.worst = self.worst.max(ratio);
        self.seconds.push(fe.3);
        ratio
    }

    fn line(&self, kind: &str) -> String {
        let mut s = self.seconds.clone();
        s.sort_by(f64::total_cmp);
        let q = |f: f64| {
            s.get(((s.len().max(1) - 1) as f64 * f) as usize)
                .copied()
                .unwrap_or(0.0)
        };
        format!(
            "{kind:24} {:4} runs, {:4} converged, {:4} within the bar, largest |err|/bar {:.2}, \
             FE time median {:.2} s, max {:.2} s; exact route looser than tol/100: {}",
            self.runs,
            self.converged,
            self.within,
            self.worst,
            q(0.5),
            q(1.0),
            self.loose
        )
    }
}

/// (R_o, bar, converged, seconds) of the route layer's FE study of `joint` at `tol`.
fn fe(joint: &Joint, interface: InterfaceModel, tol: f64) -> anyhow::Result<(f64, f64, bool, f64)> {
    let q = Question {
        interface,
        ..Question::new(joint, tol)
    };
    let t = Instant::now();
    let s = solve(joint, &q.fem_params())?;
    Ok((s.r_o, s.r_o_error, s.converged, t.elapsed().as_secs_f64()))
}

fn load(rng: &mut SplitMix64, a: f64, b: f64) -> anyhow::Result<FaceLoad> {
    Ok(match rng.below(3) {
        0 => FaceLoad::uniform(a, b, 1.0)?,
        1 => FaceLoad::triangular(a, b, 1.0, Peak::AtA)?,
        _ => FaceLoad::triangular(a, b, 1.0, Peak::AtB)?,
    })
}

/// Adds one FE run (R_o, bar, converged, seconds) against the exact (R_o, estimate) to `tally`
/// and says how it went.
fn outcome(tally: &mut Tally, run: (f64, f64, bool, f64), exact: (f64, f64), tol: f64) -> String {
    let ratio = tally.add(run, exact, tol);
    format!(
        "FE {:.9} ± {:.1e} ({}), exact {:.9} ± {:.1e}: |err|/bar {ratio:.2} {:.2} s",
        run.0,
        run.1,
        if run.2 { "converged" } else { "NOT converged" },
        exact.0,
        exact.1,
        run.3
    )
}

/// One random equal-plate joint (D = 1) against the holed route at 1e-8, for each interface.
fn equal(rng: &mut SplitMix64, tol: f64, tallies: &mut [Tally]) -> anyhow::Result<()> {
    let a = 0.3 + 0.7 * rng.unit();
    let b = a + 0.3 + 2.7 * rng.unit();
    let nu = 0.01 + 0.48 * rng.unit();
    let rim = if rng.chance(1.0 / 3.0) {
        OuterRadius::Finite(b + 3.0 + 7.0 * rng.unit())
    } else {
        OuterRadius::Infinite
    };
    let m = Material::unit(nu)?;
    let load = load(rng, a, b)?;
    let (exact, _) =
        two_plate_hole_to(&SinglePlate::new(a, rim, 1.0, m, load.clone())?, 1e-8, &[])?;
    let plate = Plate::new(1.0, m)?;
    let joint = Joint::new(a, rim, plate, plate, load)?;
    let mu = 0.05 + 0.55 * rng.unit();
    let kinds = [
        InterfaceModel::Frictionless,
        InterfaceModel::Welded,
        InterfaceModel::Friction { mu },
    ];
    let mut first: Option<f64> = None;
    for (kind, tally) in kinds.into_iter().zip(tallies.iter_mut()) {
        let run = fe(&joint, kind, tol)?;
        // equal plates are symmetric about the interface: one problem for every kind
        let r_o = *first.get_or_insert(run.0);
        anyhow::ensure!(
            run.0.to_bits() == r_o.to_bits(),
            "{kind:?}: R_o {} against {r_o}",
            run.0
        );
        let line = outcome(tally, run, (exact.r_o, exact.info.r_o_error), tol);
        let shape = joint.load().profile();
        println!("equal {kind:?}: A {a:.3} B {b:.3} nu {nu:.3} {rim:?} {shape:?}: {line}");
    }
    Ok(())
}

/// One random unequal frictionless joint (D₁ = 1) against [`Pair`] on the disk load 0..B.
fn unequal(rng: &mut SplitMix64, tol: f64, tally: &mut Tally) -> anyhow::Result<()> {
    let d2 = 0.55 + 1.35 * rng.unit();
    let upper = Plate::new(1.0, Material::new(1.0, 0.1 + 0.35 * rng.unit())?)?;
    let lower = Plate::new(
        d2,
        Material::new(0.4 + 2.5 * rng.unit(), 0.1 + 0.35 * rng.unit())?,
    )?;
    let a = 0.2 + 0.4 * rng.unit();
    let b = a + d2.max(1.0) * (8.0 + 2.0 * rng.unit());
    let disk = FaceLoad::uniform(0.0, b, 1.0)?;
    let exact = Pair::new(upper, lower, disk).receding_contact(&RecedingParams::default())?;
    let joint = Joint::new(
        a,
        OuterRadius::Infinite,
        upper,
        lower,
        FaceLoad::uniform(a, b, 1.0)?,
    )?;
    let run = fe(&joint, InterfaceModel::Frictionless, tol)?;
    let line = outcome(tally, run, (exact.r_o, exact.info.r_o_error), tol);
    println!(
        "unequal: D2 {d2:.2} E2 {:.2} nu {:.2},{:.2} A {a:.3} B {b:.3}: {line}",
        lower.material().youngs_modulus(),
        upper.material().poisson_ratio(),
        lower.material().poisson_ratio(),
    );
    Ok(())
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |k: usize, name: &str| -> anyhow::Result<String> {
        args.get(k)
            .cloned()
            .ok_or_else(|| anyhow::anyhow!("usage: 29_fe_fitted_study N SEED TOL ({name} missing)"))
    };
    let (n, seed, tol): (usize, u64, f64) = if quick {
        (1, 29, 1e-5)
    } else {
        let n = arg(0, "N")?;
        let seed = arg(1, "SEED")?;
        let tol = arg(2, "TOL")?;
        (
            n.parse().map_err(|e| anyhow::anyhow!("N {n}: {e}"))?,
            seed.parse()
                .map_err(|e| anyhow::anyhow!("SEED {seed}: {e}"))?,
            tol.parse().map_err(|e| anyhow::anyhow!("TOL {tol}: {e}"))?,
        )
    };
    anyhow::ensure!(tol > 0.0 && tol < 1.0, "TOL {tol}: must lie in (0, 1)");
    let mut rng = SplitMix64::new(seed);
    let mut tallies: Vec<Tally> = (0..4).map(|_| Tally::default()).collect();
    let t = Instant::now();
    for _ in 0..n {
        equal(&mut rng, tol, &mut tallies[..3])?;
        unequal(&mut rng, tol, &mut tallies[3])?;
    }
    println!(
        "\nN = {n} per kind, seed {seed}, tolerance {tol:e}, {:.0} s",
        t.elapsed().as_secs_f64()
    );
    let names = [
        "equal, frictionless",
        "equal, welded",
        "equal, friction",
        "unequal, frictionless",
    ];
    for (name, tally) in names.iter().zip(&tallies) {
        println!("{}", tally.line(name));
    }
    let outside: usize = tallies.iter().map(|t| t.runs - t.within).sum();
    anyhow::ensure!(outside == 0, "{outside} runs lie outside their bar");
    Ok(())
}
