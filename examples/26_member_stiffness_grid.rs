//! Each stiffness rule's error against the exact member stiffness k_P over a grid of grip over
//! diameter l/d and head over diameter d_W/d, with a figure of k_P against l/d.
//!
//! **Problem.** Two equal steel-like plates (E = 1, ν = 0.3), each l/2 thick, bolt diameter d = 1
//! in a hole of the same diameter (no catalogue bolt: d = d_h = 2A), a uniform bearing pressure
//! on A ≤ r ≤ B = d_W/2 under head and nut, outside diameter D_A = 2C = 4 d_W; l/d from 0.5 to 5
//! and d_W/d from 1.3 to 3 (10 × 10, logarithmic).
//!
//! **Routes.** The exact k_P by the route layer's two-plate member compliance
//! ([`boltzone::route::joint::stiffness`], 0.05 %); the rules by
//! [`boltzone::route::joint::stiffness_rules`]: VDI 2230's cone and sleeve, Shigley's frusta
//! (Eq. 8-20 per member), Wileman's fit (steel's constants, nearest in ν), Cornwell's (left
//! out). The table prints each rule's error (k_rule − k_P)/k_P in percent.
//!
//! **Check.** The stress field of the sleeve limit (σ_z = −p through the annulus A..B, plane
//! Lamé fields in the annulus and the ring B..C) is statically admissible, so by complementary
//! energy every exact k_P is at least k_sleeve = πE(B² − A²)/(2D·(1 − ν²(C² − B²)/(C² − A²)))
//! (2D = l; `contact::compliance`'s module docs); and a rigid head, whose contact pressure
//! minimises the complementary energy among those of the same force, is at least as stiff as
//! the uniform pressure (Thomson–Tait). Both are asserted at every point (within the estimates).
//!
//! **Figure.** `member_stiffness_grid.svg` (or the path given): k_P/(E d) against l/d at the
//! middle head size, the exact curves (uniform pressure and rigid head) and the three rules.
//!
//! Run: `cargo run --release --example 26_member_stiffness_grid [n] [figure.svg]` (n points per
//! axis, default 10). Cost: docs/joint.md (the 10 × 10 grid in 3.2 s wall); the quick size
//! (3 × 3 at 2e-3) runs in `tests/examples/main.rs`.

use boltzone::contact::two_plate::Loading;
use boltzone::plot::{write_figure, Curve, CurveFigure, PALETTE};
use boltzone::route::joint::{stiffness, stiffness_rules, RuleDiameters};
use boltzone::route::two_plate::Question;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::time::Instant;

/// Logarithmic points from `lo` to `hi`.
fn grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n.max(2) - 1) as f64))
        .collect()
}

/// The joint of grip `l` and head `dw` (d = 1).
fn joint(l: f64, dw: f64) -> Result<Joint, Box<dyn std::error::Error>> {
    let m = Material::new(1.0, 0.3)?;
    let (a, b) = (0.5, 0.5 * dw);
    Ok(Joint::new(
        a,
        OuterRadius::Finite(2.0 * dw),
        Plate::new(0.5 * l, m)?,
        Plate::new(0.5 * l, m)?,
        FaceLoad::uniform(a, b, 1.0)?,
    )?)
}

/// The sleeve limit's k_P (module docs), a lower bound of the exact one.
fn sleeve(j: &Joint) -> f64 {
    let (a, b, d) = (j.hole_radius(), j.load().outer(), j.upper().thickness());
    let c = match j.outer_radius() {
        OuterRadius::Finite(c) => c,
        OuterRadius::Infinite => f64::INFINITY,
    };
    let nu = j.upper().material().poisson_ratio();
    let ring = if c.is_finite() {
        (c * c - b * b) / (c * c - a * a)
    } else {
        1.0
    };
    std::f64::consts::PI * (b * b - a * a) / (2.0 * d * (1.0 - nu * nu * ring))
}

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let args: Vec<String> = if quick {
        Vec::new()
    } else {
        std::env::args().collect()
    };
    let n: usize = if quick {
        3
    } else {
        args.get(1).map_or(Ok(10), |s| s.parse())?
    };
    let tol = if quick { 2e-3 } else { 5e-4 };
    let figure = match args.get(2) {
        Some(p) => std::path::PathBuf::from(p),
        None if quick => std::env::temp_dir().join(format!("ex26_{}.svg", std::process::id())),
        None => "member_stiffness_grid.svg".into(),
    };
    let grips = grid(0.5, 5.0, n);
    let heads = grid(1.3, 3.0, n);
    let names = ["vdi2230", "shigley", "wileman"];
    // errors[rule][i grip][j head], percent
    let mut errors = vec![vec![vec![f64::NAN; n]; n]; names.len()];
    let mid = n / 2;
    let mut curves: Vec<Vec<(f64, f64)>> = vec![Vec::new(); names.len() + 2];
    let (mut worst_bar, mut solves) = (0.0f64, 0);
    let t0 = Instant::now();
    for (i, &l) in grips.iter().enumerate() {
        for (j, &dw) in heads.iter().enumerate() {
            let jt = joint(l, dw)?;
            let q = Question {
                stiffness: true,
                ..Question::new(&jt, tol)
            };
            let m = stiffness(&q)?;
            solves += 1;
            let k = m.stiffness;
            assert!(k.converged, "l/d {l}, dw/d {dw}: {k:?}");
            worst_bar = worst_bar.max(k.error / k.value);
            let lower = sleeve(&jt);
            assert!(
                k.value + k.error >= lower,
                "l/d {l}, dw/d {dw}: k_P {k:?} below the sleeve bound {lower}"
            );
            let rules = stiffness_rules(&jt, RuleDiameters::of_joint(&jt), k);
            for (r, name) in names.iter().enumerate() {
                errors[r][i][j] = rules[name].error_percent.map_or(f64::NAN, |e| e.value);
                if j == mid {
                    if let Some(kr) = rules[name].stiffness {
                        curves[r + 2].push((l, kr));
                    }
                }
            }
            assert!(rules["cornwell"].left_out.is_some());
            if j == mid {
                curves[0].push((l, k.value));
                let rigid = Question {
                    loading: Loading::NutDisplacement(1e-3),
                    ..q
                };
                let kr = stiffness(&rigid)?.stiffness;
                solves += 1;
                assert!(
                    kr.value + kr.error >= k.value - k.error,
                    "l/d {l}: rigid {kr:?} below uniform {k:?}"
                );
                curves[1].push((l, kr.value));
            }
        }
    }
    let seconds = t0.elapsed().as_secs_f64();
    println!(
        "Member stiffness rules against the exact k_P (two equal plates, d = d_h = 2A, \
         D_A = 4 d_W, nu = 0.3, uniform pressure, tol {tol}): error in percent"
    );
    for (r, name) in names.iter().enumerate() {
        println!("\n{name}: rows l/d, columns d_W/d");
        print!("{:>7}", "l/d");
        for dw in &heads {
            print!("{dw:>8.2}");
        }
        println!();
        for (i, l) in grips.iter().enumerate() {
            print!("{l:>7.2}");
            for e in &errors[r][i] {
                print!("{e:>8.1}");
            }
            println!();
        }
        let all: Vec<f64> = errors[r]
            .iter()
            .flatten()
            .copied()
            .filter(|e| e.is_finite())
            .collect();
        let (lo, hi) = all
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &e| {
                (a.min(e), b.max(e))
            });
        println!(
            "{name}: from {lo:+.1} % to {hi:+.1} % over {} points",
            all.len()
        );
    }
    println!(
        "\n{solves} member-compliance studies in {seconds:.2} s wall; largest relative bar \
         {worst_bar:.1e}; every k_P at or above the sleeve bound, rigid head at or above uniform"
    );
    let labels = [
        "exact, uniform pressure",
        "exact, rigid head",
        "VDI 2230",
        "Shigley",
        "Wileman",
    ];
    let y_max = curves.iter().flatten().map(|p| p.1).fold(0.0, f64::max);
    let fig = CurveFigure {
        title: format!("Member stiffness against grip, d_W/d = {:.2}", heads[mid]),
        x_label: "grip over bolt diameter l/d".into(),
        y_label: "k_P / (E d)".into(),
        curves: curves
            .into_iter()
            .zip(labels)
            .enumerate()
            .map(|(k, (points, label))| Curve {
                label: label.into(),
                points,
                color: PALETTE[[0, 1, 2, 3, 5][k]], // not the pale yellow
            })
            .collect(),
        markers: vec![],
        x_range: (0.0, grips[n - 1] * 1.05),
        y_range: (0.0, 1.05 * y_max),
    };
    write_figure(&fig, &figure, (800, 520))?;
    println!("figure: {}", figure.display());
    if quick {
        std::fs::remove_file(&figure)?;
    }
    Ok(())
}
