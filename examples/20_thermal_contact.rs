//! # What temperature does to the contact zone
//!
//! Chapter V of the report (Gould & Mikic 1970) leaves open "large heat fluxes where thermal
//! strains may have an influence on the radii of separation". This example answers it for one
//! joint: two equal aluminium plates (E = 10⁷ psi, ν = 0.33, α = 13·10⁻⁶ /°F), D = 0.1 in,
//! A = 0.1 in, B = 0.31 in, C = 1 in, bearing pressure P = 1000 psi, stress-free at 70 °F,
//! frictionless interface unless said ([`boltzone::contact::thermal`]). It prints a table of R_o
//! and the peak interface pressure for
//! - no temperature change, a uniform rise of both plates, and plates at different uniform
//!   temperatures (frictionless and welded);
//! - a temperature difference ΔT through each plate, mirrored about the interface (outer faces
//!   hotter, or the interface hotter), for several ΔT;
//! - a steady heat flow through the stack (the same gradient in both plates, a jump at the
//!   interface);
//!
//! and draws p(r) for the mirrored gradients (`target/figures/20_thermal_contact.{svg,png}`, or
//! the directory given as the first argument).
//!
//! **What it shows.** A plate whose loaded face is hotter than its contact face bends with its rim
//! toward the interface (free curvature α ΔT/D), so the rims of both plates close and the contact
//! zone grows. At 0.4 °F the rims touch: the solver finds the interface closed at r = C and
//! reports R_o = C ("full contact"), while the figure's pressure still ends near 0.36 in (zero
//! out to 0.5 in): a contact in two parts, which R_o alone does not describe. A hotter interface
//! lifts the rims and the zone shrinks. The scale that matters is E α ΔT against P: here a few tenths of a degree across a 0.1 in plate already move R_o by
//! about a percent (the free plate's rim moves by α ΔT C²/(2D) = 6.5·10⁻⁵ in per °F, against
//! bolt-load gaps of ~10⁻⁵ in). Uniform temperatures change nothing on a frictionless interface
//! (each plate expands freely). Welded equal plates at different temperatures shear each other
//! (|τ| ≈ 1100 psi for 1 °F here) but do not move R_o: the mismatch is antisymmetric about the
//! interface, so its gap and normal traction there vanish and both plates bend together. A heat
//! flow through equal plates bends both alike: no change either.
//!
//! Checks (the example fails if one does not hold): T = T_ref everywhere gives the isothermal
//! R_o; a uniform rise, different uniform temperatures and the through-flow leave R_o (to
//! 1e-9) and p(r) (to a hundredth of the model's error estimate) of the frictionless joint
//! unchanged; R_o
//! grows monotonically with ΔT when the outer faces are hotter and shrinks when the interface is;
//! every solution balances the bolt force. `BOLTZONE_QUICK=1`: two ΔT, looser tolerance.
//!
//! Builds on: example 04 (the two-plate model), `tests/fem/thermal.rs` (the thermal strains).

use anyhow::ensure;
use boltzone::contact::thermal::{solve_with_temperature, JointTemperature, PlateTemperature};
use boltzone::contact::two_plate::{solve, InterfaceModel, TwoPlateParams, TwoPlateSolution};
use boltzone::plot::{write_figure, Curve, CurveFigure, Marker};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::path::PathBuf;
use std::time::Instant;

const T_REF: f64 = 70.0;
const ALPHA: f64 = 13e-6;

fn joint() -> anyhow::Result<Joint> {
    let p = Plate::new(0.1, Material::new(10.0e6, 0.33)?)?;
    Ok(Joint::new(
        0.1,
        OuterRadius::Finite(1.0),
        p,
        p,
        FaceLoad::uniform(0.1, 0.31, 1000.0)?,
    )?)
}

fn row(name: &str, s: &TwoPlateSolution, iso: f64, secs: f64) {
    let pmax = s.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
    let tmax = s.shear.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let note = if s.full_contact {
        "  closed at the rim: reported R_o = C (the main zone ends near 0.36 in, figure)"
    } else {
        ""
    };
    println!(
        "{name:<44} {:>9.5} ± {:.1e} in {:>+9.4} % {:>7.1} psi {:>6.1} psi {:>5.2} s{note}",
        s.r_o,
        s.r_o_error,
        100.0 * (s.r_o / iso - 1.0),
        pmax,
        tmax,
        secs
    );
}

/// (ΔR_o/R_o, Δp/p_max) of `a` against `b`, p compared at `b`'s nodes.
fn change(a: &TwoPlateSolution, b: &TwoPlateSolution) -> (f64, f64) {
    let pmax = b.pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    let dp = (0..b.radius.len())
        .map(|i| (a.pressure_at(b.radius[i]) - b.pressure[i]).abs() / pmax)
        .fold(0.0, f64::max);
    ((a.r_o - b.r_o).abs() / b.r_o, dp)
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let dir = std::env::args()
        .nth(1)
        .filter(|_| !quick)
        .map_or_else(|| PathBuf::from("target/figures"), PathBuf::from);
    let j = joint()?;
    let total = j.load().total_force();
    let params = TwoPlateParams {
        tolerance: if quick { 2e-3 } else { 2e-4 },
        both_plates: true,
        ..Default::default()
    };
    let run = |plates: [PlateTemperature; 2], p: &TwoPlateParams| -> anyhow::Result<_> {
        let t = JointTemperature::constant(&j, T_REF, plates, [ALPHA; 2])?;
        let t0 = Instant::now();
        let s = solve_with_temperature(&j, p, &t)?;
        let f: f64 = s.force.iter().sum();
        ensure!(
            (f - total).abs() <= 1e-8 * total,
            "equilibrium: {f} vs {total}"
        );
        Ok((s, t0.elapsed().as_secs_f64()))
    };
    let uniform = |t: f64| PlateTemperature::Uniform(t);
    let linear = |interface: f64, outer: f64| PlateTemperature::Linear { interface, outer };

    let t0 = Instant::now();
    let iso = solve(&j, &params)?;
    let iso_secs = t0.elapsed().as_secs_f64();
    println!("joint: A = 0.1 in, B = 0.31 in, D = 0.1 in, C = 1 in, P = 1000 psi, aluminium");
    println!(
        "{:<44} {:>9}   {:>10} {:>11} {:>11} {:>10} {:>7}",
        "case", "R_o", "(error)", "ΔR_o", "p_max", "|τ|_max", "time"
    );
    row("isothermal", &iso, iso.r_o, iso_secs);

    // Cases with an exact answer: nothing changes.
    let (same, secs) = run([uniform(T_REF), uniform(T_REF)], &params)?;
    row("T = T_ref everywhere", &same, iso.r_o, secs);
    let (rise, secs) = run([uniform(170.0), uniform(170.0)], &params)?;
    row("both plates +100 °F", &rise, iso.r_o, secs);
    let (apart, secs) = run([uniform(170.0), uniform(20.0)], &params)?;
    row(
        "upper +100 °F, lower −50 °F (frictionless)",
        &apart,
        iso.r_o,
        secs,
    );
    let (flow, secs) = run([linear(75.0, 80.0), linear(72.0, 67.0)], &params)?;
    row("heat flow through: 80→75 | 72→67 °F", &flow, iso.r_o, secs);
    // "Nothing changes" is exact; what remains is rounding, which the thermal displacements
    // (up to ~200 times the bolt-load ones) amplify to 5e-11–5e-8 of p (tests/contact/thermal.rs).
    // Checked: R_o to 1e-9, and p to a hundredth of the model's own relative error estimate
    // (no change a user could tell from the discretisation).
    let bound = 0.01 * iso.r_o_error / iso.r_o;
    for (name, s) in [
        ("T = T_ref", &same),
        ("uniform", &rise),
        ("different uniform", &apart),
        ("through-flow", &flow),
    ] {
        let (dr, dp) = change(s, &iso);
        println!("  {name}: ΔR_o/R_o = {dr:.1e}, Δp/p_max = {dp:.1e} (bound {bound:.1e})");
        ensure!(
            dr <= 1e-9 && dp <= bound,
            "{name}: changed by {dr:e}, {dp:e}"
        );
    }

    // Welded plates at different temperatures: the differential expansion shears the interface.
    let welded = TwoPlateParams {
        interface: InterfaceModel::Welded,
        ..params
    };
    let t0 = Instant::now();
    let iso_welded = solve(&j, &welded)?;
    row(
        "isothermal (welded)",
        &iso_welded,
        iso.r_o,
        t0.elapsed().as_secs_f64(),
    );
    match run([uniform(T_REF + 1.0), uniform(T_REF)], &welded) {
        Ok((s, secs)) => row("upper +1 °F (welded)", &s, iso.r_o, secs),
        Err(e) => println!("upper +1 °F (welded): {e}"),
    }

    // Mirrored gradients: R_o against ΔT through each plate.
    let steps: &[f64] = if quick {
        &[0.1, 0.2]
    } else {
        &[0.05, 0.1, 0.2, 0.4]
    };
    let mut out_hot = vec![iso.r_o];
    let mut in_hot = vec![iso.r_o];
    let mut curves = vec![(0.0, iso.clone())];
    for &dt in steps {
        let (s, secs) = run(
            [linear(T_REF, T_REF + dt), linear(T_REF, T_REF + dt)],
            &params,
        )?;
        row(
            &format!("outer faces +{dt} °F (ΔT through each plate)"),
            &s,
            iso.r_o,
            secs,
        );
        out_hot.push(s.r_o);
        curves.push((dt, s));
        let (s, secs) = run(
            [linear(T_REF + dt, T_REF), linear(T_REF + dt, T_REF)],
            &params,
        )?;
        row(&format!("interface +{dt} °F"), &s, iso.r_o, secs);
        in_hot.push(s.r_o);
        curves.push((-dt, s));
    }
    ensure!(
        out_hot.windows(2).all(|w| w[1] > w[0]),
        "outer faces hotter: R_o {out_hot:?}"
    );
    ensure!(
        in_hot.windows(2).all(|w| w[1] < w[0]),
        "interface hotter: R_o {in_hot:?}"
    );

    if !quick {
        std::fs::create_dir_all(&dir)?;
        curves.sort_by(|a, b| a.0.total_cmp(&b.0));
        let n = curves.len() as f64;
        let fig = CurveFigure {
            title: "Interface pressure with a temperature difference ΔT through each plate".into(),
            x_label: "r (in)".into(),
            y_label: "p (psi)".into(),
            curves: curves
                .iter()
                .enumerate()
                .map(|(k, (dt, s))| Curve {
                    label: match dt {
                        d if *d > 0.0 => format!("outer faces +{d} °F"),
                        d if *d < 0.0 => format!("interface +{} °F", -d),
                        _ => "isothermal".into(),
                    },
                    points: s
                        .radius
                        .iter()
                        .zip(&s.pressure)
                        .filter(|(r, _)| **r <= 0.5)
                        .map(|(&r, &p)| (r, p))
                        .collect(),
                    color: (
                        (255.0 * k as f64 / n) as u8,
                        60,
                        (255.0 * (1.0 - k as f64 / n)) as u8,
                    ),
                })
                .collect(),
            markers: vec![Marker {
                label: "load edge B".into(),
                x: 0.31,
                color: (120, 120, 120),
            }],
            x_range: (0.1, 0.5),
            y_range: (
                0.0,
                curves
                    .iter()
                    .map(|c| c.1.pressure.iter().fold(0.0f64, |m, p| m.max(*p)))
                    .fold(0.0, f64::max)
                    * 1.05,
            ),
        };
        for ext in ["svg", "png"] {
            let path = dir.join(format!("20_thermal_contact.{ext}"));
            write_figure(&fig, &path, (900, 600))?;
            println!("wrote {}", path.display());
        }
    }
    Ok(())
}
