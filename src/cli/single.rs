//! `boltzone single`: the single-plate model (Fernlund's substitution, a plate 2D thick with a
//! hole, loaded on both faces by a uniform pressure over A..B) and its separation radius R_o.
//! `--method fem` runs [`boltzone::fem::single::single_plate_r_o`] (refinement levels halving the
//! elements at A, B and the previous R_o; error estimate max(|d₃|, |d₂|/4, |d₁|/16) of the last
//! level changes, [`boltzone::numerics::convergence::level_estimate`]); `--method hankel` runs
//! [`boltzone::hankel::hole::single_plate_separation`] (infinite slab + hole correction, and a
//! rim correction when `--c` is given).
//!
//! `--units` (in-psi-lbf, mm-MPa-N, m-Pa-N) sets the length of every flag and every printed
//! length, and the stress of the curve, the VTU and the figures (P = 1 in that stress). Checked by `tests/scene/joint_units.rs`
//! (the same R_o to 1e-12 in the three systems by both methods).
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/fem/cli.rs` and `tests/hankel/hole_cli.rs` check the JSON against
//! the library's value and that bad input names the field.
//!
//! # Cost
//!
//! That of the method run (`cargo bench --bench fem`, `cargo bench --bench hole`).

use super::args::{Element, Geometry, OutputFiles, Units};
use super::check;
use super::exit::{num, sig, Status};
use boltzone::fem::single::{
    midplane_of, solve, solve_with_field, FaceCondition, HalfPlate, SingleParams, SingleSolution,
};
use boltzone::fem::ElementKind;
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::separation::SeparationError;
use boltzone::route::two_plate::Key;
use boltzone::route::{single_plate, Method};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// How the bolt head loads the faces (fem).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Nut {
    /// Uniform bearing pressure over A..B (Table 1).
    Pressure,
    /// Rigid frictionless nut: uniform displacement over A..B (report Fig. 21).
    Rigid,
}

/// Arguments of `boltzone single`.
#[derive(Debug, clap::Args, serde::Serialize)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    #[command(flatten)]
    #[serde(flatten)]
    geom: Geometry,
    /// Lengths in (A, B, D, C and every printed length) and the stress of the curve (P = 1 in
    /// the stress unit).
    #[command(flatten)]
    #[serde(flatten)]
    units: Units,
    /// Plate outer radius C (default: infinite, truncated at B + 30 D).
    #[arg(long)]
    c: Option<f64>,
    /// Solver: fem, hankel (R_o and the midplane curve, milliseconds), table (R_o from the
    /// infinite plate's tables, a rim --c through its bound, microseconds), or auto (fem where --field, --plot or
    /// --nut rigid ask for it, else table where its bar meets --tol, else hankel).
    #[arg(long, value_enum, default_value_t = Method::Fem)]
    method: Method,
    /// Element family (fem).
    #[arg(long, value_enum, default_value_t = Element::Q9)]
    element: Element,
    /// Face loading (fem).
    #[arg(long, value_enum, default_value_t = Nut::Pressure)]
    nut: Nut,
    /// Most refinement levels (fem, 3..=12): levels are added until the error estimate meets
    /// --tol.
    #[arg(long, default_value_t = boltzone::fem::single::MAX_LEVELS)]
    levels: usize,
    /// Wanted relative error of R_o (default 5e-4 for fem, 1e-6 for hankel); a result that
    /// misses it is flagged NOT converged and the command exits 3.
    #[arg(long)]
    tol: Option<f64>,
    /// Corner exponents λ₁, λ₁+1, λ₁+2, λ₂, … whose singular fields enrich the hole fit
    /// (hankel; 0 = Papkovich–Fadle modes only, at most 6).
    #[arg(long, default_value_t = HoleParams::default().corner_terms)]
    corner_terms: usize,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
    /// Curve, field and figure files (fem).
    #[command(flatten)]
    #[serde(flatten)]
    out: OutputFiles,
}

/// The plate of the flags (None where they do not make one: [`check_args`] says why).
fn plate(args: &Args) -> Option<SinglePlate> {
    let g = &args.geom;
    let outer = args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    let load = FaceLoad::uniform(g.a, g.b, 1.0).ok()?;
    SinglePlate::new(g.a, outer, g.d, Material::unit(g.nu).ok()?, load).ok()
}

/// The route layer's question of the flags, on `plate` (--tol, or the Hankel route's and
/// the tables' default: the finite elements never answer from the tables).
fn question<'a>(args: &Args, plate: Option<&'a SinglePlate>) -> single_plate::Question<'a> {
    single_plate::Question {
        method: args.method,
        field: args.out.field.is_some() || args.out.plot.is_some(),
        curve: args.out.curve.is_some(),
        rigid_nut: args.nut == Nut::Rigid,
        thermal: false,
        b_over_d: args.geom.b / args.geom.d,
        plate,
        tolerance: args
            .tol
            .unwrap_or(single_plate::default_tolerance(Method::Table)),
    }
}

/// The route that answers (the route layer's choice for the method asked; `table` out of the
/// tables' reach is refused by [`check_args`]).
fn route(args: &Args) -> Method {
    let plate = plate(args);
    single_plate::plan(&question(args, plate.as_ref())).map_or(Method::Table, |p| p.method)
}

/// The flag of the route layer's [`Key`] that keeps the flags from the tables, and its value.
fn table_flag(args: &Args, key: Key) -> (&'static str, String) {
    let g = &args.geom;
    match key {
        Key::OuterRadius => ("--c", args.c.map_or("infinite".into(), num)),
        Key::HoleRadius => ("--a", num(g.a)),
        Key::Poisson => ("--nu", g.nu.to_string()),
        Key::Tolerance => (
            "--tol",
            args.tol.map_or("default".into(), |t| t.to_string()),
        ),
        Key::Curve => ("--curve", "given".into()),
        Key::Field => ("--field/--plot", "given".into()),
        Key::NutDisplacement => ("--nut", "rigid".into()),
        _ => ("--b", num(g.b)),
    }
}

/// --tol, or the route's default ([`single_plate::default_tolerance`]).
fn tolerance(args: &Args) -> f64 {
    args.tol
        .unwrap_or_else(|| single_plate::default_tolerance(route(args)))
}

/// Checks every flag before any work starts (exit 2 naming the flag).
fn check_args(args: &Args) -> anyhow::Result<()> {
    let g = &args.geom;
    check::annulus(g.a, g.b)?;
    check::positive("--d", "plate half-thickness D (the plate is 2D thick)", g.d)?;
    if let Some(c) = args.c {
        check::outer_radius("--c", c, g.b)?;
    }
    let nu_max = if route(args) == Method::Fem {
        check::NU_MAX_FEM
    } else {
        0.5
    };
    check::poisson("--nu", g.nu, nu_max)?;
    check::tolerance("--tol", tolerance(args))?;
    check::domain(g.a, g.b, g.d, check::B_OVER_D_SINGLE)?;
    if !(3..=12).contains(&args.levels) {
        return super::exit::usage("--levels", args.levels, "must lie in 3..=12");
    }
    if args.corner_terms > 6 {
        return super::exit::usage("--corner-terms", args.corner_terms, "must lie in 0..=6");
    }
    if args.method == Method::Table {
        let plate = plate(args);
        if let Err(b) = single_plate::table_answer(&question(args, plate.as_ref())) {
            let (flag, value) = table_flag(args, b.key);
            return super::exit::usage(
                flag,
                value,
                &format!("{} (--method table); use --method hankel or auto", b.reason),
            );
        }
    }
    let hankel_reach = boltzone::route::reach::B_OVER_D_SINGLE_HANKEL;
    if args.method == Method::Hankel && g.b / g.d > hankel_reach {
        return super::exit::usage(
            "--b",
            super::exit::num(g.b),
            &format!(
                "the Hankel route reaches bearing faces of at most {hankel_reach:e} plate                  thicknesses (B/D = {:.3e}): use --method fem or auto",
                g.b / g.d
            ),
        );
    }
    if route(args) == Method::Hankel && args.nut != Nut::Pressure {
        return super::exit::usage(
            "--nut",
            "rigid",
            "needs --method fem (the Hankel route loads the faces by a pressure)",
        );
    }
    if (args.out.field.is_some() || args.out.plot.is_some()) && route(args) == Method::Hankel {
        return super::exit::usage(
            "--field/--plot",
            "given",
            "need --method fem (the finest FE level is what they show)",
        );
    }
    args.out.check()?;
    Ok(())
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<Status> {
    let start = std::time::Instant::now();
    check_args(&args)?;
    let outer = args.c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    let load = FaceLoad::uniform(args.geom.a, args.geom.b, 1.0)?;
    let plate = SinglePlate::new(
        args.geom.a,
        outer,
        args.geom.d,
        Material::unit(args.geom.nu)?,
        load,
    )?;
    match route(&args) {
        Method::Hankel => return run_hankel(&args, &plate, start),
        Method::Table => return run_table(&args, &plate, start),
        _ => {}
    }
    let kind = ElementKind::from(args.element);
    let loading = match args.nut {
        Nut::Pressure => FaceCondition::Pressure,
        Nut::Rigid => FaceCondition::UniformDisplacement,
    };
    let params = SingleParams {
        loading,
        kind,
        levels: args.levels,
        tolerance: tolerance(&args),
        ..SingleParams::default()
    };
    let s = if args.out.any() {
        let (s, finest) = solve_with_field(&plate, &params)?;
        write_finest(&args, &plate, &params, &s, &finest)?;
        s
    } else {
        solve(&plate, &params)?
    };
    let info = &s.info;
    let l = args.units.length();
    if args.json {
        let v = serde_json::json!({
            "element": format!("{kind:?}"),
            "loading": format!("{loading:?}"),
            "full_contact": s.full_contact,
            // one object per level, coarse to fine, keyed as two's level records
            "levels": info.levels.iter().map(|r_o| serde_json::json!({ "r_o": r_o })).collect::<Vec<_>>(),
            "observed_order": info.observed_order,
            "nodes": info.nodes,
            "dofs": info.dofs,
            "seconds": info.seconds,
        });
        finish_json(v, &args, "fem", (s.r_o, s.r_o_error, s.converged), start)?;
    } else {
        let r_o = (s.r_o, s.r_o_error, s.converged);
        print_head(&args, &format!("FE ({kind:?})"), r_o, (7, 5));
        println!(
            "levels   = {:?} {l}\norder    = {}\nmesh     = {} nodes, {} dofs (finest), {:.2} s",
            info.levels,
            info.observed_order
                .map_or("-".into(), |p| format!("{p:.2}")),
            info.nodes,
            info.dofs,
            info.seconds
        );
        if s.full_contact {
            println!("full contact: the midplane stays compressive out to the rim, R_o = C");
        }
    }
    Ok(Status::from_converged(s.converged))
}

/// Adds the keys every route answers — `method`, `r_o`, `r_o_error`, `converged` of
/// `(r_o, error, converged)`, `tolerance`, `units`, R_o/A (with a hole) — and the run's stamp
/// and the tolerance used to the route's own JSON keys `v`, and prints it.
fn finish_json(
    mut v: serde_json::Value,
    args: &Args,
    method: &str,
    (r_o, error, converged): (f64, f64, bool),
    start: std::time::Instant,
) -> anyhow::Result<()> {
    v["method"] = method.into();
    v["r_o"] = r_o.into();
    v["r_o_error"] = error.into();
    v["converged"] = converged.into();
    v["tolerance"] = tolerance(args).into();
    v["units"] = args.units.units.name().into();
    if args.geom.a > 0.0 {
        v["r_o_over_a"] = (r_o / args.geom.a).into();
    }
    super::output::stamp(&mut v, args, start)?;
    v["inputs"]["tol"] = tolerance(args).into(); // the method's default filled in
    super::print_json(&v)
}

/// Prints the text answer's first lines: the plate and the `route`, R_o ± error (R_o, error,
/// converged) to `digits.0` significant digits and R_o/A (with a hole) to `digits.1` decimals.
fn print_head(args: &Args, route: &str, r_o: (f64, f64, bool), digits: (usize, usize)) {
    let l = args.units.length();
    println!(
        "single plate 2D thick, {route}, A = {} {l}, B = {} {l}, D = {} {l}, C = {}, nu = {}",
        num(args.geom.a),
        num(args.geom.b),
        num(args.geom.d),
        args.c
            .map_or("infinite".into(), |c| format!("{} {l}", num(c))),
        args.geom.nu
    );
    println!(
        "R_o      = {} ± {:.2e} {l}{}",
        sig(r_o.0, digits.0),
        r_o.1,
        not_converged(r_o.2)
    );
    if args.geom.a > 0.0 {
        println!("R_o / A  = {:.*}", digits.1, r_o.0 / args.geom.a);
    }
}

/// The text flag of a result that missed --tol.
fn not_converged(converged: bool) -> &'static str {
    if converged {
        ""
    } else {
        "   NOT converged to --tol (exit 3)"
    }
}

/// `--method table` (or `auto` where the tables' bar meets --tol): R_o from the infinite
/// plate's tables, a rim through its bound ([`single_plate::table_answer`]).
fn run_table(
    args: &Args,
    plate: &SinglePlate,
    start: std::time::Instant,
) -> anyhow::Result<Status> {
    let r = single_plate::table_answer(&question(args, Some(plate)))
        .map_err(|b| anyhow::anyhow!("the tables do not answer: {}", b.reason))?;
    if args.json {
        let v = serde_json::json!({});
        finish_json(v, args, "table", (r.value, r.error, r.converged), start)?;
    } else {
        print_head(
            args,
            "from the tables (built by the 1e-8 Hankel route)",
            (r.value, r.error, r.converged),
            (9, 7),
        );
        println!("time     = {:.3} ms", 1e3 * start.elapsed().as_secs_f64());
    }
    Ok(Status::from_converged(r.converged))
}

/// `--method hankel`: R_o of the plate with its hole made traction-free (Hankel route).
fn run_hankel(
    args: &Args,
    plate: &SinglePlate,
    start: std::time::Instant,
) -> anyhow::Result<Status> {
    let (search, params) = single_plate::hankel_params(tolerance(args));
    let params = HoleParams {
        corner_terms: args.corner_terms,
        ..params
    };
    // Every flag was checked: what the route rejects now is a plate outside its reach (e.g.
    // too thin for its quadrature budget), a limit of the method (exit 1), not bad input.
    let (sep, hole) = match single_plate_separation(plate, &search, &params) {
        Ok(found) => found,
        // a rim within reach of the load's compression: the plate may touch out to C, which
        // only the finite elements answer (full contact, R_o = C)
        Err(e @ SeparationError::NotFound { .. }) if args.c.is_some() => {
            let why = format!(
                "{e}: the plate may be in full contact out to its rim, which the Hankel route \
                 cannot answer; use --method fem"
            );
            return super::exit::usage("--c", super::exit::num(args.c.unwrap_or(0.0)), &why);
        }
        Err(e) => anyhow::bail!("the Hankel route cannot treat this plate ({e}); try --method fem"),
    };
    if let Some(path) = &args.out.curve {
        let (l, st) = (args.units.length(), args.units.stress());
        let r = super::hankel_curve::radii(plate, 200);
        let (values, worst) = super::hankel_curve::midplane_curve(plate, &params, &hole, &r)?;
        let notes = [
            format!(
                "method: single plate 2D thick with a traction-free hole, semi-analytic (Hankel \
                 transform of the slab + hole correction with {} modes, \
                 boltzone::hankel::hole); P = 1 {st}: stresses scale with P",
                hole.terms
            ),
            "sigma_z = midplane normal stress, compression negative".to_string(),
            format!(
                "sigma_z error bound: {worst:.2e} {st} (slab quadrature + hole residual traction)"
            ),
            super::output::r_o_note_in(l, sep.r_o, sep.r_o_error, sep.converged),
        ];
        let rows: Vec<Vec<f64>> = r.iter().zip(&values).map(|(r, v)| vec![*r, v[0]]).collect();
        super::write_output(path, &sigma_curve(args.units, &notes, &rows))?;
    }
    let l = args.units.length();
    if args.json {
        let v = serde_json::json!({
            "outer_radius": args.c,
            "hole_terms": hole.terms,
            "hole_corner_terms": hole.corner_terms,
            "hole_residual_max": hole.residual_max,
            "hole_residual_rms": hole.residual_rms,
            "rim_residual_max": hole.rim_residual_max,
            "rim_bound": hole.rim_bound,
            "hole_condition": hole.condition,
            "hole_history": hole.history,
            "evaluations": sep.evaluations + hole.slab_evaluations,
            "seconds": sep.seconds,
        });
        finish_json(
            v,
            args,
            "hankel",
            (sep.r_o, sep.r_o_error, sep.converged),
            start,
        )?;
    } else {
        let r_o = (sep.r_o, sep.r_o_error, sep.converged);
        print_head(args, "with a hole, Hankel route", r_o, (9, 7));
        println!(
            "hole     = {} modes + {} corner exponents, residual traction max {:.2e} P, rms {:.2e} P, condition {:.1e}",
            hole.terms, hole.corner_terms, hole.residual_max, hole.residual_rms, hole.condition
        );
        if hole.rim_bound > 0.0 {
            println!(
                "rim      = not fitted: it moves R_o by at most {:.2e} {l} (included in ±)",
                hole.rim_bound
            );
        } else if args.c.is_some() {
            println!(
                "rim      = residual traction max {:.2e} P",
                hole.rim_residual_max
            );
        }
        println!("time     = {:.2} ms", 1e3 * sep.seconds);
    }
    Ok(Status::from_converged(sep.converged))
}

/// `--curve` and `--field`: the finest level kept by [`solve_with_field`], its midplane
/// σ_z as CSV and its field as VTU (upper half and its mirror image: the whole plate 2D thick).
fn write_finest(
    args: &Args,
    plate: &SinglePlate,
    params: &SingleParams,
    s: &SingleSolution,
    h: &HalfPlate,
) -> anyhow::Result<()> {
    let (l, st) = (args.units.length(), args.units.stress());
    let method = format!(
        "method: single plate 2D thick (Fernlund's substitution), axisymmetric FE {:?}, finest of \
         {} levels ({} nodes in the upper half); E = 1 {st}, P = 1 {st}: stresses scale with P, \
         displacements with P/E",
        params.kind,
        s.info.levels.len(),
        h.mesh.n_nodes()
    );
    let m = midplane_of(plate, h)?;
    if let Some(path) = &args.out.plot {
        let g = &args.geom;
        let y_label = format!("σz [{st}] (P = 1 {st})");
        let what = format!("single plate 2D thick (E = P = 1 {st})");
        let curve = super::figure::RadiusCurve {
            title: "Single plate 2D thick: midplane normal stress (FE, finest level)".into(),
            y_label: &y_label,
            label: "σz(r), finest mesh",
            r: &m.r,
            y: &m.sigma_z,
            r_o: (s.r_o, s.r_o_error),
            length: l,
        };
        let x_end = super::figure::radius_plot(path, &curve, (g.b, g.d, g.d, args.c))?;
        let d = super::joint_figs::Deformed {
            what: &what,
            mesh: &h.mesh,
            u: &h.u,
            mirror: true,
            names: vec![
                "upper half (computed)".into(),
                "lower half (mirror image)".into(),
            ],
            b: g.b,
            r_o: (s.r_o, s.r_o_error),
            x_end,
            length: l,
        };
        let deformed = super::joint_figs::sibling(path, "deformed");
        super::joint_figs::deformed_plot(&deformed, &d)?;
    }
    if let Some(path) = &args.out.curve {
        let notes = [
            method.clone(),
            "sigma_z = midplane normal stress from the roller reactions, compression negative"
                .to_string(),
            super::output::r_o_note_in(l, s.r_o, s.r_o_error, s.converged),
        ];
        let rows: Vec<Vec<f64>> =
            m.r.iter()
                .zip(&m.sigma_z)
                .map(|(r, z)| vec![*r, *z])
                .collect();
        super::write_output(path, &sigma_curve(args.units, &notes, &rows))?;
    }
    if let Some(path) = &args.out.field {
        let grid = boltzone::scene::field::single_plate_grid(plate.material(), h)?;
        let note = format!(
            "{method}; units {}: coordinates and displacements [{l}], stresses [{st}]; plate 0 = \
             upper half z >= 0 (computed), plate 1 = its mirror image; {}; command: {}",
            args.units.units.name(),
            super::output::r_o_note_in(l, s.r_o, s.r_o_error, s.converged),
            super::output::command_line()
        );
        super::write_output(path, &grid.to_vtu(&note))?;
    }
    Ok(())
}

/// The midplane σ_z curve (r, σ_z) in the one curve layout, headed in the units of `units`.
fn sigma_curve(units: Units, notes: &[String], rows: &[Vec<f64>]) -> String {
    let cols = [
        format!("r [{}]", units.length()),
        format!("sigma_z [{}]", units.stress()),
    ];
    super::output::curve_csv_in(units.units, &[&cols[0], &cols[1]], notes, rows)
}
