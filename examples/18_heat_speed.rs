//! Example 18: how fast the heat answers are, time against error (issue 11 "How fast").
//!
//! Chapter V's joint (aluminium, D = A = 0.1 in, 2B = 0.26 in, 1000 lb, eq. 1.1 surfaces):
//! (1) the joint conductance ∫ h_c dA INCLUDING the contact solve, through the scene
//! `examples/scenes/chapter5_lap.toml` at several tolerances, against a tight reference
//! (target < 100 ms); (2) the lap-joint network of `heat::lap` from the coarse network the
//! report could have used (a few cells across the strip) to the converged one (target < 1 ms
//! for the report's size); (3) the contact zone's resistance by the conduction FE of
//! `heat::zone` (Q9, R_e = 0.75 in, 4 elements per plate in z) against radial refinement
//! (target 1 % in < 200 ms).
//!
//! Each time is the minimum of `reps` runs (the machine is shared: its load is printed).
//! Errors are against the finest run of the same column, so they are the method's own.
//! Self-checks (fail): (1) every G within its tolerance of the reference (the scene's
//! contract); (2), (3) the second finest run closer to the finest than the coarsest.
//!
//! Measured 24 Nov 2026 (2 cores, load average 22, test profile, minimum of 3 runs):
//! (1) tolerance 1e-2: 7.2e-6 relative error in 36 ms (3e-3: 1.4e-6, 84 ms; 5e-4: 4.1e-7,
//! 346 ms); reference 117.386 Btu/(hr·°F). (2) 6 cells across (146 nodes): 8.0e-3 in 0.16 ms;
//! 8 cells (258 nodes): 1.0e-3 in 0.31 ms; the converged 120 cells (57,186 nodes): 3.3231
//! Btu/hr in 511 ms (the report's network: 2.88; example 15 explains the difference). (3)
//! 32 radial elements: 1.3e-2 in 2.3 ms; 64: 4.2e-3 in 24 ms (the 1 % target); 256: 79 ms.
//!
//! Run: `cargo run --release --example 18_heat_speed [reps]` (default 3).
//! Builds on: example 15 (the Chapter V numbers beside the report's).

use boltzone::contact::two_plate::{solve, TwoPlateParams, TwoPlateSolution};
use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
use boltzone::heat::joint::JointParams;
use boltzone::heat::lap::LapJoint;
use boltzone::heat::units::{Conductivity, Length, Pressure};
use boltzone::heat::zone::{zone_resistance, Zone};
use boltzone::scene::Scene;
use boltzone::{FaceLoad, Joint, Material, OuterRadius};
use std::f64::consts::PI;
use std::time::Instant;

const SCENE: &str = include_str!("scenes/chapter5_lap.toml");

fn best<T>(reps: usize, f: impl Fn() -> T) -> (T, f64) {
    let mut out = None;
    let mut t_min = f64::INFINITY;
    for _ in 0..reps.max(1) {
        let t = Instant::now();
        out = Some(f());
        t_min = t_min.min(t.elapsed().as_secs_f64());
    }
    (out.unwrap_or_else(|| unreachable!("reps >= 1")), t_min)
}

fn conductance(tol: f64) -> f64 {
    let scene = Scene::parse(&format!("tolerance = {tol:e}\n{SCENE}")).unwrap();
    boltzone::solve(&scene).unwrap().joint_conductance.unwrap()
}

fn contact() -> TwoPlateSolution {
    let (a, b) = (0.1, 0.13);
    let joint = Joint::symmetric(a, b, 0.1, Material::new(1.0e7, 0.33).unwrap())
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(1.54))
        .unwrap()
        .with_load(FaceLoad::uniform(a, b, 1000.0 / (PI * (b * b - a * a))).unwrap())
        .unwrap();
    solve(&joint, &TwoPlateParams::default()).unwrap()
}

fn law() -> JointParams {
    let s = Surfaces::new(
        [Conductivity::btu_per_hr_ft_f(100.0); 2],
        [Length::micro_inches(50.0); 2],
        [0.1 / 2f64.sqrt(); 2],
        Pressure::psi(150_000.0),
    )
    .unwrap();
    JointParams::new(ContactConductance::new(Correlation::Cmy1969, s).unwrap())
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(if quick { 1 } else { 3 });
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "machine load average: {}; times = minimum of {reps} runs",
        load.split_whitespace().next().unwrap_or("?")
    );

    println!("\n(1) joint conductance incl. the contact solve (scene chapter5_lap, eq. 1.1):");
    let reference = conductance(if quick { 1e-4 } else { 2e-5 });
    println!("    reference (tolerance 2e-5): {reference:.6} Btu/(hr·°F)");
    println!("    tolerance   G [Btu/(hr·°F)]   rel. error      ms");
    for tol in [1e-2, 3e-3, 1e-3, 5e-4] {
        let (g, t) = best(reps, || conductance(tol));
        let err = (g / reference - 1.0).abs();
        println!("    {tol:9.0e}   {g:15.6}   {err:10.2e}   {:7.1}", 1e3 * t);
        // the scene's contract: the tolerance holds on every value asked
        anyhow::ensure!(err <= tol, "G at tolerance {tol:e} is off by {err:e}");
    }

    let s = contact();
    let params = law();
    println!("\n(2) Chapter V lap network (heat::lap; the report: 2.88 Btu/hr):");
    println!("    cells across   nodes      Q [Btu/hr]   rel. error vs finest        ms");
    let sizes: &[usize] = if quick {
        &[4, 8, 30]
    } else {
        &[4, 6, 8, 15, 30, 60, 120]
    };
    let runs: Vec<(usize, f64, usize, f64)> = sizes
        .iter()
        .map(|&cells| {
            let lap = LapJoint {
                cells,
                ..LapJoint::chapter5()
            };
            let (r, t) = best(reps, || lap.solve(&s, &params).unwrap());
            (cells, r.heat_flow.to_btu_per_hr(), r.nodes, t)
        })
        .collect();
    print_runs(&runs);

    println!("\n(3) contact-zone resistance by conduction FE (heat::zone, Q9, R_e = 0.75 in):");
    println!("     radial els   nodes   R [°F·hr/Btu]   rel. error vs finest        ms");
    let radial: &[usize] = if quick {
        &[8, 32, 64]
    } else {
        &[4, 8, 16, 32, 64, 128, 256]
    };
    let zone = |n: usize| Zone {
        outer_radius: 0.75,
        thickness: [0.1, 0.1],
        conductivity: Conductivity::btu_per_hr_ft_f(100.0),
        radial: n,
        axial: 4,
    };
    let runs: Vec<(usize, f64, usize, f64)> = radial
        .iter()
        .map(|&n| {
            let (r, t) = best(reps, || zone_resistance(&s, &params, &zone(n)).unwrap());
            (n, r.resistance.to_f_hr_per_btu(), r.nodes, t)
        })
        .collect();
    print_runs(&runs);
    Ok(())
}

/// Rows (size, value, nodes, seconds), each value's relative difference from the last row's;
/// panics unless the second finest row is closer to the finest than the coarsest is.
fn print_runs(runs: &[(usize, f64, usize, f64)]) {
    let finest = runs.last().map_or(f64::NAN, |r| r.1);
    for (n, v, nodes, t) in runs {
        println!(
            "    {n:12}   {nodes:5}   {v:13.5}   {:20.2e}   {:7.3}",
            (v / finest - 1.0).abs(),
            1e3 * t
        );
    }
    let d = |i: usize| (runs[i].1 / finest - 1.0).abs();
    assert!(d(runs.len() - 2) < d(0), "no convergence: {runs:?}");
}
