//! The fastener catalogue a bolted-joint calculation reads its diameters from, as the standards
//! tabulate them (files in `reference/bolts/`, each with its provenance header):
//!
//! - clearance holes d_h of ISO 273, fine / medium / coarse series, M3–M36
//!   (`iso273_clearance.csv`);
//! - the bearing diameters: hexagon heads ISO 4014/4017 d_w,min (product grade A to M24, B
//!   beyond), hexagon nuts ISO 4032 d_w,min, socket heads ISO 4762 d_k,max
//!   (`bearing_diameters.csv`);
//! - plain washers ISO 7089 (normal) and ISO 7093-1 (large): d1, d2, h (`washers.csv`);
//! - VDI 2230's limiting surface pressure p_G of common plate materials
//!   (`vdi2230_limiting_pressure.csv`).
//!
//! A fine-pitch size ("M10x1.25") takes its nominal diameter's row. Units: mm, MPa.
//!
//! # Accuracy
//!
//! Table values, not computed: `tests/joint/catalogue.rs` checks the tables against identities
//! (d < d_h,fine < d_h,medium < d_h,coarse; d_w < s; ISO 7089's d1 equals ISO 273's fine
//! series; the washer covers the head's bearing face).
//!
//! # Cost
//!
//! A scan of a table of a few dozen rows.
//!
//! ```
//! use boltzone::bolt::catalogue::{clearance_hole, head_bearing_diameter, HeadKind, HoleSeries};
//! assert_eq!(clearance_hole("M10", HoleSeries::Medium)?, 11.0);
//! assert_eq!(head_bearing_diameter("M10x1.25", HeadKind::Hex)?, 14.63);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub use super::table::NotInCatalogue;
use super::table::{cell, rows};

const CLEARANCE: &str = include_str!("../../reference/bolts/iso273_clearance.csv");
const BEARING: &str = include_str!("../../reference/bolts/bearing_diameters.csv");
const WASHERS: &str = include_str!("../../reference/bolts/washers.csv");
const LIMITING: &str = include_str!("../../reference/bolts/vdi2230_limiting_pressure.csv");

/// ISO 273's clearance-hole series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HoleSeries {
    /// Fine.
    Fine,
    /// Medium (the default).
    #[default]
    Medium,
    /// Coarse.
    Coarse,
}

/// The head's kind, which fixes its bearing diameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HeadKind {
    /// Hexagon head, ISO 4014/4017 (d_w,min; the default).
    #[default]
    Hex,
    /// Hexagon socket head cap screw, ISO 4762 (d_k,max).
    Socket,
}

/// A plain washer's series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum WasherSeries {
    /// ISO 7089, normal series.
    #[serde(rename = "ISO 7089")]
    Iso7089,
    /// ISO 7093-1, large series.
    #[serde(rename = "ISO 7093")]
    Iso7093,
}

impl WasherSeries {
    /// The standard's name as the table writes it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Iso7089 => "ISO 7089",
            Self::Iso7093 => "ISO 7093",
        }
    }
}

/// A plain washer (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Washer {
    /// Bore d1.
    pub d1: f64,
    /// Outside diameter d2.
    pub d2: f64,
    /// Thickness h.
    pub h: f64,
}

/// The nominal size of a thread name: "M10x1.25" → "M10".
fn nominal(size: &str) -> String {
    let s = size.trim().replace('×', "x");
    match s.split_once(['x', 'X']) {
        Some((n, _)) => n.to_string(),
        None => s,
    }
}

/// The row of `table` whose first cell is `size`'s nominal size (and whose column `extra.0`
/// equals `extra.1`, if given).
fn row<'a>(
    table: &'a str,
    what: &str,
    size: &str,
    extra: Option<(usize, &str)>,
) -> Result<Vec<&'a str>, NotInCatalogue> {
    named(table, what, &nominal(size), extra).map_err(|e| NotInCatalogue {
        name: size.into(),
        ..e
    })
}

/// The row of `table` whose first cell is `key` (and whose column `extra.0` equals `extra.1`).
fn named<'a>(
    table: &'a str,
    what: &str,
    key: &str,
    extra: Option<(usize, &str)>,
) -> Result<Vec<&'a str>, NotInCatalogue> {
    let keep = |f: &Vec<&str>| extra.is_none_or(|(i, v)| f.get(i) == Some(&v));
    rows(table)
        .find(|f| f[0].eq_ignore_ascii_case(key) && keep(f))
        .ok_or_else(|| {
            let known: Vec<String> = rows(table).filter(keep).map(|f| f[0].to_string()).collect();
            NotInCatalogue::new(what, key, &known.join(", "))
        })
}

/// ISO 273's clearance hole d_h (mm) of a metric `size` in `series`.
pub fn clearance_hole(size: &str, series: HoleSeries) -> Result<f64, NotInCatalogue> {
    let f = row(CLEARANCE, "ISO 273 clearance hole", size, None)?;
    let col = match series {
        HoleSeries::Fine => 2,
        HoleSeries::Medium => 3,
        HoleSeries::Coarse => 4,
    };
    Ok(cell(f[col]))
}

/// The head's bearing diameter (mm): ISO 4014/4017 d_w,min or ISO 4762 d_k,max.
pub fn head_bearing_diameter(size: &str, head: HeadKind) -> Result<f64, NotInCatalogue> {
    let f = row(BEARING, "head size (ISO 4014/4017/4762)", size, None)?;
    Ok(cell(match head {
        HeadKind::Hex => f[2],
        HeadKind::Socket => f[5],
    }))
}

/// The hexagon nut's bearing diameter d_w,min (mm), ISO 4032.
pub fn nut_bearing_diameter(size: &str) -> Result<f64, NotInCatalogue> {
    Ok(cell(row(BEARING, "nut size (ISO 4032)", size, None)?[4]))
}

/// The width across flats s (mm) of the hexagon head and nut.
pub fn across_flats(size: &str) -> Result<f64, NotInCatalogue> {
    Ok(cell(row(BEARING, "hexagon size", size, None)?[1]))
}

/// The plain washer of `size` in `series`.
pub fn washer(size: &str, series: WasherSeries) -> Result<Washer, NotInCatalogue> {
    let what = format!("{} washer", series.name());
    let f = row(WASHERS, &what, size, Some((1, series.name())))?;
    Ok(Washer {
        d1: cell(f[2]),
        d2: cell(f[3]),
        h: cell(f[4]),
    })
}

/// VDI 2230's limiting surface pressure p_G (MPa) of a plate material named as the table
/// names it ("S235", "42CrMo4", "EN-GJL-250", …).
pub fn limiting_pressure(material: &str) -> Result<f64, NotInCatalogue> {
    let f = named(LIMITING, "VDI 2230 plate material", material.trim(), None)?;
    Ok(cell(f[1]))
}

/// Every size of the bearing-diameter table (for sweeps over the catalogue).
pub fn sizes() -> Vec<&'static str> {
    rows(BEARING).map(|f| f[0]).collect()
}
