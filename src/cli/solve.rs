//! `boltzone solve SCENE.toml`: answers a scene file ([`boltzone::scene`]): one joint, or every
//! point of its `[sweep]` in parallel; `--json` prints the result object (a sweep:
//! `{"results": [...]}`), `--explain` the plan (routes run and skipped, time per step).
//!
//! # Accuracy
//!
//! No numerics of its own (`boltzone::scene`): `tests/scene/errors.rs` (exit codes 2 and 3, sweeps,
//! `--explain`) and `tests/scene/examples.rs` (the command equals the library call).
//!
//! # Cost
//!
//! That of the scene's routes (example 17).

use super::exit::{sig, Status, UsageError};
use boltzone::route::sanity;
use boltzone::scene::sweep::{points, rows, solve_all, SweepPoint};
use boltzone::scene::{read, Scene, SceneError, Solution};
use std::path::{Path, PathBuf};

/// Arguments of `boltzone solve`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scene file (TOML; see `examples/scenes/`).
    scene: PathBuf,
    /// Print the result as JSON (a sweep: {"results": [...]}).
    #[arg(long)]
    json: bool,
    /// Print the plan: which routes ran, which were skipped, time per step.
    #[arg(long)]
    explain: bool,
    /// A CSV of geometries: a header row naming dotted scene keys (`load.outer_radius`,
    /// `plates[0].thickness`), one point per further row, in the scene's units.
    #[arg(long)]
    geometries: Option<PathBuf>,
    /// Treat a plausibility warning (a modulus or pressure that looks like a unit slip, a
    /// deflection beyond 1 % of the plate) as bad input: exit 2 instead of a warning on stderr.
    #[arg(long)]
    strict: bool,
}

/// The plausibility warnings of `scene` naming the scene keys: before solving (`s` None) of its
/// moduli and bearing pressure in its own units, after (`s` its solution) of its deflection
/// under the nut; with `strict` the first is refused as bad input (exit 2).
fn warn(scene: &Scene, s: Option<&Solution>, strict: bool) -> anyhow::Result<()> {
    let st = scene.units.stress();
    let e = |i: usize| boltzone::scene::si::material(scene, i).map(|m| m.youngs_modulus() / st);
    let last = scene.plates.len().saturating_sub(1);
    let (a, b) = (scene.hole.radius, scene.load.outer_radius);
    let p = match (scene.load.pressure, scene.load.force) {
        (Some(p), _) => p,
        (None, Some(f)) => f / (std::f64::consts::PI * (b * b - a * a)),
        (None, None) => 0.0,
    };
    let thinner = scene
        .plates
        .iter()
        .map(|p| p.thickness)
        .fold(f64::INFINITY, f64::min);
    let w = match s {
        None => {
            let e = [e(0).map_err(classify)?, e(last).map_err(classify)?];
            sanity::inputs(scene.units, e, p)
        }
        Some(s) => s
            .nut_deflection
            .and_then(|d| sanity::deflection(d, thinner))
            .into_iter()
            .collect(),
    };
    for w in w {
        let key = match w.slip {
            sanity::Slip::Modulus { plate } => format!("plates[{}].material", plate.min(last)),
            sanity::Slip::Pressure if scene.load.force.is_some() => "load.force".into(),
            sanity::Slip::Pressure => "load.pressure".into(),
            sanity::Slip::Deflection => "load".into(),
        };
        if strict {
            return Err(UsageError(format!("{key}: {} (--strict)", w.message)).into());
        }
        eprintln!("warning: {key}: {}", w.message);
    }
    Ok(())
}

/// Bad input becomes a [`UsageError`] (exit 2); a solver failure stays as it is (exit 1).
fn classify(e: SceneError) -> anyhow::Error {
    if e.is_input() {
        UsageError(e.to_string()).into()
    } else {
        e.into()
    }
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<Status> {
    let start = std::time::Instant::now();
    let text = read(&args.scene).map_err(classify)?;
    let pts = match &args.geometries {
        Some(csv) => {
            let table = match std::fs::read_to_string(csv) {
                Ok(t) => t,
                Err(e) => {
                    let why = format!("cannot read the geometries CSV: {e}");
                    return super::exit::usage("--geometries", csv.display(), &why);
                }
            };
            rows(&text, &table).map_err(classify)?
        }
        None => points(&text).map_err(classify)?,
    };
    let base = &pts[0].scene;
    warn(base, None, args.strict)?;
    if pts.len() == 1 && pts[0].values.is_empty() {
        let s = boltzone::solve(base).map_err(classify)?;
        warn(base, Some(&s), args.strict)?;
        if let Some(path) = &base.outputs.interface_pressure {
            super::write_output(path, &curve_csv(&pts, &[Ok(s.clone())], &args.scene))?;
        }
        let o = &base.outputs;
        write_fields(&s, (o.field.as_deref(), o.midplane.as_deref()), &args.scene)?;
        if let Some(path) = &o.plot {
            super::solve_plot::write(path, base, &s)?;
        }
        if let Some(path) = &o.report {
            super::solve_report::write(path, base, &s)?;
        }
        if args.json {
            let mut v = serde_json::to_value(&s)?;
            super::output::stamp_run(&mut v, start)?;
            super::print_json(&v)?;
        } else {
            print_text(&s);
        }
        if args.explain {
            explain(&s);
        }
        return Ok(Status::from_converged(s.converged));
    }
    for (key, p) in [
        ("plot", &base.outputs.plot),
        ("report", &base.outputs.report),
    ] {
        if let Some(p) = p {
            return Err(UsageError(format!(
                "scene key `outputs.{key}` = {}: one joint per {key}; a [sweep] or --geometries \
                 run writes outputs.results and outputs.interface_pressure instead",
                p.display()
            ))
            .into());
        }
    }
    let bar = super::progress(pts.len() as u64, "sweep");
    let results = solve_all(&pts, &|| bar.inc(1));
    bar.finish_and_clear();
    let failed = results
        .iter()
        .find_map(|r| r.as_ref().err().map(|e| e.to_string()));
    // one point's JSON object: its solution (or error) with the point's values under "sweep"
    let row = |i: usize| -> anyhow::Result<serde_json::Value> {
        let sweep: serde_json::Map<String, serde_json::Value> = pts[i]
            .values
            .iter()
            .map(|(k, v)| (k.clone(), serde_json::to_value(v).unwrap_or_default()))
            .collect();
        let path = format!("result.results[{i}]");
        Ok(match &results[i] {
            Ok(s) => {
                let mut v = super::print::checked_json(s, &path)?;
                v["sweep"] = super::print::checked_json(&sweep, &format!("{path}.sweep"))?;
                v
            }
            Err(e) => super::print::checked_json(
                &serde_json::json!({ "sweep": sweep, "error": e.to_string() }),
                &path,
            )?,
        })
    };
    if let Some(path) = &base.outputs.interface_pressure {
        super::write_output(path, &curve_csv(&pts, &results, &args.scene))?;
    }
    // one field and midplane file per point: NAME_i.EXT, i the point's index from 0
    for (i, r) in results.iter().enumerate() {
        if let Ok(s) = r {
            let o = &base.outputs;
            let f = o.field.as_deref().map(|p| numbered(p, i));
            let m = o.midplane.as_deref().map(|p| numbered(p, i));
            write_fields(s, (f.as_deref(), m.as_deref()), &args.scene)?;
        }
    }
    if let Some(path) = &base.outputs.results {
        super::write_output(path, &sweep_csv(&pts, &results, &args.scene))?;
    }
    if args.json {
        let mut head = serde_json::json!({});
        super::output::stamp_run(&mut head, start)?;
        let head = head.as_object().cloned().unwrap_or_default();
        super::print::print_json_results(&head, pts.len(), &row)?;
    } else {
        for (p, r) in pts.iter().zip(&results) {
            let at: Vec<String> = p.values.iter().map(|(k, v)| format!("{k} = {v}")).collect();
            match r {
                Ok(s) => println!("{}:  {}", at.join(", "), r_o_line(s)),
                Err(e) => println!("{}:  FAILED: {e}", at.join(", ")),
            }
        }
    }
    if args.explain {
        for s in results.iter().flatten().take(1) {
            explain(s);
        }
    }
    if let Some(e) = failed {
        anyhow::bail!("a sweep point failed: {e}");
    }
    Ok(Status::from_converged(
        results.iter().flatten().all(|s| s.converged),
    ))
}

/// "R_o = … ± … mm  (model, method)".
fn r_o_line(s: &Solution) -> String {
    let u = s.length_unit;
    format!(
        "R_o = {} ± {:.1e} {u}  ({}, {}){}",
        sig(s.r_o, 7),
        s.r_o_error,
        serde_json::to_value(s.model).map_or(String::new(), |v| v.as_str().unwrap_or("").into()),
        serde_json::to_value(s.method).map_or(String::new(), |v| v.as_str().unwrap_or("").into()),
        if s.converged {
            ""
        } else {
            "  NOT converged to the tolerance (exit 3)"
        }
    )
}

fn print_text(s: &Solution) {
    println!("{}", r_o_line(s));
    if s.full_contact == Some(true) {
        println!("full contact: the plates touch out to the rim, R_o = C");
    }
    if let Some(d) = s.nut_deflection {
        println!("deflection under the nut: {d:.4e} {}", s.length_unit);
    }
    println!("{}", super::print::rules_line(&s.rules, s.length_unit));
    for line in super::two_bolt::lines(&s.joint, s.units) {
        println!("{line}");
    }
    if let (Some(g), Some(u)) = (s.joint_conductance, s.conductance_unit) {
        println!(
            "joint conductance (integral of h_c dA over the contact zone): {} {u}",
            sig(g, 6)
        );
    }
    if let (Some(q), Some(u), Some(n)) = (s.heat_flow, s.heat_flow_unit, s.heat_passes) {
        let q = sig(q, 6);
        println!("heat flow through the joint (from_heat, {n} thermal passes): {q} {u}");
    }
}

/// The plan, on stderr-free stdout after the result.
fn explain(s: &Solution) {
    println!("plan ({}):", s.units.name());
    for st in &s.plan {
        println!(
            "  {} {:<45} {:>10.3} ms  {}",
            if st.ran { "ran    " } else { "skipped" },
            st.name,
            1e3 * st.seconds,
            st.note
        );
    }
}

/// The interface curves as CSV: header with units first (the swept keys first in a sweep),
/// `#` provenance after it, then r, p, g, τ of each point's finest mesh (shortest round-trip
/// numbers: each reads back as the solution's own f64).
fn curve_csv(
    pts: &[SweepPoint],
    results: &[Result<Solution, SceneError>],
    scene: &std::path::Path,
) -> String {
    let (l, p, _) = pts[0].scene.units.symbols();
    let keys: String = pts[0].values.iter().map(|(k, _)| format!("{k},")).collect();
    let friction = results
        .iter()
        .any(|r| r.as_ref().is_ok_and(|s| s.friction.is_some()));
    let (cols, note) = if friction {
        (
            format!(",s [{l}],state [-]"),
            "; s = slip u_upper - u_lower (outward > 0), state 0 open, 1 stick, 2 slip",
        )
    } else {
        (String::new(), "")
    };
    let mut out = format!(
        "{keys}r [{l}],p [{p}],g [{l}],tau [{p}]{cols}\n# boltzone {} solve {}: interface of the \
         finest mesh; p > 0 compression, g = gap between the plates, tau = interface shear on the \
         upper plate (0 in the frictionless model){note}\n",
        env!("CARGO_PKG_VERSION"),
        scene.display(),
    );
    for (pt, r) in pts.iter().zip(results) {
        let at: String = pt.values.iter().map(|(_, v)| format!("{v},")).collect();
        let shown: String = pt
            .values
            .iter()
            .map(|(k, v)| format!("{k} = {v}: "))
            .collect();
        let Ok(s) = r else {
            out += &format!("# {shown}failed\n");
            continue;
        };
        out += &format!(
            "# {shown}R_o = {} ± {:e} {l}, converged = {}\n",
            s.r_o, s.r_o_error, s.converged
        );
        let Some(c) = &s.interface else { continue };
        for i in 0..c.radius.len() {
            let (r, pr, g, tau) = (c.radius[i], c.pressure[i], c.gap[i], c.shear[i]);
            out += &format!("{at}{r:e},{pr:e},{g:e},{tau:e}");
            if friction {
                let (s, st) = (c.slip.get(i), c.state.get(i));
                match (s, st) {
                    (Some(s), Some(st)) => out += &format!(",{s:e},{st}"),
                    _ => out += ",,",
                }
            }
            out += "\n";
        }
    }
    out
}

/// One row per sweep point: the swept keys, R_o, its error, converged.
fn sweep_csv(
    pts: &[SweepPoint],
    results: &[Result<Solution, SceneError>],
    scene: &std::path::Path,
) -> String {
    let l = pts[0].scene.units.symbols().0;
    let keys: Vec<String> = pts[0].values.iter().map(|(k, _)| k.clone()).collect();
    let mut out = format!(
        "{},r_o_{l},r_o_error_{l},converged\n# boltzone solve {}: one row per sweep point; \
         swept lengths in {l}, stresses in {}, forces in {}\n",
        keys.join(","),
        scene.display(),
        pts[0].scene.units.symbols().1,
        pts[0].scene.units.symbols().2,
    );
    for (p, r) in pts.iter().zip(results) {
        let vals: Vec<String> = p.values.iter().map(|(_, v)| v.to_string()).collect();
        match r {
            Ok(s) => {
                out += &format!(
                    "{},{},{},{}\n",
                    vals.join(","),
                    s.r_o,
                    s.r_o_error,
                    s.converged
                )
            }
            Err(_) => out += &format!("{},,,false\n", vals.join(",")),
        }
    }
    out
}

/// `[outputs] field` (VTU) and `midplane` (CSV, the one curve layout), in the scene's units.
fn write_fields(
    s: &Solution,
    (field, midplane): (Option<&Path>, Option<&Path>),
    file: &Path,
) -> anyhow::Result<()> {
    let (l, st, _) = s.units.symbols();
    let r_o = format!(
        "R_o = {:e} {l} +- {:.2e} {l}, converged: {}",
        s.r_o, s.r_o_error, s.converged
    );
    if let (Some(path), Some(grid)) = (field, &s.field) {
        let hot = grid.scalars.iter().any(|(n, _)| n == "temperature");
        let note = format!(
            "boltzone solve {}: finest mesh of the {} route ({:?} model); units {}: coordinates, \
             displacements and gap in {l}, stresses and contact_pressure in {st} (compression \
             negative; contact_pressure > 0 in compression){}; {r_o}; command: {}",
            file.display(),
            serde_json::to_value(s.method)?.as_str().unwrap_or(""),
            s.model,
            s.units.name(),
            if hot {
                "; temperature in the degrees of [temperature], stresses sigma = D (eps - eps_th)"
            } else {
                ""
            },
            super::output::command_line()
        );
        super::write_output(path, &grid.to_vtu(&note))?;
    }
    if let (Some(path), Some(m)) = (midplane, &s.midplane) {
        let r = format!("r [{l}]");
        let z = format!("sigma_z [{st}]");
        let e = format!("sigma_z_error [{st}]");
        let mut cols = vec![r.as_str(), z.as_str()];
        let rows: Vec<Vec<f64>> = match &m.error {
            Some(err) => {
                cols.push(e.as_str());
                (0..m.radius.len())
                    .map(|i| vec![m.radius[i], m.sigma_z[i], err[i]])
                    .collect()
            }
            None => (0..m.radius.len())
                .map(|i| vec![m.radius[i], m.sigma_z[i]])
                .collect(),
        };
        let notes = [
            format!(
                "scene {}: midplane normal stress, compression negative ({:?} model, {} route)",
                file.display(),
                s.model,
                serde_json::to_value(s.method)?.as_str().unwrap_or("")
            ),
            r_o,
        ];
        super::write_output(
            path,
            &super::output::curve_csv_in(s.units, &cols, &notes, &rows),
        )?;
    }
    Ok(())
}

/// `dir/NAME_i.EXT` for `dir/NAME.EXT`: point `i`'s file of a sweep.
fn numbered(path: &Path, i: usize) -> PathBuf {
    let stem = path.file_stem().unwrap_or_default().to_string_lossy();
    let name = match path.extension() {
        Some(e) => format!("{stem}_{i}.{}", e.to_string_lossy()),
        None => format!("{stem}_{i}"),
    };
    path.with_file_name(name)
}
