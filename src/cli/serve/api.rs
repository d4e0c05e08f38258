//! `GET /api/joint?a=…&b=…&d=…[&c=…&nu=…&d2=…&units=…]` (a contract): one joint, answered as
//! `{"two": {"r_o", "r_o_error", "converged", …}, "single": {…}, "rules": […], "curves": {…},
//! "units", "unit_symbols"}`.
//!
//! `two` is what `boltzone two --a A --b B --d D [--c C] [--nu ν] [--d2 D2] [--units U] --json`
//! prints for the same joint (304 steel E = 28e6 psi converted to the units' stress, P = 1 in
//! the units' stress, frictionless interface, Q9 elements, tolerance 5e-4: the command's
//! defaults, `--method fem`): the route layer's question of the page (its curves drawn:
//! [`boltzone::route::two_plate::plan`] gives the finite elements) solved by
//! [`boltzone::contact::two_plate::solve`]; `method` says which route answered. `single` is
//! Fernlund's single plate 2D thick (D of the upper plate) by [`boltzone::fem::single`] at the
//! same tolerance; `rules` the 45°, VDI 2230 (finite plates) and 30° cones' contact radii with
//! their error against the two-plate R_o (percent, with the error bar the R_o's error gives);
//! `curves` the two-plate interface pressure `{"r", "p"}` and the single plate's midplane σ_z
//! `{"r", "sigma_z"}` (P = 1, compression negative), both out to 1.6 times the largest radius
//! of interest. `units` (`in-psi-lbf`, the default, `mm-MPa-N` or `m-Pa-N`) sets the length of
//! a, b, d, c, d2 and of every length answered, and the stress of E, P and the curves; the
//! answer names them (`units`, `unit_symbols: {length, stress, force}`). Query errors name the
//! parameter and its value (HTTP 400).
//!
//! [`opening`] is the page's opening joint (its sliders' defaults), answered once by the
//! server at start-up and embedded in the page.
//!
//! # Accuracy
//!
//! `tests/figures/server.rs`: `api_gives_the_cli_numbers` (the answer against `boltzone two --json`
//! and `boltzone single --json` for the same joint), `api_in_mm_is_two_in_mm_bit_for_bit` and
//! `bad_queries_get_400_naming_the_field_and_the_server_survives`.
//!
//! # Cost
//!
//! One two-plate solve and one single-plate study per new joint (`cargo bench --bench contact`,
//! `cargo bench --bench fem`); under load: `tests/figures/load.rs`
//! (`api_load_2000_requests_8_concurrent`, ignored).

use crate::cli::args::Units;
use crate::cli::check;
use crate::cli::exit::usage;
use boltzone::contact::two_plate::solve;
use boltzone::fem::single::{midplane_of, solve_with_field, SingleParams};
use boltzone::route::{rules_beside, single_plate, two_plate, Method};
use boltzone::scene::UnitSystem;
use boltzone::units::as_entered;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate, SinglePlate, Value};
use serde_json::json;

/// The tolerance of `two`'s default, shared by both models here.
pub const TOLERANCE: f64 = 5e-4;
/// Young's modulus of `two`'s default (psi; converted to the query's units).
const E_PSI: f64 = 28.0e6;

/// A joint asked for (lengths in the length of `units`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointQuery {
    /// Hole radius A.
    pub a: f64,
    /// Bearing radius B.
    pub b: f64,
    /// Upper plate thickness D.
    pub d: f64,
    /// Outer radius C (None: infinite).
    pub c: Option<f64>,
    /// Poisson's ratio (default 0.3).
    pub nu: f64,
    /// Lower plate thickness (None: D).
    pub d2: Option<f64>,
    /// The unit system of the lengths asked and of everything answered.
    pub units: UnitSystem,
}

/// The page's hole radius A in `units`: 0.1 in (the report's Table 1), as the page sends it
/// (12 significant digits, `x.toPrecision(12)`).
pub fn hole(units: UnitSystem) -> f64 {
    as_entered(0.1 * UnitSystem::InPsiLbf.length() / units.length())
}

/// The page's opening joint in `units` (the sliders' defaults of `page.html`: A/D = 1,
/// B/A = 3.1, C/A = 15, ν = 0.3, D₂ = D), with each length as the page's query sends it: in
/// mm-MPa-N A = 2.54, B = 7.874, D = 2.54, C = 38.1.
pub fn opening(units: UnitSystem) -> JointQuery {
    let a = hole(units);
    JointQuery {
        a,
        b: as_entered(a * 3.1),
        d: as_entered(a),
        c: Some(as_entered(a * 15.0)),
        nu: 0.3,
        d2: None,
        units,
    }
}

/// Decodes `%XX` and `+` of a query component.
fn decode(s: &str) -> String {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' if i + 2 < bytes.len() => {
                let hex = |c: u8| (c as char).to_digit(16);
                match (hex(bytes[i + 1]), hex(bytes[i + 2])) {
                    (Some(h), Some(l)) => {
                        out.push((16 * h + l) as u8);
                        i += 2;
                    }
                    _ => out.push(b'%'),
                }
            }
            c => out.push(c),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Parses the query string (a, b, d required; c, nu, d2, units optional; no other keys): the
/// error names the parameter and the value.
pub fn parse(query: &str) -> anyhow::Result<JointQuery> {
    let (mut a, mut b, mut d, mut c, mut nu, mut d2) = (None, None, None, None, None, None);
    let mut units = None;
    for pair in query.split('&').filter(|p| !p.is_empty()) {
        let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
        let (k, v) = (decode(k), decode(v));
        if k == "units" {
            let Ok(u) = v.parse::<UnitSystem>() else {
                return usage(
                    "units",
                    format!("'{v}'"),
                    "is not a unit system (in-psi-lbf, mm-MPa-N, m-Pa-N)",
                );
            };
            if units.replace(u).is_some() {
                return usage("units", u.name(), "is given twice");
            }
            continue;
        }
        let x: f64 = match v.trim().parse() {
            Ok(x) if f64::is_finite(x) => x,
            _ => return usage(&k, format!("'{v}'"), "must be a finite number"),
        };
        let slot = match k.as_str() {
            "a" => &mut a,
            "b" => &mut b,
            "d" => &mut d,
            "c" => &mut c,
            "nu" => &mut nu,
            "d2" => &mut d2,
            _ => {
                return usage(
                    &k,
                    format!("'{v}'"),
                    "is not a parameter (a, b, d, c, nu, d2, units)",
                )
            }
        };
        if slot.replace(x).is_some() {
            return usage(&k, x, "is given twice");
        }
    }
    let need = |name: &str, v: Option<f64>| match v {
        Some(x) => Ok(x),
        None => usage(
            name,
            "missing",
            "is required (a, b, d in the length of units)",
        ),
    };
    let q = JointQuery {
        a: need("a", a)?,
        b: need("b", b)?,
        d: need("d", d)?,
        c,
        nu: nu.unwrap_or(0.3),
        d2,
        units: units.unwrap_or_default(),
    };
    check::annulus(q.a, q.b)?;
    check::positive("d", "plate thickness D", q.d)?;
    if let Some(d2) = q.d2 {
        check::positive("d2", "lower plate thickness D2", d2)?;
        check::ratio("d2", d2, q.d, 1e3, "thickness")?;
    }
    if let Some(c) = q.c {
        check::outer_radius("c", c, q.b)?;
    }
    check::poisson("nu", q.nu, check::NU_MAX_FEM)?;
    check::domain(
        q.a,
        q.b,
        q.d2.map_or(q.d, |d2| d2.min(q.d)),
        check::B_OVER_D_TWO,
    )?;
    Ok(q)
}

/// Answers the joint `q` (module docs).
pub fn answer(q: &JointQuery) -> anyhow::Result<serde_json::Value> {
    let start = std::time::Instant::now();
    let e = Units { units: q.units }.psi_in(E_PSI);
    let mat = Material::new(e, q.nu)?;
    let outer = q.c.map_or(OuterRadius::Infinite, OuterRadius::Finite);
    let d2 = q.d2.unwrap_or(q.d);
    let load = FaceLoad::uniform(q.a, q.b, 1.0)?;
    let joint = Joint::new(
        q.a,
        outer,
        Plate::new(q.d, mat)?,
        Plate::new(d2, mat)?,
        load.clone(),
    )?;
    // the route layer decides: the pressure curve of the two plates and the midplane σ_z of
    // the single plate, both drawn, ask the finite elements at the page's tolerance
    let two_q = two_plate::Question {
        curve: true,
        ..two_plate::Question::new(&joint, TOLERANCE)
    };
    let single_q = single_plate::Question {
        field: true,
        ..Default::default()
    };
    let two_plan = two_plate::plan(&two_q).map_err(|b| anyhow::anyhow!("{}", b.reason))?;
    let single_plan = single_plate::plan(&single_q).map_err(|b| anyhow::anyhow!("{}", b.reason))?;
    for plan in [two_plan, single_plan] {
        if plan.method != Method::Fem {
            anyhow::bail!(
                "the page draws the finite elements' curves; the route layer chose {:?}",
                plan.method
            );
        }
    }
    let (two, plate_single) = rayon::join(
        || solve(&joint, &two_q.fem_params()),
        || -> anyhow::Result<_> {
            let plate = SinglePlate::new(q.a, outer, q.d, Material::unit(q.nu)?, load.clone())?;
            let sp = SingleParams {
                tolerance: TOLERANCE,
                ..SingleParams::default()
            };
            let (s, h) = solve_with_field(&plate, &sp)?;
            Ok((s, midplane_of(&plate, &h)?))
        },
    );
    let two = two?;
    let (single, mid) = plate_single?;
    let two_value = Value::with_tolerance(two.r_o, two.r_o_error, TOLERANCE);
    let rules = rules_beside::beside((q.b, q.d, d2, outer), 30.0, two_value);
    let reach = 1.6
        * rules
            .rules
            .iter()
            .map(|r| r.radius)
            .fold(single.r_o.max(two.r_o), f64::max);
    let clip = |r: &[f64], y: &[f64]| -> (Vec<f64>, Vec<f64>) {
        r.iter()
            .zip(y)
            .filter(|(r, _)| **r <= reach)
            .map(|(r, y)| (*r, *y))
            .unzip()
    };
    let (pr, pp) = clip(&two.radius, &two.pressure);
    let (sr, ss) = clip(&mid.r, &mid.sigma_z);
    let levels = two.info.levels.last();
    let (length, stress, force) = q.units.symbols();
    let mut out = json!({
        "inputs": {"a": q.a, "b": q.b, "d": q.d, "nu": q.nu, "d2": d2, "e": e, "p": 1.0},
        "units": q.units.name(),
        "unit_symbols": {"length": length, "stress": stress, "force": force},
        "two": {
            "r_o": two.r_o, "r_o_error": two.r_o_error, "converged": two.converged,
            "full_contact": two.full_contact, "overlap": two.overlap, "report_rule": two.report_rule,
            "tolerance": TOLERANCE, "interface": two.info.model, "method": "fem",
            "nodes": levels.map(|l| l.nodes), "dofs": levels.map(|l| l.dofs),
            "observed_order": two.info.observed_order, "nut_deflection": two.nut_deflection,
            "seconds": two.info.seconds,
        },
        "single": {
            "r_o": single.r_o, "r_o_error": single.r_o_error, "converged": single.converged,
            "tolerance": TOLERANCE, "method": "fem", "thickness": 2.0 * q.d,
            "seconds": single.info.seconds,
        },
        "rules": rules.rules,
        "curves": {
            "pressure": {"r": pr, "p": pp},
            "sigma_z": {"r": sr, "sigma_z": ss},
        },
    });
    if !rules.left_out.is_empty() {
        out["rules_left_out"] = serde_json::to_value(&rules.left_out)?;
    }
    // no null in the answer: optional quantities are left out
    if let Some(c) = q.c {
        out["inputs"]["c"] = c.into();
    }
    if q.a > 0.0 {
        out["two"]["r_o_over_a"] = (two.r_o / q.a).into();
        out["single"]["r_o_over_a"] = (single.r_o / q.a).into();
    }
    for key in ["nodes", "dofs", "observed_order"] {
        if out["two"][key].is_null() {
            if let Some(m) = out["two"].as_object_mut() {
                m.remove(key);
            }
        }
    }
    out["seconds"] = start.elapsed().as_secs_f64().into();
    Ok(out)
}
