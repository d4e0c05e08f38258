//! `boltzone figures [--out DIR] [--only 12,15,slab] [--tol T] [--units U]`: the report's Figs.
//! 12–29 and the classic slab curves ([`boltzone::figures`]), each as `DIR/ID.svg` and `DIR/ID.png`
//! (drawn by [`boltzone::figures::draw`]), its curves as `DIR/ID.csv` and its points (the
//! report's values, measurements) as `DIR/ID_points.csv` in the one CSV layout
//! ([`super::output`]), a manifest `DIR/figures.json` (ids, captions, every curve's R_o with
//! its error, the points) and a gallery `DIR/index.html`. The directory is created and checked
//! before any work starts; every file is written whole or not at all. Exit 3 when some R_o
//! missed `--tol`. `--units in-psi-lbf|mm-MPa-N|m-Pa-N` (default the report's) sets the units of
//! the axes, the CSV files and the manifest ([`boltzone::figures::units`]); each figure's
//! `report_values` (manifest, CSV comment) says what the report prints for it, or that it
//! prints nothing.
//!
//! # Accuracy
//!
//! That of [`boltzone::figures`]; `tests/figures/gallery.rs` checks the files, manifest and gallery
//! (`files_and_gallery_are_complete`) and the exit codes (`bad_flags_exit_2`).
//!
//! # Cost
//!
//! The figures' solves; `boltzone figures` prints each figure's time; the whole set is timed by the
//! ignored test `every_curve_separates_at_its_r_o` (tests/figures/gallery.rs, which runs the whole
//! set once, about 6 s).

use super::exit::{usage, Status};
use boltzone::figures::{self, draw, FigureData, FiguresParams};
use boltzone::plot::{typeset, write_figure};
use boltzone::scene::UnitSystem;
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Arguments of `boltzone figures`.
#[derive(Debug, clap::Args, serde::Serialize)]
pub struct Args {
    /// Directory of the figures (created if missing).
    #[arg(long, default_value = "figures")]
    out: PathBuf,
    /// Only these figures: numbers 12–29 or `slab`, comma-separated (default: all).
    #[arg(long, value_delimiter = ',')]
    only: Vec<String>,
    /// Wanted relative error of every R_o (the default draws the whole set in seconds).
    #[arg(long, default_value_t = FiguresParams::default().tolerance)]
    tol: f64,
    /// Units of the axes, the CSV files and the manifest (default the report's).
    #[command(flatten)]
    #[serde(flatten)]
    units: super::args::Units,
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<Status> {
    super::check::tolerance("--tol", args.tol)?;
    let ids: Vec<&'static str> = if args.only.is_empty() {
        figures::IDS.to_vec()
    } else {
        args.only
            .iter()
            .map(|k| match figures::resolve(k) {
                Some(id) => Ok(id),
                None => usage(
                    "--only",
                    k,
                    &format!(
                        "is not a figure (12–29 or slab; known: {})",
                        figures::IDS.join(", ")
                    ),
                ),
            })
            .collect::<anyhow::Result<_>>()?
    };
    if args.out.exists() && !args.out.is_dir() {
        return usage("--out", args.out.display(), "exists and is not a directory");
    }
    if let Err(e) = std::fs::create_dir_all(&args.out) {
        return usage(
            "--out",
            args.out.display(),
            &format!("cannot create the directory: {e}"),
        );
    }
    super::check::output_path("--out", &args.out.join("index.html"))?;
    let params = FiguresParams {
        tolerance: args.tol,
    };
    let figs = ids
        .par_iter()
        .map(|id| figures::compute(id, &params))
        .map(|f| f.map(|f| figures::units::in_units(&f, args.units.units)))
        .collect::<Result<Vec<_>, _>>()?;
    for fig in &figs {
        write_one(&args.out, fig, args.units.units)?;
        println!(
            "{:<6} {:>6.2} s  {} curve(s), {} point series{}  {}",
            fig.id,
            fig.seconds,
            fig.curves.len(),
            fig.points.len(),
            if fig.converged() {
                ""
            } else {
                "  NOT converged to --tol"
            },
            fig.title
        );
    }
    let manifest = serde_json::json!({
        "version": env!("CARGO_PKG_VERSION"),
        "command": super::output::command_line(),
        "units": args.units.units.name(),
        "tolerance": args.tol,
        "figures": figs.iter().map(summary).collect::<Vec<_>>(),
    });
    super::write_output(
        &args.out.join("figures.json"),
        &serde_json::to_string_pretty(&manifest)?,
    )?;
    super::write_output(
        &args.out.join("index.html"),
        &gallery(&figs, args.units.units),
    )?;
    Ok(Status::from_converged(
        figs.iter().all(FigureData::converged),
    ))
}

/// A figure's entry of `figures.json`: everything but the curves' points.
fn summary(fig: &FigureData) -> serde_json::Value {
    let curves: Vec<_> = fig
        .curves
        .iter()
        .enumerate()
        .map(|(k, c)| {
            serde_json::json!({"curve": k, "label": c.label, "kind": c.kind, "b": c.b, "r_o": c.r_o})
        })
        .collect();
    serde_json::json!({
        "id": fig.id, "title": fig.title, "note": fig.note, "seconds": fig.seconds,
        "converged": fig.converged(), "x_label": fig.x_label, "y_label": fig.y_label,
        "report_values": fig.report_values,
        "curves": curves, "points": fig.points,
    })
}

/// A column name for the CSV header: the axis label up to its parenthesis, in ASCII.
fn column(label: &str) -> String {
    let name = label.split(" (").next().unwrap_or(label);
    name.replace("σz", "sigma_z")
        .replace('µ', "u")
        .replace(',', ";")
}

/// Writes the SVG, the PNG and the CSVs of `fig` into `dir`.
fn write_one(dir: &Path, fig: &FigureData, units: UnitSystem) -> anyhow::Result<()> {
    for ext in ["svg", "png"] {
        write_figure(fig, &dir.join(format!("{}.{ext}", fig.id)), draw::SIZE)?;
    }
    let (x, y) = (column(&fig.x_label), column(&fig.y_label));
    let mut notes = vec![
        format!("{}: {}", fig.id, fig.title),
        fig.note.clone(),
        format!("report values: {}", fig.report_values),
    ];
    let mut rows = Vec::new();
    for (k, c) in fig.curves.iter().enumerate() {
        let r_o = c.r_o.map_or("no R_o".into(), |v| {
            super::output::r_o_note_in(units.symbols().0, v.value, v.error, v.converged)
        });
        notes.push(format!(
            "curve {k}: {}; kind {:?}; B = {} {}; {r_o}",
            c.label,
            c.kind,
            c.b,
            units.symbols().0
        ));
        rows.extend(c.x.iter().zip(&c.y).map(|(x, y)| vec![*x, *y, k as f64]));
    }
    let csv = super::output::curve_csv_in(units, &[&x, &y, "curve"], &notes, &rows);
    boltzone::plot::write_atomic(&dir.join(format!("{}.csv", fig.id)), csv.as_bytes())?;
    if !fig.points.is_empty() {
        let mut notes = vec![format!(
            "{}: points (x, y) with bars x_lo..x_hi, y_lo..y_hi; series:",
            fig.id
        )];
        let mut rows = Vec::new();
        for (k, s) in fig.points.iter().enumerate() {
            notes.push(format!("series {k}: {} ({:?})", s.label, s.source));
            rows.extend(s.points.iter().map(|p| {
                vec![
                    p.x, p.y, p.x_bar.0, p.x_bar.1, p.y_bar.0, p.y_bar.1, k as f64,
                ]
            }));
        }
        let cols = [
            x.as_str(),
            y.as_str(),
            "x_lo",
            "x_hi",
            "y_lo",
            "y_hi",
            "series",
        ];
        let csv = super::output::curve_csv_in(units, &cols, &notes, &rows);
        boltzone::plot::write_atomic(&dir.join(format!("{}_points.csv", fig.id)), csv.as_bytes())?;
    }
    Ok(())
}

/// Text with the five HTML specials escaped.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&#39;")
}

/// The gallery page: every figure with its caption, note, computed R_o and files.
fn gallery(figs: &[FigureData], units: UnitSystem) -> String {
    let (l, s, _) = units.symbols();
    let mut h = format!(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>boltzone: the figures of Gould &amp; Mikic (1970), recomputed</title>\
         <style>body{{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em}}\
         figure{{margin:2em 0;border-top:1px solid #ccc;padding-top:1em}}\
         img{{width:100%;height:auto}}figcaption{{font-size:0.95em}}</style></head><body>\n\
         <h1>The figures of Gould &amp; Mikic (1970), recomputed</h1>\n<p>Each figure's drawing \
         was lost from the report's text; its caption survives. The curves are computed by \
         boltzone from the captions' cases; triangles mark the report's printed values, open \
         circles the measurements of Table 2 (bars: min–max). Lengths in {l}, stresses in {s} \
         ({}), compression negative for σ<sub>z</sub>.</p>\n",
        units.name()
    );
    for f in figs {
        let _ = write!(
            h,
            "<figure id=\"{id}\"><img src=\"{id}.svg\" alt=\"{t}\"><figcaption><b>{t}</b><br>{n}\
             <br><i>The report's values:</i> {r}<ul>",
            id = f.id,
            t = esc(&typeset(&f.title)),
            n = esc(&typeset(&f.note)),
            r = esc(&typeset(&f.report_values))
        );
        for c in &f.curves {
            let _ = write!(h, "<li>{}</li>", esc(&typeset(&c.label)));
        }
        let _ = writeln!(
            h,
            "</ul>Files: <a href=\"{id}.svg\">SVG</a>, <a href=\"{id}.png\">PNG</a>, \
             <a href=\"{id}.csv\">curves (CSV)</a>{p}; computed in {s:.2} s.</figcaption></figure>",
            id = f.id,
            p = if f.points.is_empty() {
                String::new()
            } else {
                format!(", <a href=\"{}_points.csv\">points (CSV)</a>", f.id)
            },
            s = f.seconds
        );
    }
    h + "</body></html>\n"
}
