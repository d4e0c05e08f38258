//! `boltzone map`: the design map of [`boltzone::compare::map`] over A/D × B/A, as CSV and as
//! heat maps (SVG or PNG): R_o/A of both models, the substitution's discrepancy, and the 45° and
//! VDI rules' errors against the two-plate answer; `--method fem|hankel|auto` picks how each
//! model's R_o is computed ([`boltzone::compare::route`]) and the CSV says which method
//! produced each value.
//!
//! # Accuracy
//!
//! No numerics of its own (`boltzone::compare::map`): `tests/compare/cli.rs`
//! (`map_writes_csv_and_figures`, `map_takes_your_own_points`, `bad_arguments_are_named`) and
//! `tests/compare/map_method.rs` (`--method`).
//!
//! # Cost
//!
//! That of the map's points (example 13).

use super::exit::{num, Status};
use super::{check, progress, write_output};
use boltzone::compare::map::{check_reach, compute, log_spaced, DesignMap, MapParams};
use boltzone::compare::{Method, Route};
use boltzone::plot::{write_figure, HeatMapFigure, HeatPanel};
use std::path::PathBuf;

/// Arguments of `boltzone map`.
#[derive(Debug, clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Points per axis (A/D ∈ [0.2, 5], B/A ∈ [1.1, 5], log spaced).
    #[arg(long, default_value_t = 40)]
    n: usize,
    /// Relative tolerance of each R_o.
    #[arg(long, default_value_t = 1e-3)]
    tol: f64,
    /// C/A of the plates (Table 1's: 15.4; inf: infinite plates, which `auto` answers from
    /// the tables where their bar meets --tol).
    #[arg(long, default_value_t = 15.4)]
    c_over_a: f64,
    /// Your own A/D values instead of the log-spaced axis (comma-separated; sorted).
    #[arg(long, value_delimiter = ',', value_name = "LIST")]
    a_over_d: Vec<f64>,
    /// Your own B/A values instead of the log-spaced axis (comma-separated; sorted).
    #[arg(long, value_delimiter = ',', value_name = "LIST")]
    b_over_a: Vec<f64>,
    /// Write the map as CSV to FILE.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Draw the map as SVG to FILE.
    #[arg(long, value_name = "FILE")]
    svg: Option<PathBuf>,
    /// Draw the map as PNG to FILE.
    #[arg(long, value_name = "FILE")]
    png: Option<PathBuf>,
    /// How each model's R_o is computed: fem (finite elements), hankel (the semi-analytic
    /// routes with the rim; refuses a point beyond the two-plate route's reach: B/D > 8,
    /// A/D < 0.04 or C ≤ B + D), table (infinite plates only: --c-over-a inf) or auto (the
    /// route layer's choice per point and model, as `two` and `single --method auto`: the
    /// tables where their bar meets --tol, hankel for the single plate, for two plates only
    /// below --tol 3e-5 and where it applies; fem where hankel does not converge).
    /// The CSV says which method produced each value.
    #[arg(long, value_enum, default_value_t = Method::Fem)]
    method: Method,
}

/// Runs `boltzone map`.
pub fn run(args: Args) -> anyhow::Result<Status> {
    if !(2..=400).contains(&args.n) {
        return super::exit::usage("--n", args.n, "must lie in 2..=400");
    }
    check::tolerance("--tol", args.tol)?;
    if args.c_over_a != f64::INFINITY {
        check::positive("--c-over-a", "C/A", args.c_over_a)?;
    }
    for (flag, field, list) in [
        ("--a-over-d", "A/D", &args.a_over_d),
        ("--b-over-a", "B/A", &args.b_over_a),
    ] {
        for &x in list {
            check::positive(flag, field, x)?;
        }
    }
    for &x in &args.b_over_a {
        if x <= 1.0 + 1e-6 {
            return super::exit::usage(
                "--b-over-a",
                num(x),
                "B/A must exceed 1 + 1e-6 (the bearing face wider than 1e-6·B beyond the hole)",
            );
        }
    }
    // the domain of `two` (check::domain) over the whole map, named by the map's own flags
    for &x in &args.a_over_d {
        if !(1e-3..=1e3).contains(&x) {
            return super::exit::usage("--a-over-d", num(x), "A/D must lie within 1e-3..1e3");
        }
    }
    let widest = |list: &[f64], default: f64| list.iter().copied().fold(default, f64::max);
    let b_over_d = widest(&args.a_over_d, 5.0) * widest(&args.b_over_a, 5.0);
    if b_over_d > check::B_OVER_D_TWO {
        return super::exit::usage(
            "--b-over-a",
            num(widest(&args.b_over_a, 5.0)),
            &format!(
                "the widest point's B/D = (A/D)(B/A) = {b_over_d:e} is beyond the two-plate \
                 model's {:e} plate thicknesses",
                check::B_OVER_D_TWO
            ),
        );
    }
    let b_max = args.b_over_a.iter().copied().fold(5.0, f64::max);
    if args.c_over_a <= b_max {
        return super::exit::usage(
            "--c-over-a",
            args.c_over_a,
            &format!("C/A must exceed the largest B/A of the map ({b_max})"),
        );
    }
    for (flag, p) in [
        ("--csv", &args.csv),
        ("--svg", &args.svg),
        ("--png", &args.png),
    ] {
        if let Some(p) = p {
            check::output_path(flag, p)?;
        }
    }
    for (flag, p) in [("--svg", &args.svg), ("--png", &args.png)] {
        let ext = p
            .as_ref()
            .and_then(|p| p.extension())
            .and_then(|e| e.to_str());
        if let Some(p) = p {
            if !ext.is_some_and(|e| e.eq_ignore_ascii_case(&flag[2..])) {
                return super::exit::usage(
                    flag,
                    p.display(),
                    &format!("the extension must be .{}", &flag[2..]),
                );
            }
        }
    }
    let axis = |own: &[f64], lo: f64, hi: f64| {
        if own.is_empty() {
            log_spaced(lo, hi, args.n)
        } else {
            let mut v = own.to_vec();
            v.sort_by(f64::total_cmp);
            v.dedup();
            v
        }
    };
    if args.method == Method::Table && args.c_over_a.is_finite() {
        return super::exit::usage(
            "--method",
            "table",
            "the map's plates have a rim C (--c-over-a), which the tables do not take; use fem, \
             hankel or auto",
        );
    }
    let params = MapParams {
        a_over_d: axis(&args.a_over_d, 0.2, 5.0),
        b_over_a: axis(&args.b_over_a, 1.1, 5.0),
        c_over_a: args.c_over_a,
        tolerance: args.tol,
        method: args.method,
        ..MapParams::default()
    };
    if let Err(e) = check_reach(&params) {
        return super::exit::usage("--method", args.method.as_str(), &e.to_string());
    }
    let bar = progress(
        (params.a_over_d.len() * params.b_over_a.len()) as u64,
        "map",
    );
    let map = compute(&params, &|| bar.inc(1))?;
    bar.finish_and_clear();
    let (es, et) = map.max_relative_error();
    println!(
        "design map {} x {} (A/D {}..{}, B/A {}..{}, C/A = {}, nu = 0.3): {:.1} s on {} threads",
        map.a_over_d.len(),
        map.b_over_a.len(),
        map.a_over_d[0],
        map.a_over_d[map.a_over_d.len() - 1],
        map.b_over_a[0],
        map.b_over_a[map.b_over_a.len() - 1],
        args.c_over_a,
        map.seconds,
        rayon::current_num_threads()
    );
    println!(
        "largest estimated relative error of R_o: single {es:.1e}, two-plate {et:.1e} (tolerance {:e})",
        args.tol
    );
    let range = |f: &dyn Fn(&boltzone::compare::Comparison) -> f64| {
        map.points
            .iter()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            })
    };
    let (d0, d1) = range(&|c| c.discrepancy_percent.value);
    let (r0, r1) = range(&|c| rule_error(c, 0));
    println!("single-plate discrepancy {d0:.1} .. {d1:.1} %; 45° rule error {r0:.1} .. {r1:.1} %");
    let n = map.points.len();
    let counts = [Route::Table, Route::Hankel, Route::Fem].map(|r| (r, map.count(r)));
    let of = |model: fn((usize, usize)) -> usize| {
        counts
            .iter()
            .map(|(r, c)| format!("{} at {}", r.as_str(), model(*c)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    println!(
        "methods (--method {}): single plate {} of {n} points; two plates {} of {n} points",
        args.method.as_str(),
        of(|c| c.0),
        of(|c| c.1)
    );
    if let Some(p) = &args.csv {
        write_output(p, &map.csv())?;
    }
    for p in [&args.svg, &args.png].into_iter().flatten() {
        write_figure(&figure(&map), p, (1200, 1000))?;
    }
    let converged = map.points.iter().all(|c| c.converged());
    if !converged {
        println!("some values missed --tol (NOT converged): exit 3");
    }
    Ok(Status::from_converged(converged))
}

/// Four heat maps: two-plate R_o/A, single-plate discrepancy, 45° and VDI errors.
fn figure(map: &DesignMap) -> HeatMapFigure {
    let panel = |title: &str, f: &dyn Fn(&boltzone::compare::Comparison) -> f64| HeatPanel {
        title: title.into(),
        z: map.points.iter().map(f).collect(),
    };
    HeatMapFigure {
        x: map.a_over_d.clone(),
        y: map.b_over_a.clone(),
        x_label: "A/D".into(),
        y_label: "B/A".into(),
        panels: vec![
            panel("two-plate R_o/A", &|c| c.over_a(c.two).value),
            panel("single-plate vs two-plate R_o, %", &|c| {
                c.discrepancy_percent.value
            }),
            panel("45° rule vs two-plate R_o, %", &|c| rule_error(c, 0)),
            match map.points.first().and_then(|c| c.rules[1]) {
                Some(_) => panel("VDI 2230 cone vs two-plate R_o, %", &|c| rule_error(c, 1)),
                // infinite plates: VDI's cone angle needs D'_A = 2C
                None => panel(
                    "30° cone vs two-plate R_o, % (VDI 2230 needs a rim)",
                    &|c| rule_error(c, 2),
                ),
            },
        ],
    }
}

/// Rule `k`'s error against the two-plate R_o, % (NaN where it does not apply).
fn rule_error(c: &boltzone::compare::Comparison, k: usize) -> f64 {
    c.rules[k].map_or(f64::NAN, |r| r.error_percent.value)
}
