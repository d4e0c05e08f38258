//! Arguments shared by the solver commands: the joint's geometry in the report's notation and
//! the element family. Negative numbers are accepted by the parser so that the library's
//! validation can name the field (`--d -1` → "plate thickness D = -1 must be positive").
//!
//! # Accuracy
//!
//! No numerics: bad values are named by their flag, `tests/cli/regressions.rs`
//! (`every_bad_value_is_named_by_its_flag`).
//!
//! # Cost
//!
//! None.

use boltzone::fem::ElementKind;
use std::path::PathBuf;

/// Hole radius A, load radius B, plate thickness D and Poisson's ratio ν (lengths in inches,
/// or the length of the command's `--units`).
#[derive(Debug, Clone, Default, clap::Args, serde::Serialize)]
pub struct Geometry {
    /// Hole radius A, the inner radius of the bearing annulus (in).
    #[arg(long, allow_negative_numbers = true)]
    pub a: f64,
    /// Outer radius B of the bearing annulus (in).
    #[arg(long, allow_negative_numbers = true)]
    pub b: f64,
    /// Thickness D of ONE plate (in); the single-plate substitute is 2D thick.
    #[arg(long, allow_negative_numbers = true)]
    pub d: f64,
    /// Poisson's ratio ν (it moves R_o through the hole, the rim and the second plate; only the
    /// no-hole infinite slab's R_o is independent of it).
    #[arg(long, default_value_t = 0.3, allow_negative_numbers = true)]
    pub nu: f64,
}

/// Finite-element family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Element {
    /// 9-node biquadratic quadrilateral (the default: its error estimates are the reliable ones).
    Q9,
    /// Bilinear quadrilateral (locks for ν near 0.5).
    Q4,
    /// Bilinear quadrilateral with B-bar.
    Q4bbar,
    /// The report's quadrilateral of four constant-strain triangles.
    Cst4,
}

impl From<Element> for ElementKind {
    fn from(e: Element) -> Self {
        match e {
            Element::Q9 => ElementKind::Q9,
            Element::Q4 => ElementKind::Q4,
            Element::Q4bbar => ElementKind::Q4Bbar,
            Element::Cst4 => ElementKind::Cst4,
        }
    }
}

/// Output and accuracy of the table commands.
#[derive(Debug, Clone, clap::Args)]
pub struct TableOutput {
    /// Print one JSON array (ours and the report's per row) instead of the text table.
    #[arg(long)]
    pub json: bool,
    /// Also write the table as CSV to FILE.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Relative tolerance of each R_o (each meets it by its own error estimate; a value that
    /// misses it is flagged NOT converged and the command exits 3).
    #[arg(long, default_value_t = 5e-4, allow_negative_numbers = true)]
    pub tol: f64,
}

impl TableOutput {
    /// Checks --tol and the --csv path before any work starts.
    pub fn check(&self) -> anyhow::Result<()> {
        super::check::tolerance("--tol", self.tol)?;
        if let Some(p) = &self.csv {
            super::check::output_path("--csv", p)?;
        }
        Ok(())
    }
}

/// The files `single` and `two` write besides their printout (each path checked before any
/// work; exit 2 naming the flag).
#[derive(Debug, Clone, clap::Args, serde::Serialize)]
pub struct OutputFiles {
    /// Write the finest mesh's curve to this CSV file (`two`: r, p, g, τ at the interface;
    /// `single`: the midplane σ_z at P = 1 psi): one header row with units, then `#` provenance
    /// lines, then data.
    #[arg(long)]
    pub curve: Option<PathBuf>,
    /// Write the finest mesh's field (mesh, displacements, stresses; a symmetric joint or the
    /// single plate with its mirror image; `two`: the interface pressure, gap and status) to
    /// this VTU file for ParaView.
    #[arg(long)]
    pub field: Option<PathBuf>,
    /// Draw the interface pressure (`two`) or the midplane σ_z (`single`) against r, with B,
    /// R_o and the rules' radii marked, to this SVG or PNG file.
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

impl OutputFiles {
    /// Whether any file is asked.
    pub fn any(&self) -> bool {
        self.curve.is_some() || self.field.is_some() || self.plot.is_some()
    }

    /// Checks every path before any work starts.
    pub fn check(&self) -> anyhow::Result<()> {
        for (flag, path) in [("--curve", &self.curve), ("--field", &self.field)] {
            if let Some(path) = path {
                super::check::output_path(flag, path)?;
            }
        }
        if let Some(path) = &self.plot {
            super::figure::check_plot_path("--plot", path)?;
        }
        Ok(())
    }
}

/// `--units`: the unit system of every length, stress and force given and printed.
#[derive(Debug, Clone, Copy, clap::Args, serde::Serialize)]
pub struct Units {
    /// Unit system of every length, stress and force given and printed: in-psi-lbf (the
    /// report's), mm-MPa-N or m-Pa-N.
    #[arg(long, default_value = "in-psi-lbf", value_parser = clap::builder::ValueParser::new(
        |s: &str| s.parse::<boltzone::scene::UnitSystem>()))]
    pub units: boltzone::scene::UnitSystem,
}

impl Units {
    /// The length symbol (`in`, `mm`, `m`).
    pub fn length(&self) -> &'static str {
        self.units.symbols().0
    }

    /// The stress symbol (`psi`, `MPa`, `Pa`).
    pub fn stress(&self) -> &'static str {
        self.units.symbols().1
    }

    /// A stress of `psi` pounds per square inch in these units (the one conversion,
    /// [`boltzone::scene::UnitSystem::stress`]).
    pub fn psi_in(&self, psi: f64) -> f64 {
        psi * (boltzone::scene::UnitSystem::InPsiLbf.stress() / self.units.stress())
    }
}
