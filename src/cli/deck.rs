//! `boltzone deck`: run the 1970 programs' card decks (Appendices B and C) on boltzone's finite
//! elements and print what the old program printed ([`boltzone::io::deck`]); `--emit` writes a
//! single plate of the library as an Appendix B deck. Bad decks exit 2 with the line, columns and
//! field at fault.
//!
//! # Accuracy
//!
//! No numerics of its own (those of `boltzone::io::deck` and `boltzone::heat::deck`):
//! `tests/io/cli.rs` (`json_contract_and_emit_round_trip`,
//! `bad_decks_and_flags_exit_2_naming_line_and_field`,
//! `appendix_d_decks_run_through_the_deck_command`).
//!
//! # Cost
//!
//! That of the decks it runs.

use anyhow::Context;
use boltzone::fem::Spacing;
use boltzone::heat::deck::parse_network_decks;
use boltzone::io::deck::{
    json_deck, plate_on_plane_deck, read_decks_as, report, run as run_deck, write_deck, Appendix,
};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use std::path::PathBuf;

use super::exit::Status;

/// Which appendix's format the file is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
pub enum Format {
    /// Appendix B: elastic.
    B,
    /// Appendix C: elastic with thermal strains.
    C,
    /// Appendix D: the conductance network.
    D,
}

/// Arguments of `boltzone deck`.
#[derive(Debug, clap::Args, serde::Serialize)]
pub struct Args {
    /// The deck file (one or more decks separated by a card starting `*****`).
    #[arg(required_unless_present = "emit")]
    file: Option<PathBuf>,
    /// The format; when not given each deck is read as the appendix its cards fit (B or C, else
    /// D).
    #[arg(long, value_enum)]
    appendix: Option<Format>,
    /// Print {"decks": [...]} as JSON instead of the 1970 printout.
    #[arg(long)]
    json: bool,
    /// Write the upper half of a single plate (hole radius A, load to B, half-thickness D, rim C)
    /// under a uniform pressure P as an Appendix B deck to this file, instead of running one.
    #[arg(long)]
    emit: Option<PathBuf>,
    /// Hole radius A (in), with --emit.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    a: f64,
    /// Outer radius B of the loaded annulus (in), with --emit.
    #[arg(long, default_value_t = 0.31, allow_negative_numbers = true)]
    b: f64,
    /// Outer radius C of the plate (in), with --emit.
    #[arg(long, default_value_t = 1.54, allow_negative_numbers = true)]
    c: f64,
    /// Half-thickness D (in) of the single plate (the thickness of one plate of the joint), with --emit.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    d: f64,
    /// Young's modulus E (psi), with --emit.
    #[arg(long, default_value_t = 28.0e6, allow_negative_numbers = true)]
    e: f64,
    /// Poisson's ratio, with --emit.
    #[arg(long, default_value_t = 0.3, allow_negative_numbers = true)]
    nu: f64,
    /// Face pressure P (psi), with --emit.
    #[arg(long, default_value_t = 1000.0, allow_negative_numbers = true)]
    p: f64,
    /// Contact radius (in), with --emit: the bottom is held (code 2) only for r ≤ this — one
    /// plate of an equal pair on its frictionless interface, in contact out to it (as the 1970
    /// program ran the two-plate model: one trial contact zone per deck). Default: everywhere
    /// (the single-plate substitute's midplane).
    #[arg(long, allow_negative_numbers = true)]
    contact: Option<f64>,
    /// Element size (in), with --emit; default D/4. Nodes fall on A, B, C (and the contact radius).
    #[arg(long, allow_negative_numbers = true)]
    h: Option<f64>,
}

/// Runs the command.
pub fn run(args: Args) -> anyhow::Result<Status> {
    let start = std::time::Instant::now();
    if let Some(out) = &args.emit {
        return emit(&args, out).map(|()| Status::Converged);
    }
    let appendix = match args.appendix {
        Some(Format::D) => None,
        Some(Format::B) => Some(Appendix::B),
        Some(Format::C) => Some(Appendix::C),
        None => None,
    };
    let Some(path) = args.file.as_ref() else {
        return super::exit::usage("FILE", "(none)", "a deck file is required");
    };
    let text = match std::fs::read_to_string(path) {
        Ok(text) => text,
        Err(e) => {
            return super::exit::usage(
                "FILE",
                path.display(),
                &format!("cannot read the deck: {e}"),
            )
        }
    };
    if args.appendix == Some(Format::D) {
        return network_decks(&text, path, &args, start);
    }
    let decks = match read_decks_as(&text, appendix) {
        Ok(decks) => decks,
        // not B or C: a conductance network (Appendix D) when it reads as one
        Err(e) if args.appendix.is_none() && parse_network_decks(&text).is_ok() => {
            let _ = e;
            return network_decks(&text, path, &args, start);
        }
        Err(e) => return Err(e).with_context(|| format!("{}", path.display())),
    };
    let mut out = Vec::with_capacity(decks.len());
    for deck in &decks {
        let sol = run_deck(deck).with_context(|| format!("{}", path.display()))?;
        out.push((deck, sol));
    }
    if args.json {
        let list: Vec<_> = out.iter().map(|(d, s)| json_deck(d, s)).collect();
        let mut v = serde_json::json!({ "decks": list });
        super::output::stamp(&mut v, &args, start)?;
        println!("{v}");
    } else {
        for (d, s) in &out {
            print!("{}", report(d, s));
        }
        println!(
            "\n END OF JOB ({} deck{})",
            out.len(),
            if out.len() == 1 { "" } else { "s" }
        );
    }
    Ok(Status::Converged)
}

/// Solves Appendix D conductance-network decks ([`boltzone::heat::deck`]) and prints the
/// program's output or `{"decks": [{"title", "nodes": [{"n", "t", …}], "residual"}]}`.
fn network_decks(
    text: &str,
    path: &std::path::Path,
    args: &Args,
    start: std::time::Instant,
) -> anyhow::Result<Status> {
    let decks = parse_network_decks(text).with_context(|| format!("{}", path.display()))?;
    let mut solved = Vec::with_capacity(decks.len());
    for deck in &decks {
        let s = deck.solve().with_context(|| {
            format!(
                "{}: the deck starting on line {}",
                path.display(),
                deck.line
            )
        })?;
        solved.push(s);
    }
    if args.json {
        let mut v = serde_json::json!({ "decks": solved });
        super::output::stamp(&mut v, args, start)?;
        super::print_json(&v)?;
    } else {
        for s in &solved {
            print!("{s}");
        }
    }
    Ok(Status::Converged)
}

/// Points from `x0` to `x1` at a spacing near `h` (at least one element).
fn line(x0: f64, x1: f64, h: f64) -> anyhow::Result<Vec<f64>> {
    let n = ((x1 - x0) / h).ceil().max(1.0);
    if n.is_nan() || n > 1e5 {
        anyhow::bail!("element size h = {h} in gives too many elements for a deck");
    }
    Ok(Spacing::uniform(x0, x1, n as usize)?.points().to_vec())
}

fn emit(args: &Args, out: &std::path::Path) -> anyhow::Result<()> {
    super::check::output_path("--emit", out)?;
    let load = FaceLoad::uniform(args.a, args.b, args.p)?;
    let plate = SinglePlate::new(
        args.a,
        OuterRadius::Finite(args.c),
        args.d,
        Material::new(args.e, args.nu)?,
        load,
    )?;
    let h = args.h.unwrap_or(args.d / 4.0);
    if !(h > 0.0 && h.is_finite()) {
        anyhow::bail!("element size --h = {h} in must be positive");
    }
    let mut r = line(args.a, args.b, h)?;
    let mut knots = vec![args.b, args.c];
    if let Some(rc) = args.contact {
        if !(rc > args.b && rc < args.c) {
            anyhow::bail!(
                "--contact {rc} in must lie between B = {} and C = {} in",
                args.b,
                args.c
            );
        }
        knots.insert(1, rc);
    }
    for w in knots.windows(2) {
        r.extend_from_slice(&line(w[0], w[1], h)?[1..]);
    }
    let radial = Spacing::from_points(r)?;
    let axial = Spacing::from_points(line(0.0, args.d, h)?)?;
    let title = match args.contact {
        None => format!(
            "SINGLE PLATE A={} B={} C={} D={} IN, P={} PSI (BOLTZONE)",
            args.a, args.b, args.c, args.d, args.p
        ),
        Some(rc) => format!(
            "PAIR PLATE A={} B={} C={} D={} P={} CONTACT R={} (IN, PSI)",
            args.a, args.b, args.c, args.d, args.p, rc
        ),
    };
    let deck = plate_on_plane_deck(&plate, &radial, &axial, &title, args.contact)?;
    let text = write_deck(&deck)?;
    boltzone::plot::write_atomic(out, text.as_bytes())?;
    eprintln!(
        "wrote {} ({} nodes, {} elements, {} pressure cards; lengths in in, stresses in psi)",
        out.display(),
        deck.nodes.len(),
        deck.elements.len(),
        deck.pressures.len()
    );
    Ok(())
}
