//! The TOML shape of a scene's bolted-joint tables: `[bolt]` (a catalogue bolt), `[washer]` and
//! `[preload]`, as read from the file, in the scene's units. Data only: how they fill the
//! joint and what they answer is [`super::bolt_spec`]'s.
//!
//! ```
//! let keys: boltzone::scene::bolt_keys::BoltKeys = toml::from_str("size = \"M10\"")?;
//! assert_eq!((keys.size.as_str(), keys.shank, keys.load_introduction), ("M10", 0.0, 1.0));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::bolt::catalogue::{HeadKind, HoleSeries, WasherSeries};
use serde::{Deserialize, Serialize};

/// `[bolt]`: a catalogue bolt.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoltKeys {
    /// "M10", "M10x1.25", "1/2-13 UNC" (ISO 262, ASME B1.1).
    pub size: String,
    /// Property class "8.8", "10.9", "12.9" (needed for `[preload] utilisation`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grade: Option<String>,
    /// "hex" (ISO 4014/4017, default) or "socket" (ISO 4762).
    #[serde(default)]
    pub head: HeadKind,
    /// ISO 273 clearance series: "fine", "medium" (default), "coarse".
    #[serde(default)]
    pub hole: HoleSeries,
    /// Unthreaded shank length l_1 inside the grip (length unit; default 0).
    #[serde(default)]
    pub shank: f64,
    /// Bolt and nut modulus E_S (stress unit; default 205 GPa).
    #[serde(rename = "E", default, skip_serializing_if = "Option::is_none")]
    pub e: Option<f64>,
    /// Load-introduction factor n (default 1: under head and nut).
    #[serde(default = "one")]
    pub load_introduction: f64,
}

fn one() -> f64 {
    1.0
}

/// `[washer]`: a plain washer under the head and under the nut.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WasherKeys {
    /// "ISO 7089" (normal) or "ISO 7093" (large).
    pub standard: WasherSeries,
}

/// `[preload]`: exactly one of `force`, `torque` (with `mu_thread` and `mu_head`),
/// `utilisation` (with `mu_thread` and `[bolt] grade`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PreloadKeys {
    /// The preload F_M (force unit).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<f64>,
    /// The tightening torque M_A (force unit · length unit).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub torque: Option<f64>,
    /// The utilisation ν of R_p0.2, in (0, 1].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub utilisation: Option<f64>,
    /// Thread friction μ_G.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu_thread: Option<f64>,
    /// Head friction μ_K.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu_head: Option<f64>,
    /// VDI 2230 material of the plates for the limiting pressure p_G ("S235", …).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limit_material: Option<String>,
}
