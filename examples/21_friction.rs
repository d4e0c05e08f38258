//! Example 21: interface friction, from frictionless to welded (issue 14).
//!
//! Table 2 case 5 (304 steel, 0.124 in on 0.257 in, A = 0.1285 in, B = 0.211 in, C = 2.0 in)
//! and the same geometry with the lower plate in aluminium (E = 10.0·10⁶ psi, ν = 0.33) and in
//! titanium (16.5·10⁶ psi, 0.34): the separation radius R_o against the Coulomb coefficient
//! μ ∈ [0, 3] (`contact::friction`), beside the frictionless and (same material only) the
//! welded model, and case 5's 2R_o beside the report's computed 0.588 in and the tests' 0.56 in.
//! Then the cost: a frictional solve at 0.05 % against the frictionless one (best of three).
//!
//! Self-checks (errors): every run converged; μ = 0 gives the frictionless R_o to 1e-9; R_o(μ)
//! is monotone non-decreasing within the error estimates; for case 5 the largest μ gives the
//! welded R_o within the tolerance. The figure `target/figures/21_friction.{svg,png}` (or the
//! directory given as the first argument). `BOLTZONE_QUICK=1` runs three μ on two pairs at a
//! loose tolerance and skips the timing (the test suite does).
//!
//! Builds on: example 04 (the two-plate model), example 11 (its variants).

use anyhow::{ensure, Context};
use boltzone::compare::table2;
use boltzone::contact::two_plate::{solve, InterfaceModel, TwoPlateParams, TwoPlateSolution};
use boltzone::plot::{write_figure, Curve, CurveFigure, Marker};
use boltzone::{reference, FaceLoad, Joint, Material, OuterRadius, Plate};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Case 5's geometry with the lower plate in `lower` (None: 304 steel, Table 2 itself).
fn joint(lower: Option<Material>) -> anyhow::Result<Joint> {
    let case = reference::table2()
        .into_iter()
        .find(|c| c.case == 5)
        .context("Table 2 case 5")?;
    let Some(m) = lower else {
        return Ok(table2::joint(&case)?);
    };
    let a = reference::TABLE2_HOLE_RADIUS;
    Ok(Joint::new(
        a,
        OuterRadius::Finite(reference::TABLE2_OUTER_RADIUS),
        Plate::new(case.d1, Material::steel_304_psi())?,
        Plate::new(case.d2, m)?,
        FaceLoad::uniform(a, case.two_b / 2.0, 1.0)?,
    )?)
}

fn run_model(j: &Joint, interface: InterfaceModel, tol: f64) -> anyhow::Result<TwoPlateSolution> {
    let s = solve(
        j,
        &TwoPlateParams {
            interface,
            tolerance: tol,
            ..Default::default()
        },
    )?;
    ensure!(s.converged, "{interface:?}: not converged");
    Ok(s)
}

/// R_o(μ) of one pair, checked (module docs); returns (μ, R_o) points.
fn sweep(name: &str, j: &Joint, mus: &[f64], tol: f64) -> anyhow::Result<Vec<(f64, f64)>> {
    let free = run_model(j, InterfaceModel::Frictionless, tol)?;
    println!(
        "\n{name}: frictionless R_o = {:.5} ± {:.1e} in",
        free.r_o, free.r_o_error
    );
    println!(
        "{:>6} {:>10} {:>9} {:>8} {:>13} {:>7}",
        "mu", "R_o [in]", "± [in]", "R_o/A", "slip nodes", "t [s]"
    );
    let mut out: Vec<(f64, f64, f64)> = Vec::new();
    for &mu in mus {
        let s = run_model(j, InterfaceModel::Friction { mu }, tol)?;
        let z = s.friction.as_ref().context("friction record")?;
        let slipping = z.state.iter().filter(|x| x.code() == 2.0).count();
        println!(
            "{mu:>6.2} {:>10.5} {:>9.1e} {:>8.4} {:>13} {:>7.2}",
            s.r_o,
            s.r_o_error,
            s.r_o / j.hole_radius(),
            slipping,
            s.info.seconds
        );
        if mu == 0.0 {
            ensure!(
                (s.r_o - free.r_o).abs() <= 1e-9 * free.r_o,
                "{name}: μ = 0 ≠ frictionless"
            );
        }
        if let Some(&(m0, r0, e0)) = out.last() {
            ensure!(
                s.r_o >= r0 - (e0 + s.r_o_error),
                "{name}: R_o({mu}) = {} < R_o({m0}) = {r0}",
                s.r_o
            );
        }
        out.push((mu, s.r_o, s.r_o_error));
    }
    Ok(out.into_iter().map(|(m, r, _)| (m, r)).collect())
}

/// Best of `n` wall times of a solve at 0.05 %.
fn time(j: &Joint, interface: InterfaceModel, n: usize) -> anyhow::Result<f64> {
    let mut best = f64::INFINITY;
    for _ in 0..n {
        let t = Instant::now();
        run_model(j, interface, 5e-4)?;
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

/// Runs the study and writes the figure into `out`; returns the figure files.
pub fn run(out: &Path, quick: bool) -> anyhow::Result<Vec<PathBuf>> {
    let tol = if quick { 2e-3 } else { 5e-4 };
    let mus: Vec<f64> = if quick {
        vec![0.0, 0.3, 3.0]
    } else {
        vec![0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 3.0]
    };
    let al = Material::new(10.0e6, 0.33)?;
    let ti = Material::new(16.5e6, 0.34)?;
    let mut pairs = vec![
        ("steel on steel (Table 2 case 5)", None),
        ("steel on aluminium", Some(al)),
    ];
    if !quick {
        pairs.push(("steel on titanium", Some(ti)));
    }
    let colors = [(20, 80, 200), (200, 60, 30), (0, 150, 60)];
    let mut curves = Vec::new();
    for (k, (name, lower)) in pairs.iter().enumerate() {
        let j = joint(*lower)?;
        let pts = sweep(name, &j, &mus, tol)?;
        if lower.is_none() {
            let w = run_model(&j, InterfaceModel::Welded, tol)?;
            let (mu_max, r_max) = pts[pts.len() - 1];
            println!("welded R_o = {:.5} ± {:.1e} in", w.r_o, w.r_o_error);
            ensure!(
                (r_max - w.r_o).abs() <= tol * w.r_o,
                "μ = {mu_max} vs welded"
            );
            let case = reference::table2()
                .into_iter()
                .find(|c| c.case == 5)
                .context("case 5")?;
            println!(
                "2R_o: μ = 0 {:.3}, μ = {mu_max} {:.3}, welded {:.3} in; report computed {:.3} in, \
                 tests {:.2}-{:.2} (average {:.2}) in",
                2.0 * pts[0].1,
                2.0 * r_max,
                2.0 * w.r_o,
                case.computed,
                case.rubbing.min,
                case.rubbing.max,
                case.rubbing.average
            );
            curves.push(Curve {
                label: format!("case 5 welded, Rₒ = {:.4} in", w.r_o),
                points: vec![(0.0, w.r_o), (3.0, w.r_o)],
                color: (120, 120, 120),
            });
        }
        curves.push(Curve {
            label: (*name).into(),
            points: pts,
            color: colors[k],
        });
    }
    let (lo, hi) = curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.1))
        .fold((f64::INFINITY, 0.0f64), |(a, b), y| (a.min(y), b.max(y)));
    let fig = CurveFigure {
        title:
            "Separation radius against the friction coefficient (A = 0.1285 in, 0.124 on 0.257 in)"
                .into(),
        x_label: "friction coefficient μ".into(),
        y_label: "Rₒ [in]".into(),
        curves,
        markers: Vec::<Marker>::new(),
        x_range: (0.0, 3.0),
        y_range: (lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo)),
    };
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let mut files = Vec::new();
    for ext in ["svg", "png"] {
        let p = out.join(format!("21_friction.{ext}"));
        write_figure(&fig, &p, (1000, 650))?;
        files.push(p);
    }
    if !quick {
        println!("\ncost at 0.05 % (best of 3 wall times; the machine is shared):");
        for (name, lower) in &pairs {
            let j = joint(*lower)?;
            let t0 = time(&j, InterfaceModel::Frictionless, 3)?;
            let t1 = time(&j, InterfaceModel::Friction { mu: 0.3 }, 3)?;
            println!(
                "  {name}: frictionless {t0:.3} s, friction μ = 0.3 {t1:.3} s, ratio {:.2}",
                t1 / t0
            );
        }
    }
    println!("figure: {}", files[0].display());
    Ok(files)
}

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        let dir = std::env::temp_dir().join(format!("boltzone_ex18_{}", std::process::id()));
        run(&dir, true)?;
        return Ok(std::fs::remove_dir_all(&dir)?);
    }
    let out = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/figures"));
    run(&out, false).map(|_| ())
}
