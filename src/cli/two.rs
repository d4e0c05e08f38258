//! `boltzone two`: the two-plate model (report Chapter II.B), solved by
//! [`boltzone::contact::two_plate`]: separation radius R_o with its error, and on request the
//! interface pressure p(r), gap g(r) and (welded) shear τ(r) as CSV. `--method hankel` takes the
//! semi-analytic routes (modules `two_hankel`, `two_pair`, `two_rim`); `--method auto` takes them
//! below a tolerance of 3e-5 where they apply, and the finite elements when a route declines the
//! joint (its [`super::exit::Declined`] reason in the text and the JSON's `fallback`; the
//! JSON's `method` says which answered: `tests/hankel/two_plate_hole_handover.rs`).
//!
//! `--units` (in-psi-lbf, mm-MPa-N, m-Pa-N) sets the units of every flag and of the text, the
//! JSON (`units` key), the curve, the VTU, the figures and the report; the solver works in any
//! consistent units. Checked by `tests/scene/joint_units.rs`.
//!
//! # Accuracy
//!
//! No numerics of its own (`boltzone::contact::two_plate`): `tests/contact/cli.rs`
//! (`json_and_curve`, `bad_input_is_reported_not_panicked`).
//!
//! # Cost
//!
//! That of the two-plate solve (`cargo bench --bench contact`).

use super::args::Units;
use super::check;
use super::exit::{usage, Status};
use super::joint_figs::JointFigure;
pub use super::two_args::{Args, Interface};
use super::two_question::{add_rules, joint, pressure, print_rules, question, warn};
use boltzone::contact::two_plate::{
    solve, solve_field, TwoPlateField, TwoPlateParams, TwoPlateSolution,
};
use boltzone::fem::ElementKind;
use boltzone::route::two_plate::HankelSolver;
use boltzone::route::{sanity, two_plate, Method};
use boltzone::Value;

impl Args {
    /// Young's modulus E of the upper plate in the --units stress (--e, or 304 steel's 28e6 psi
    /// converted).
    pub(super) fn e(&self) -> f64 {
        self.e.unwrap_or_else(|| self.units.psi_in(28.0e6))
    }

    /// The parsed arguments as JSON with the default E filled in.
    pub(super) fn inputs(&self) -> anyhow::Result<serde_json::Value> {
        let mut v = serde_json::to_value(self)?;
        v["e"] = self.e().into();
        Ok(v)
    }
}

/// Fills --e, --nu (and --e2, --nu2) from --material (--material2): the library's SI values in
/// the --units stress; an unknown name is bad input naming the flag.
fn apply_materials(args: &mut Args) -> anyhow::Result<()> {
    let stress = args.units.units.stress();
    let lookup = |flag: &str, name: &str| match boltzone::scene::materials::lookup(name) {
        Some(m) => Ok((m.youngs_modulus / stress, m.poisson_ratio)),
        None => usage(
            flag,
            name,
            &format!(
                "not a library material (one of {}; `boltzone materials` lists them)",
                boltzone::scene::materials::names()
            ),
        ),
    };
    if let Some(name) = &args.material {
        let (e, nu) = lookup("--material", name)?;
        (args.e, args.geom.nu) = (Some(e), nu);
    }
    if let Some(name) = &args.material2 {
        let (e, nu) = lookup("--material2", name)?;
        (args.e2, args.nu2) = (Some(e), Some(nu));
    }
    Ok(())
}

/// Checks every flag before any work starts (exit 2 naming the flag).
fn check_args(args: &Args) -> anyhow::Result<()> {
    let g = &args.geom;
    check::annulus(g.a, g.b)?;
    check::positive("--d", "plate thickness D", g.d)?;
    if let Some(d2) = args.d2 {
        check::positive("--d2", "lower plate thickness D2", d2)?;
    }
    if let Some(b2) = args.b2 {
        check::positive("--b2", "nut's bearing-face outer radius B2", b2)?;
        if b2 <= g.a {
            return usage(
                "--b2",
                super::exit::num(b2),
                &format!(
                    "the nut's bearing face B2 = {} must exceed the hole radius A = {}",
                    super::exit::num(b2),
                    super::exit::num(g.a)
                ),
            );
        }
        let d = args.d2.map_or(g.d, |d2| d2.min(g.d));
        if !(1e-3..=check::B_OVER_D_TWO).contains(&(b2 / d)) {
            return usage(
                "--b2",
                super::exit::num(b2),
                &format!(
                    "the nut's bearing face must lie within 1e-3..{} plate thicknesses, as B's \
                     (B2/D = {:.3e})",
                    check::B_OVER_D_TWO,
                    b2 / d
                ),
            );
        }
    }
    if let Some(c) = args.c {
        check::outer_radius("--c", c, g.b)?;
        if let Some(b2) = args.b2 {
            check::outer_radius("--c", c, b2)?;
        }
    }
    check::positive("--e", "Young's modulus E", args.e())?;
    if let Some(e2) = args.e2 {
        check::positive("--e2", "lower plate's Young's modulus E2", e2)?;
    }
    check::poisson("--nu", g.nu, check::NU_MAX_FEM)?;
    if let Some(nu2) = args.nu2 {
        check::poisson("--nu2", nu2, check::NU_MAX_FEM)?;
    }
    check::positive("--p", "bearing pressure P", args.p)?;
    if let Some(f) = args.force {
        check::positive("--force", "bolt force F", f)?;
    }
    if let Some(n) = args.nut_displacement {
        check::positive("--nut-displacement", "nut displacement", n)?;
        let d = args.d2.map_or(args.geom.d, |d2| d2.min(args.geom.d));
        if !(1e-12 * d..=d).contains(&n) {
            return usage(
                "--nut-displacement",
                super::exit::num(n),
                "must lie within 1e-12..1 thicknesses of the thinner plate (smaller leaves the \
                 solver's floating-point range; larger is no small-strain joint)",
            );
        }
    }
    check::tolerance("--tol", args.tol)?;
    match (args.interface, args.mu) {
        (Interface::Friction, Some(mu)) => {
            check::non_negative("--mu", "friction coefficient mu", mu)?;
        }
        (Interface::Friction, None) => {
            return usage(
                "--interface",
                "friction",
                "needs the friction coefficient --mu M",
            );
        }
        (_, Some(mu)) => {
            return usage(
                "--mu",
                mu,
                "a friction coefficient needs --interface friction",
            );
        }
        (_, None) => {}
    }
    check::domain(
        g.a,
        g.b,
        args.d2.map_or(g.d, |d2| d2.min(g.d)),
        check::B_OVER_D_TWO,
    )?;
    if let Some(d2) = args.d2 {
        check::ratio(
            "--d2",
            d2,
            g.d,
            boltzone::route::reach::THICKNESS_RATIO,
            "thickness",
        )?;
    }
    if let Some(e2) = args.e2 {
        check::ratio("--e2", e2, args.e(), 1e6, "Young's modulus")?;
    }
    if args.method == Method::Hankel {
        if let Some((flag, value, why)) = super::two_hankel::unsupported(args) {
            return super::exit::usage(flag, value, &why);
        }
    }
    if args.method == Method::Table {
        if let Some((flag, value, why)) = super::two_hankel::table_unsupported(args) {
            return super::exit::usage(flag, value, &why);
        }
    }
    args.out.check()?;
    if let Some(path) = &args.report {
        check::output_path("--report", path)?;
    }
    Ok(())
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<Status> {
    let start = std::time::Instant::now();
    // the flags' geometry first (--bolt fills A, B), then --material's E and ν into it
    let mut args = super::two_bolt::resolve(args)?;
    apply_materials(&mut args)?;
    let args = args;
    check_args(&args)?;
    let p_given = match args.nut_displacement {
        Some(_) => 0.0,
        None => pressure(&args),
    };
    let e = [args.e(), args.e2.unwrap_or(args.e())];
    warn(&args, &sanity::inputs(args.units.units, e, p_given))?;
    let joint = joint(&args)?;
    args.heat.check(args.units.units, &joint)?;
    let q = question(&args, &joint);
    let p = pressure(&args);
    let load = joint.load().clone();
    let plan = two_plate::plan(&q);
    if plan.is_ok_and(|plan| plan.method == Method::Table) {
        return super::two_table::run(&args, &q, start);
    }
    let hankel = plan.is_ok_and(|plan| plan.method == Method::Hankel);
    // `auto` hands a joint the semi-analytic route declines to the finite elements, saying why
    let mut fallback = None;
    if hankel {
        let ran = match two_plate::hankel_solver(&joint) {
            HankelSolver::Rim(c) => super::two_rim::run(&args, c, load.clone(), start),
            HankelSolver::Pair => super::two_pair::run(&args, load.clone(), start),
            HankelSolver::Holed => super::two_hankel::run(&args, load.clone(), start),
        };
        match ran {
            Err(e) if two_plate::fall_back(args.method, true, true) => {
                let why = e.downcast::<super::exit::Declined>()?.0;
                fallback = Some(format!(
                    "the Hankel route declined ({why}); the finite elements answer"
                ));
            }
            ran => return ran,
        }
    }
    let params = TwoPlateParams {
        element: ElementKind::from(args.element),
        ..q.fem_params()
    };
    let html = args
        .report
        .as_ref()
        .is_some_and(|p| super::report::is_html(p));
    // welded dissimilar plates: the contact problem can be defective (an oscillatory edge
    // singularity); the message says what to use instead
    let welded_dissimilar = matches!(args.interface, Interface::Welded) && !q.equal_plates();
    // (bad input, exit 2 naming --interface: the model asked has no solution here)
    let hint = |e: boltzone::contact::ContactError| -> anyhow::Error {
        match welded_dissimilar {
            true => super::exit::UsageError(format!(
                "--interface = welded: {e}: welded dissimilar plates have an oscillatory edge \
                 singularity and the welded model is ill-posed here; use --interface \
                 frictionless or --interface friction --mu M"
            ))
            .into(),
            false => e.into(),
        }
    };
    // k_P (--stiffness, --bolt): its study's contact solution answers R_o where it can
    let (joint_answer, member) = match super::two_bolt::answer(&args, &q)? {
        Some((a, m)) => (Some(a), m),
        None => (None, None),
    };
    let (s, field) = if args.out.field.is_some() || args.out.plot.is_some() || html {
        let (s, field) = solve_field(&joint, &params).map_err(hint)?;
        (s, Some(field))
    } else {
        match member {
            Some(m) if args.nut_displacement.is_none() && params == q.fem_params() => {
                (m.contact, None)
            }
            _ => (solve(&joint, &params).map_err(hint)?, None),
        }
    };
    if !s.nut_deflection.is_finite() {
        // the solve is scaled (R_o does not depend on P/E); only the deflection, ∝ P·D/E, is
        // out of the floating-point range
        let e = args.e2.unwrap_or(args.e()).min(args.e());
        return usage(
            if args.e2.is_some_and(|e2| e2 < args.e()) {
                "--e2"
            } else {
                "--e"
            },
            super::exit::num(e),
            "the deflection under the nut, of order P·D/E, overflows the floating-point range",
        );
    }
    if let (Some(path), Some(field)) = (&args.out.field, &field) {
        super::write_output(path, &super::two_files::field_vtu(&s, field, args.units)?)?;
    }
    if let Some(path) = &args.out.curve {
        super::write_output(path, &super::two_files::curve_csv(&s, p, args.units))?;
    }
    let html = args
        .report
        .as_ref()
        .is_some_and(|p| super::report::is_html(p));
    let figs = match &field {
        Some(field) if args.out.plot.is_some() || html => {
            let g = &args.geom;
            figures(
                &s,
                field,
                (g.b, g.d, args.d2.unwrap_or(g.d), args.c),
                args.units,
            )
        }
        _ => Vec::new(),
    };
    let file_of = |suffix: &str| {
        args.out.plot.as_ref().map(|p| match suffix {
            "" => p.clone(),
            _ => super::joint_figs::sibling(p, suffix),
        })
    };
    for (suffix, _, fig) in &figs {
        if let Some(path) = file_of(suffix) {
            fig.write(&path)?;
        }
    }
    if let (Some(path), Some(a)) = (&args.out.plot, &joint_answer) {
        super::joint_figs::write_joint_diagram(path, a, args.units.units)?;
    }
    if let Some(path) = &args.report {
        let g = &args.geom;
        let inputs = super::report::ReportInputs {
            inputs: args.inputs()?,
            geometry: (g.a, g.b, g.d, args.d2.unwrap_or(g.d), args.c),
            pressure: p,
            units: args.units,
        };
        let shown = super::report::shown(&figs, args.out.plot.as_deref(), html)?;
        let answer = super::report::Answer::fem(&s, args.tol);
        let blocks = super::report::two_report(&answer, &inputs, shown);
        super::write_output(path, &super::report::render(path, &blocks))?;
    }
    let thinner = args.d2.map_or(args.geom.d, |d2| d2.min(args.geom.d));
    warn(
        &args,
        &sanity::deflection(s.nut_deflection, thinner)
            .into_iter()
            .collect::<Vec<_>>(),
    )?;
    let Some(last) = s.info.levels.last() else {
        anyhow::bail!("the two-plate solver returned no mesh level");
    };
    let conductance = args.heat.conductance(args.units.units, &joint, &s)?;
    let r_o_over_a = (args.geom.a > 0.0).then(|| s.r_o / args.geom.a);
    if args.json {
        let mut out = serde_json::json!({
            "method": "fem",
            "r_o": s.r_o,
            "r_o_error": s.r_o_error,
            "converged": s.converged,
            "full_contact": s.full_contact,
            "overlap": s.overlap,
            "overlapping": s.overlapping,
            "report_rule": s.report_rule,
            "tolerance": args.tol,
            "interface": s.info.model,
            "nodes": last.nodes,
            "dofs": last.dofs,
            "levels": s.info.levels,
            "observed_order": s.info.observed_order,
            "nut_deflection": s.nut_deflection,
            "seconds": s.info.seconds,
            "units": args.units.units.name(),
        });
        if let Some(q) = r_o_over_a {
            out["r_o_over_a"] = q.into();
        }
        if let Some(why) = &fallback {
            out["fallback"] = why.as_str().into();
        }
        if let Some(f) = &s.friction {
            super::friction_out::json(&mut out, &s, f)?;
        }
        out["bearing_pressure"] = p.into();
        super::two_heat::add_json(&mut out, conductance, args.units.units);
        add_rules(&mut out, &args)?;
        if let Some(a) = &joint_answer {
            super::two_bolt::add_json(&mut out, a)?;
        }
        super::output::stamp(&mut out, &args.inputs()?, start)?;
        super::print_json(&out)?;
    } else {
        let l = args.units.length();
        let r_o = Value {
            value: s.r_o,
            error: s.r_o_error,
            converged: s.converged,
        };
        println!(
            "{}",
            super::two_question::r_o_line(&args, r_o, (7, 6), "  NOT converged to --tol (exit 3)")
        );
        println!(
            "interface: {}; {} levels, finest mesh {} nodes / {} unknowns, observed rate {}; {:.3} s",
            s.info.model,
            s.info.levels.len(),
            last.nodes,
            last.dofs,
            s.info.observed_order.map_or("—".into(), |r| format!("{r:.2}")),
            s.info.seconds
        );
        if s.report_rule || s.overlapping {
            println!(
                "WARNING: no sign-consistent contact edge (welded dissimilar plates have an \
                 oscillatory edge singularity){}; the welded model is ill-posed here: use \
                 --interface frictionless or --interface friction --mu M",
                if s.overlapping {
                    format!(", the plates overlap by {:.2e} {l}", s.overlap)
                } else {
                    String::new()
                }
            );
        }
        if s.full_contact {
            println!("full contact: the plates touch out to the rim, R_o = C");
        }
        if let Some(f) = &s.friction {
            println!("{}", super::friction_out::summary(&s, f, l));
        }
        println!("deflection under the nut: {:.4e} {l}", s.nut_deflection);
        if let Some(g) = conductance {
            println!("{}", super::two_heat::line(g, args.units.units));
        }
        print_rules(&args, r_o);
        for line in joint_answer
            .iter()
            .flat_map(|a| super::two_bolt::lines(a, args.units.units))
        {
            println!("{line}");
        }
        if let Some(why) = &fallback {
            println!("method auto: {why}");
        }
    }
    Ok(Status::from_converged(s.converged))
}

/// The figures of `--plot FILE` and the HTML report: the interface pressure (to FILE), the gap
/// (FILE-gap) and the deformed joint (FILE-deformed, [`super::joint_figs`]), each with its
/// caption and file suffix; `geom` is B, D, D₂, C.
fn figures(
    s: &TwoPlateSolution,
    field: &TwoPlateField,
    geom: (f64, f64, f64, Option<f64>),
    units: Units,
) -> Vec<(&'static str, &'static str, JointFigure)> {
    let iface = super::joint_figs::Interface {
        r: &s.radius,
        p: &s.pressure,
        gap: Some(&s.gap),
        r_o: (s.r_o, s.r_o_error),
        model: format!("model: {}", s.info.model),
        source: "finest mesh",
        units: units.units,
    };
    let (mut figs, x_end) = super::joint_figs::interface_figures(&iface, geom);
    let l = units.length();
    let mirror = field.model.lower.is_none();
    let names = if mirror {
        vec!["upper plate".into(), "lower plate (mirror image)".into()]
    } else {
        vec!["lower plate".into(), "upper plate".into()]
    };
    let d = super::joint_figs::Deformed {
        what: "joint",
        mesh: &field.model.mesh,
        u: &field.u,
        mirror,
        names,
        b: geom.0,
        r_o: (s.r_o, s.r_o_error),
        x_end,
        length: l,
    };
    figs.push((
        "deformed",
        "the deformed joint (displacements exaggerated)",
        JointFigure::Section(super::joint_figs::deformed_figure(&d)),
    ));
    figs
}
