//! The bolted-joint flags of `boltzone two` in the route layer's terms
//! ([`boltzone::route::joint`]): `--bolt M10` fills the hole radius A from ISO 273's series
//! (`--hole`), the bearing radius B from the head's d_w/2 (or the washer's d2/2, `--washer`)
//! and the nut's B2 from the nut's d_w/2 (ISO 4032; the washer's d2/2) where `--a`, `--b`,
//! `--b2` are omitted (a `--b` given serves the nut too unless `--b2` is given); `--preload`, `--torque` (with `--mu-thread`, `--mu-head`)
//! or `--utilisation` (with `--mu-thread`, `--grade`) give the bolt force; `--stiffness` (or a
//! bolt) asks the member stiffness k_P, the rules beside it, and with a bolt δ_S, Φ and the
//! bearing pressures. Bad values exit 2 naming the flag.
//!
//! # Accuracy
//!
//! Translations only: `tests/joint/front_ends.rs` (the M10 example's `two` line and scene agree
//! bit for bit; bad flags are named).
//!
//! # Cost
//!
//! Table look-ups; k_P is the route layer's.

use super::exit::{num, usage};
use super::two_args::Args;
use super::two_bolt_args::{HeadFlag, HoleFlag, WasherFlag};
use boltzone::bolt::catalogue::{HeadKind, HoleSeries, WasherSeries};
use boltzone::route::joint::{
    bolt_geometry, grade, preload_force, BoltGeometry, BoltQuestion, BoltSpec, JointAnswer,
    JointError, JointKey, Preload, Scale,
};
use boltzone::route::two_plate::Question;
use boltzone::Value;

/// The flag of a route-layer bolt input.
fn flag_of(key: JointKey) -> &'static str {
    match key {
        JointKey::Size => "--bolt",
        JointKey::Grade => "--grade",
        JointKey::Washer => "--washer",
        JointKey::Shank => "--shank",
        JointKey::Modulus => "--bolt-e",
        JointKey::LoadIntroduction => "--load-introduction",
        JointKey::Force => "--preload",
        JointKey::Torque => "--torque",
        JointKey::MuThread => "--mu-thread",
        JointKey::MuHead => "--mu-head",
        JointKey::Utilisation => "--utilisation",
        JointKey::LimitMaterial => "--limit-material",
    }
}

/// A route-layer bolt error as bad input naming its flag (exit 2).
fn named<T>(args: &Args, e: JointError) -> anyhow::Result<T> {
    let b = &args.bolt;
    let value = match e.key {
        JointKey::Size => b.bolt.clone().unwrap_or_default(),
        JointKey::Grade => b.grade.clone().unwrap_or_default(),
        JointKey::LimitMaterial => b.limit_material.clone().unwrap_or_default(),
        JointKey::Washer => format!("{:?}", b.washer),
        JointKey::Shank => num(b.shank),
        JointKey::Modulus => b.bolt_e.map_or_else(String::new, num),
        JointKey::LoadIntroduction => num(b.load_introduction),
        JointKey::Force => b.preload.map_or_else(String::new, num),
        JointKey::Torque => b.torque.map_or_else(String::new, num),
        JointKey::MuThread => b.mu_thread.map_or_else(String::new, num),
        JointKey::MuHead => b.mu_head.map_or_else(String::new, num),
        JointKey::Utilisation => b.utilisation.map_or_else(String::new, num),
    };
    usage(flag_of(e.key), value, &e.reason)
}

/// The route layer's bolt of the arguments, in their units.
fn spec(args: &Args) -> anyhow::Result<Option<BoltSpec>> {
    let b = &args.bolt;
    let Some(size) = &b.bolt else {
        return Ok(None);
    };
    Ok(Some(BoltSpec {
        size: size.clone(),
        grade: match &b.grade {
            Some(g) => Some(grade(g).or_else(|e| named(args, e))?),
            None => None,
        },
        head: match b.head {
            HeadFlag::Hex => HeadKind::Hex,
            HeadFlag::Socket => HeadKind::Socket,
        },
        hole: match b.hole {
            HoleFlag::Fine => HoleSeries::Fine,
            HoleFlag::Medium => HoleSeries::Medium,
            HoleFlag::Coarse => HoleSeries::Coarse,
        },
        washer: b.washer.map(|w| match w {
            WasherFlag::Iso7089 => WasherSeries::Iso7089,
            WasherFlag::Iso7093 => WasherSeries::Iso7093,
        }),
        shank: b.shank,
        modulus: b.bolt_e,
        load_introduction: b.load_introduction,
    }))
}

/// The tightening of the arguments (None: the bolt is loaded by --force or --p).
fn tightening(args: &Args) -> Option<Preload> {
    let b = &args.bolt;
    match (b.preload, b.torque, b.utilisation) {
        (Some(f), _, _) => Some(Preload::Force(f)),
        (_, Some(torque), _) => Some(Preload::Torque {
            torque,
            mu_thread: b.mu_thread.unwrap_or(f64::NAN),
            mu_head: b.mu_head.unwrap_or(f64::NAN),
        }),
        (_, _, Some(nu)) => Some(Preload::Utilisation {
            nu,
            mu_thread: b.mu_thread.unwrap_or(f64::NAN),
        }),
        _ => None,
    }
}

/// The bolt's catalogue dimensions in the arguments' units.
fn geometry(args: &Args, spec: &BoltSpec) -> anyhow::Result<BoltGeometry> {
    bolt_geometry(spec, Scale::of(args.units.units)).or_else(|e| named(args, e))
}

/// The arguments with A and B filled from `--bolt` where omitted and the bolt force from the
/// preload (exit 2 naming the flag when neither gives them).
pub fn resolve(mut args: Args) -> anyhow::Result<Args> {
    let spec = spec(&args)?;
    let g = match &spec {
        Some(s) => Some(geometry(&args, s)?),
        None => None,
    };
    let given = args.given.clone();
    let pick = |v: Option<f64>, from: Option<f64>, flag: &str| match (v, from) {
        (Some(v), _) => Ok(v),
        (None, Some(d)) => Ok(0.5 * d),
        (None, None) => usage(
            flag,
            "(none)",
            match g {
                Some(_) => "needed: the catalogue has no clearance hole or head for this bolt",
                None => "needed (or --bolt SIZE to fill it from the catalogue)",
            },
        ),
    };
    args.geom = super::args::Geometry {
        a: pick(given.a, g.and_then(|g| g.hole_diameter), "--a")?,
        b: pick(given.b, g.and_then(|g| g.head_diameter), "--b")?,
        d: given.d,
        nu: given.nu,
    };
    // the nut's face: --b2, else with the catalogue's head (no --b) the catalogue's nut, else B
    args.b2 = match (given.b2, given.b, g.and_then(|g| g.nut_diameter)) {
        (Some(b2), _, _) => Some(b2),
        (None, None, Some(d)) => Some(0.5 * d),
        _ => None,
    };
    if let (Some(s), Some(g), Some(p)) = (&spec, &g, tightening(&args)) {
        let sizes = (2.0 * args.geom.a, 2.0 * args.geom.b);
        let f = preload_force(s, g, p, sizes, Scale::of(args.units.units))
            .or_else(|e| named(&args, e))?;
        args.force = Some(f);
    }
    Ok(args)
}

/// The bolted-joint answer of the arguments' question `q` (when --stiffness or --bolt ask it),
/// with the member-compliance study.
pub fn answer(
    args: &Args,
    q: &Question,
) -> anyhow::Result<
    Option<(
        JointAnswer,
        Option<boltzone::contact::compliance::MemberCompliance>,
    )>,
> {
    if !q.stiffness && args.bolt.bolt.is_none() {
        return Ok(None);
    }
    let spec = spec(args)?;
    let g = match &spec {
        Some(s) => Some(geometry(args, s)?),
        None => None,
    };
    let preload = tightening(args).unwrap_or(Preload::Force(q.joint.load().total_force()));
    let bolt = match (&spec, &g) {
        (Some(spec), Some(geometry)) => Some(BoltQuestion {
            spec,
            geometry,
            preload,
            limit_material: args.bolt.limit_material.as_deref(),
        }),
        _ => None,
    };
    match boltzone::route::joint::answer(q, bolt, Scale::of(args.units.units)) {
        Ok(a) => Ok(Some(a)),
        Err(boltzone::route::joint::AnswerError::Bolt(e)) => named(args, e),
        Err(boltzone::route::joint::AnswerError::Contact(e)) => Err(e.into()),
    }
}

/// Adds the answer's keys to the JSON `out` (their names: [`JointAnswer`]).
pub fn add_json(out: &mut serde_json::Value, a: &JointAnswer) -> anyhow::Result<()> {
    if let (serde_json::Value::Object(m), serde_json::Value::Object(j)) =
        (out, serde_json::to_value(a)?)
    {
        m.extend(j);
    }
    Ok(())
}

/// The text lines of a bolted-joint answer in the unit system `units` (the same for `two` and
/// `solve`).
pub fn lines(a: &JointAnswer, units: boltzone::scene::UnitSystem) -> Vec<String> {
    let (l, s, f) = units.symbols();
    let pm = |v: Value| {
        format!(
            "{} ± {:.1e}{}",
            super::exit::sig(v.value, 5),
            v.error,
            if v.converged { "" } else { " (NOT converged)" }
        )
    };
    let mut out = Vec::new();
    if let (Some(k), Some(d)) = (a.member_stiffness, a.member_compliance) {
        out.push(format!(
            "member stiffness k_P = {} {f}/{l}, compliance delta_P = {} {l}/{f}",
            pm(k),
            pm(d)
        ));
    }
    if let Some(rules) = &a.rules {
        let shown: Vec<String> = rules
            .iter()
            .map(|(name, r)| match (r.stiffness, r.error_percent) {
                (Some(k), Some(e)) => {
                    format!("{name} {} ({:+.1} %)", super::exit::sig(k, 4), e.value)
                }
                _ => format!("{name} left out"),
            })
            .collect();
        out.push(format!("k_P rules [{f}/{l}]: {}", shown.join(", ")));
    }
    if let (Some(p), Some(ds), Some(lk)) = (a.preload, a.bolt_compliance, a.clamp_length) {
        out.push(format!(
            "bolt: preload F_M = {} {f}, delta_S = {:.4e} {l}/{f} (clamp length {} {l}){}",
            super::exit::sig(p, 6),
            ds,
            super::exit::sig(lk, 6),
            a.load_factor.map_or(String::new(), |phi| format!(
                ", load factor Phi = {}",
                pm(phi)
            ))
        ));
    }
    if let Some(p) = a.bearing_pressure {
        out.push(format!(
            "bearing pressure: head {} {s}, nut {} {s}{}",
            super::exit::sig(p.head, 5),
            super::exit::sig(p.nut, 5),
            p.limit.map_or(String::new(), |g| format!(
                " (limit p_G {} {s})",
                super::exit::sig(g, 4)
            ))
        ));
    }
    out
}
