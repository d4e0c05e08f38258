//! `boltzone materials`: the built-in material library ([`boltzone::scene::materials`]) that
//! scenes name (`material = "steel-304"`): E and ν in the `--units` stress (SI in `--json`
//! beside it), the mean expansion α (1/K), the conductivity k (W/(m·K)), the Brinell hardness
//! HB (kgf/mm²) and each row's source.
//!
//! # Accuracy
//!
//! No numerics: prints the table; `tests/cli/materials.rs` checks every row against the library
//! and the conversion of E.
//!
//! # Cost
//!
//! None.

use super::args::Units;
use super::exit::sig;
use boltzone::scene::materials::LIBRARY;

/// Arguments of `boltzone materials`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The stress unit E is printed in.
    #[command(flatten)]
    units: Units,
    /// Print JSON: `{"units", "stress_unit", "materials": [{name, youngs_modulus (Pa),
    /// youngs_modulus_in_unit, poisson_ratio, expansion (1/K), conductivity (W/(m·K)),
    /// hardness_hb, source}]}`.
    #[arg(long)]
    json: bool,
}

/// Prints the library.
pub fn run(args: Args) -> anyhow::Result<()> {
    let st = args.units.stress();
    let per_unit = args.units.units.stress();
    if args.json {
        let rows: Vec<serde_json::Value> = LIBRARY
            .iter()
            .map(|m| -> anyhow::Result<serde_json::Value> {
                let mut v = serde_json::to_value(m)?;
                v["youngs_modulus_in_unit"] = (m.youngs_modulus / per_unit).into();
                Ok(v)
            })
            .collect::<anyhow::Result<_>>()?;
        let out = serde_json::json!({
            "units": args.units.units.name(),
            "stress_unit": st,
            "materials": rows,
        });
        return super::print_json(&out);
    }
    println!(
        "{:<20} {:>12} {:>6} {:>12} {:>10} {:>6}  source",
        "name",
        format!("E [{st}]"),
        "nu",
        "alpha [1/K]",
        "k [W/m/K]",
        "HB"
    );
    for m in &LIBRARY {
        println!(
            "{:<20} {:>12} {:>6} {:>12} {:>10} {:>6}  {}",
            m.name,
            sig(m.youngs_modulus / per_unit, 4),
            m.poisson_ratio,
            sig(m.expansion, 3),
            m.conductivity,
            m.hardness_hb,
            m.source
        );
    }
    Ok(())
}
