//! The scene's `[temperature]` table as read ([`TemperatureSpec`]), apart from its checks and
//! its conversion ([`super::temperature`]) so that the scene file ([`super::file`]) holds it
//! without importing the code that reads the file. Public path:
//! `boltzone::scene::temperature::TemperatureSpec`.
//!
//! # Accuracy
//!
//! Types only: `tests/scene/temperature.rs` (`scene_gradient_equals_the_library_call`,
//! `bad_temperature_tables_name_key_and_line`).
//!
//! # Cost
//!
//! Parsing only; the thermal joint is timed by example 20.

use serde::{Deserialize, Serialize};

/// The `[temperature]` table (keys in [`super::temperature`]'s docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TemperatureSpec {
    /// Stress-free temperature.
    pub reference: f64,
    /// Uniform temperature per plate (upper, lower; one entry: both).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plates: Option<Vec<f64>>,
    /// [contact face, loaded face] temperatures per plate, linear between (one entry: both).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient: Option<Vec<[f64; 2]>>,
    /// The temperatures from the joint's heat flow ([`super::from_heat`]; default false).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub from_heat: bool,
    /// With `from_heat`: the upper and the lower loaded face's temperatures.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub faces: Option<[f64; 2]>,
    /// Expansion coefficient α per plate, per degree (one entry: both); empty with `table`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub alpha: Vec<f64>,
    /// Rows (T, E, ν, α) for both plates, read linearly between rows
    /// ([`super::temperature_table`]); E in the scene's stress unit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub table: Option<Vec<[f64; 4]>>,
}
