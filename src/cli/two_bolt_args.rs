//! The bolted-joint flags of `boltzone two` as parsed (clap): the geometry as given (A and B
//! may be left to `--bolt`), the catalogue bolt, its head, hole and washer series, the
//! preload and the stiffness question. Read by [`super::two_args::Args`]; translated into
//! the route layer's terms by [`super::two_bolt`].
//!
//! # Accuracy
//!
//! No numerics: `tests/joint/front_ends.rs` (bad flags are named).
//!
//! # Cost
//!
//! Argument parsing only.

/// A, B, D, ν as given on the line (A and B may be left to `--bolt`).
#[derive(Debug, Clone, clap::Args)]
pub struct GivenGeometry {
    /// Hole radius A, the inner radius of the bearing annulus (in, or the --units length;
    /// omitted with --bolt: half the --hole series' clearance hole).
    #[arg(long, allow_negative_numbers = true)]
    pub a: Option<f64>,
    /// Outer radius B of the bearing annulus (in, or the --units length; omitted with --bolt:
    /// half the head's bearing diameter, or the --washer's outside diameter).
    #[arg(long, allow_negative_numbers = true)]
    pub b: Option<f64>,
    /// Outer radius B2 of the nut's bearing annulus on the lower plate (in, or the --units
    /// length; default: the head's B, or with --bolt and no --b the nut's own bearing diameter
    /// over 2, ISO 4032). It carries the head's force.
    #[arg(long, allow_negative_numbers = true)]
    pub b2: Option<f64>,
    /// Thickness D of ONE plate (in, or the --units length).
    #[arg(long, allow_negative_numbers = true)]
    pub d: f64,
    /// Poisson's ratio ν.
    #[arg(long, default_value_t = 0.3, allow_negative_numbers = true)]
    pub nu: f64,
}

/// Head kinds of `--head`.
#[derive(Debug, Clone, Copy, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum HeadFlag {
    /// Hexagon head, ISO 4014/4017 (d_w,min).
    Hex,
    /// Hexagon socket head cap screw, ISO 4762 (d_k,max).
    Socket,
}

/// Clearance series of `--hole`.
#[derive(Debug, Clone, Copy, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum HoleFlag {
    /// ISO 273 fine.
    Fine,
    /// ISO 273 medium.
    Medium,
    /// ISO 273 coarse.
    Coarse,
}

/// Washer series of `--washer`.
#[derive(Debug, Clone, Copy, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum WasherFlag {
    /// ISO 7089, normal series.
    Iso7089,
    /// ISO 7093, large series.
    Iso7093,
}

/// The bolted-joint flags of `two`.
#[derive(Debug, Clone, clap::Args, serde::Serialize)]
pub struct BoltArgs {
    /// A catalogue bolt: M3 … M36 (ISO 262 coarse), M8x1 … M36x3 (fine), #4-40 … 1-1/2-12
    /// (ASME B1.1 UNC/UNF, e.g. "1/2-13 UNC": thread only, give --a and --b). Implies
    /// --stiffness.
    #[arg(long)]
    pub bolt: Option<String>,
    /// Property class of the bolt: 8.8, 10.9, 12.9 (for --utilisation).
    #[arg(long, requires = "bolt")]
    pub grade: Option<String>,
    /// The bolt's head.
    #[arg(long, value_enum, default_value_t = HeadFlag::Hex)]
    pub head: HeadFlag,
    /// ISO 273 clearance-hole series that fills --a.
    #[arg(long, value_enum, default_value_t = HoleFlag::Medium)]
    pub hole: HoleFlag,
    /// A plain washer under the head and under the nut (its d2 fills --b; rigid, its 2h add to
    /// the clamp length of δ_S).
    #[arg(long, value_enum, requires = "bolt")]
    pub washer: Option<WasherFlag>,
    /// Unthreaded shank length l_1 inside the grip (in, or the --units length).
    #[arg(
        long,
        default_value_t = 0.0,
        requires = "bolt",
        allow_negative_numbers = true
    )]
    pub shank: f64,
    /// Bolt and nut modulus E_S (psi, or the --units stress; default 205 GPa converted).
    #[arg(long, requires = "bolt", allow_negative_numbers = true)]
    pub bolt_e: Option<f64>,
    /// Load-introduction factor n of the load factor Φ = n δ_P/(δ_S + δ_P).
    #[arg(
        long,
        default_value_t = 1.0,
        requires = "bolt",
        allow_negative_numbers = true
    )]
    pub load_introduction: f64,
    /// The preload F_M (lbf, or the --units force): the bolt force.
    #[arg(long, requires = "bolt", conflicts_with_all = ["force", "p", "torque", "utilisation", "nut_displacement"], allow_negative_numbers = true)]
    pub preload: Option<f64>,
    /// The tightening torque M_A (lbf·in, or the --units force·length), with --mu-thread and
    /// --mu-head (VDI 2230 Eq. R13/1).
    #[arg(long, requires_all = ["bolt", "mu_thread", "mu_head"], conflicts_with_all = ["force", "p", "utilisation", "nut_displacement"], allow_negative_numbers = true)]
    pub torque: Option<f64>,
    /// Thread friction μ_G (with --torque or --utilisation).
    #[arg(long, allow_negative_numbers = true)]
    pub mu_thread: Option<f64>,
    /// Head friction μ_K (with --torque).
    #[arg(long, requires = "torque", allow_negative_numbers = true)]
    pub mu_head: Option<f64>,
    /// The utilisation ν of R_p0.2 (0 < ν ≤ 1), with --mu-thread and --grade (VDI 2230 R7/1).
    #[arg(long, requires_all = ["bolt", "mu_thread", "grade"], conflicts_with_all = ["force", "p", "nut_displacement"], allow_negative_numbers = true)]
    pub utilisation: Option<f64>,
    /// VDI 2230 material of the plates whose limiting pressure p_G the bearing pressures are
    /// set against (S235, S355, C45, 42CrMo4, 34CrNiMo6, X5CrNi18-10, EN-GJL-250, EN-GJS-400,
    /// AlMgSi1-F31, AlZnMgCu1.5).
    #[arg(long, requires = "bolt")]
    pub limit_material: Option<String>,
    /// Compute the member stiffness k_P and compliance δ_P (two-plate finite elements) with
    /// the rules beside it (VDI 2230, Shigley, Wileman, Cornwell).
    #[arg(long)]
    pub stiffness: bool,
}
