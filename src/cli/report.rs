//! `two --report FILE.md` or `FILE.html`: a one-page calculation report of the user's joint —
//! the boltzone version, units and command, the inputs as understood (defaults filled in), the
//! method and its error estimate, the results, the rules of thumb beside R_o with their errors,
//! and the figures. Markdown links the `--plot` files; HTML is self-contained, its figures (the
//! interface pressure, the gap, the deformed joint) inlined as SVG. The report is built once as
//! [`Block`]s and rendered either way. Checked by `tests/io/plot_out.rs` (the Markdown record
//! against the run's JSON, the rules against their closed forms) and `tests/io/figure_joint.rs`
//! (the HTML: the same rows, three inline SVGs, no external reference).
//!
//! # Accuracy
//!
//! No numerics of its own: `tests/io/plot_out.rs`
//! (`calculation_report_records_inputs_results_and_rules`) checks the Markdown against the run's
//! JSON and the cones' closed forms, `tests/io/figure_joint.rs` the HTML.
//!
//! # Cost
//!
//! Milliseconds, after the solve.

use super::figure::rule_radii;
use super::joint_figs::JointFigure;
use boltzone::contact::two_plate::TwoPlateSolution;
use std::fmt::Write;
use std::path::Path;

/// What the report shows besides the solution: the parsed arguments, the joint's A, B, D, D₂,
/// C (None: infinite), the bearing pressure P and the unit system of them all.
pub struct ReportInputs {
    /// The arguments as understood (serialized).
    pub inputs: serde_json::Value,
    /// A, B, D, D₂, C.
    pub geometry: (f64, f64, f64, f64, Option<f64>),
    /// Mean bearing pressure P.
    pub pressure: f64,
    /// Unit system of every input and result (`--units`).
    pub units: super::args::Units,
}

/// What the report says of the answer: R_o with its error bar, the flags, the deflection
/// under the nut and the method paragraph.
pub struct Answer {
    /// R_o, its error estimate and whether it met the tolerance.
    pub r_o: boltzone::Value,
    /// The plates touch out to the rim.
    pub full_contact: bool,
    /// Mean axial displacement under the nut (None: not computed by the route).
    pub nut_deflection: Option<f64>,
    /// How R_o was computed (a paragraph).
    pub method: String,
}

impl Answer {
    /// The finite elements' answer `s` at `tolerance` (`two`; a scene's FE route).
    pub fn fem(s: &TwoPlateSolution, tolerance: f64) -> Self {
        let last = s.info.levels.last();
        Self {
            r_o: boltzone::Value {
                value: s.r_o,
                error: s.r_o_error,
                converged: s.converged,
            },
            full_contact: s.full_contact,
            nut_deflection: Some(s.nut_deflection),
            method: format!(
                "The two-plate model of Gould & Mikic (1970), Chapter II.B: axisymmetric finite \
                 elements, unilateral contact at the interface ({} model). The mesh is refined at \
                 A, B and Rₒ level by level until the error estimate of Rₒ (max(|d₃|, |d₂|/4, \
                 |d₁|/16) of the last level changes, plus the error of cutting a wide plate) \
                 meets the relative tolerance {tolerance}: {} levels, finest mesh {} nodes / {} \
                 unknowns, {:.2} s.",
                s.info.model,
                s.info.levels.len(),
                last.map_or(0, |l| l.nodes),
                last.map_or(0, |l| l.dofs),
                s.info.seconds
            ),
        }
    }
}

/// A piece of a report.
pub enum Block {
    /// A heading of `level` (1 or 2).
    Heading(u8, String),
    /// A paragraph (text; `code` spans marked by backticks).
    Para(String),
    /// A table: header and rows.
    Table(Vec<String>, Vec<Vec<String>>),
    /// A figure: caption, the file of `--plot` (Markdown link) and its SVG text (HTML).
    Figure(String, Option<String>, String),
}

/// The report as [`Block`]s; `figures` are (caption, file, SVG text).
pub fn two_report(
    s: &Answer,
    r: &ReportInputs,
    figures: Vec<(String, Option<String>, String)>,
) -> Vec<Block> {
    let (a, b, d, d2, c) = r.geometry;
    let (l, st, f) = r.units.units.symbols();
    let row = |cells: &[&str]| cells.iter().map(|c| c.to_string()).collect::<Vec<_>>();
    let head = |cells: &[&str]| row(cells);
    let mut v = vec![
        Block::Heading(
            1,
            "Calculation report: bolted joint, two-plate model".into(),
        ),
        Block::Para(format!(
            "boltzone {}; units {} (lengths {l}, stresses {st}, forces {f}).",
            env!("CARGO_PKG_VERSION"),
            r.units.units.name()
        )),
        Block::Para(format!("Command: `{}`", super::output::command_line())),
        Block::Heading(2, "Inputs".into()),
    ];
    let mut inputs = Vec::new();
    if let serde_json::Value::Object(map) = &r.inputs {
        // a force given sets P = F/(π(B² − A²)): the unused default p is not an input
        let has_force = map.get("force").is_some_and(|f| !f.is_null());
        for (k, v) in map
            .iter()
            .filter(|(k, v)| !(v.is_null() || (has_force && k.as_str() == "p")))
        {
            let shown = match v {
                serde_json::Value::String(t) => t.clone(),
                v => v.to_string(),
            };
            inputs.push(row(&[k, &shown, unit_of(k, r.units)]));
        }
    }
    v.push(Block::Table(head(&["input", "value", "unit"]), inputs));
    v.push(Block::Heading(2, "Method".into()));
    v.push(Block::Para(s.method.clone()));
    let yes = |x: bool| if x { "yes" } else { "no" };
    let r_o = s.r_o.value;
    let mut results = vec![row(&[
        "separation radius Rₒ",
        &format!("{r_o:.6} ± {:.1e} {l}", s.r_o.error),
    ])];
    if a > 0.0 {
        results.push(row(&["Rₒ / A", &format!("{:.5}", r_o / a)]));
    }
    results.extend([
        row(&["contact diameter 2Rₒ", &format!("{:.6} {l}", 2.0 * r_o)]),
        row(&["converged to the tolerance", yes(s.r_o.converged)]),
        row(&["full contact (Rₒ = C)", yes(s.full_contact)]),
        row(&[
            "mean bearing pressure P",
            &format!("{:.6e} {st}", r.pressure),
        ]),
    ]);
    if let Some(w) = s.nut_deflection {
        results.push(row(&["deflection under the nut", &format!("{w:.4e} {l}")]));
    }
    v.push(Block::Heading(2, "Results".into()));
    v.push(Block::Table(head(&["quantity", "value"]), results));
    v.push(Block::Heading(2, "Rules of thumb".into()));
    v.push(Block::Para(
        "Contact radius R of each rule and its error against the computed Rₒ.".into(),
    ));
    let rules = rule_radii((b, d, d2, c))
        .into_iter()
        .map(|(name, radius)| {
            row(&[
                name,
                &format!("{radius:.4}"),
                &format!("{:+.1} %", 100.0 * (radius - r_o) / r_o),
            ])
        })
        .collect();
    v.push(Block::Table(
        head(&["rule", &format!("R [{l}]"), "(R − Rₒ)/Rₒ"]),
        rules,
    ));
    if !figures.is_empty() {
        v.push(Block::Heading(2, "Figures".into()));
    }
    v.extend(
        figures
            .into_iter()
            .map(|(t, f, svg)| Block::Figure(t, f, svg)),
    );
    v
}

/// Whether the report at `path` is HTML (extension .html or .htm, any case), else Markdown.
pub fn is_html(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("html") || e.eq_ignore_ascii_case("htm"))
}

/// The report's figures of `figs` (file suffix, caption, figure): (caption, the file `--plot`
/// or `outputs.plot` wrote it to, its SVG text when the report is `html`).
pub fn shown(
    figs: &[(&str, &str, JointFigure)],
    plot: Option<&Path>,
    html: bool,
) -> anyhow::Result<Vec<(String, Option<String>, String)>> {
    figs.iter()
        .map(|(suffix, caption, fig)| {
            let file = plot.map(|p| match *suffix {
                "" => p.display().to_string(),
                _ => super::joint_figs::sibling(p, suffix).display().to_string(),
            });
            let svg = if html { fig.svg()? } else { String::new() };
            Ok((caption.to_string(), file, svg))
        })
        .collect()
}

/// Renders `blocks` as HTML when `path` [`is_html`], else as Markdown.
pub fn render(path: &Path, blocks: &[Block]) -> String {
    match is_html(path) {
        true => html(blocks),
        false => markdown(blocks),
    }
}

/// The blocks as Markdown (figures linked to their files; figures without a file left out).
pub fn markdown(blocks: &[Block]) -> String {
    let mut m = String::new();
    for b in blocks {
        match b {
            Block::Heading(level, t) => {
                let _ = writeln!(m, "{} {t}\n", "#".repeat(usize::from(*level)));
            }
            Block::Para(t) => {
                let _ = writeln!(m, "{t}\n");
            }
            Block::Table(head, rows) => {
                let _ = writeln!(m, "| {} |", head.join(" | "));
                let _ = writeln!(m, "|{}", "---|".repeat(head.len()));
                for r in rows {
                    let _ = writeln!(m, "| {} |", r.join(" | "));
                }
                m.push('\n');
            }
            Block::Figure(caption, Some(file), _) => {
                let _ = writeln!(m, "![{caption}]({file})\n");
            }
            Block::Figure(_, None, _) => {}
        }
    }
    m
}

/// `t` with &, <, > and " escaped for HTML.
fn esc(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The blocks as one self-contained HTML page (figures inlined as SVG, no external file).
pub fn html(blocks: &[Block]) -> String {
    let mut h = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>boltzone calculation report</title>\n<style>\n\
         body { font-family: sans-serif; max-width: 60em; margin: 2em auto; }\n\
         table { border-collapse: collapse; margin: 1em 0; }\n\
         td, th { border: 1px solid #999; padding: 0.2em 0.6em; text-align: left; }\n\
         figure { margin: 1em 0; } svg { max-width: 100%; height: auto; }\n\
         </style>\n</head>\n<body>\n",
    );
    for b in blocks {
        match b {
            Block::Heading(level, t) => {
                let _ = writeln!(h, "<h{level}>{}</h{level}>", esc(t));
            }
            Block::Para(t) => {
                // backtick spans as <code>
                let parts: Vec<String> = esc(t).split('`').map(str::to_string).collect();
                let mut p = String::new();
                for (k, part) in parts.iter().enumerate() {
                    if k % 2 == 1 {
                        let _ = write!(p, "<code>{part}</code>");
                    } else {
                        p += part;
                    }
                }
                let _ = writeln!(h, "<p>{p}</p>");
            }
            Block::Table(head, rows) => {
                h += "<table>\n<tr>";
                for c in head {
                    let _ = write!(h, "<th>{}</th>", esc(c));
                }
                h += "</tr>\n";
                for r in rows {
                    h += "<tr>";
                    for c in r {
                        let _ = write!(h, "<td>{}</td>", esc(c));
                    }
                    h += "</tr>\n";
                }
                h += "</table>\n";
            }
            Block::Figure(caption, _, svg) => {
                let _ = writeln!(
                    h,
                    "<figure>\n{svg}\n<figcaption>{}</figcaption>\n</figure>",
                    esc(caption)
                );
            }
        }
    }
    h + "</body>\n</html>\n"
}

/// The unit of a `two` flag's value in `units` ("" for counts, names, switches and ratios).
fn unit_of(flag: &str, units: super::args::Units) -> &'static str {
    let (l, st, f) = units.units.symbols();
    // a flag of `two`, or the last part of a scene's dotted key
    match flag.rsplit('.').next().unwrap_or(flag) {
        "a" | "b" | "c" | "d" | "d2" | "nut_displacement" | "radius" | "outer_radius"
        | "inner_radius" | "thickness" | "roughness" => l,
        "e" | "e2" | "p" | "pressure" | "E" | "hardness" => st,
        "force" => f,
        _ => "",
    }
}
