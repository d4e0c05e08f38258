//! Checks of every value of a scene before any work starts; each error names the key, the
//! value and the line. Output paths are checked here too, so that nothing is computed for a
//! file that cannot be written. Tests: `tests/scene/errors.rs`.
//!
//! # Accuracy
//!
//! Not numerical: each rule's error names the key and line, `tests/scene/errors.rs` and the mutated
//! scenes of `tests/scene/fuzz.rs`.
//!
//! # Cost
//!
//! Linear in the scene's keys.
//!
//! ```
//! let text = "[hole]\nradius = 0.1\n[load]\nouter_radius = 0.05\npressure = 1.0\n\
//!             [[plates]]\nthickness = 0.1\n";
//! let e = boltzone::scene::Scene::parse(text).unwrap_err();
//! assert!(e.to_string().contains("line 4, key `load.outer_radius`: 0.05"), "{e}");
//! ```

use super::error::SceneError;
use super::file::{
    line_of, path_name, InterfaceKind, MaterialSpec, Method, Model, ProfileKind, Scene, Seg,
};
use super::heat::{CorrelationSpec, CORRELATIONS};
use super::materials;
use crate::route::reach;
use std::path::Path;

/// Largest B/D each model reaches ([`crate::route::reach`]).
fn b_over_d_max(model: Model) -> f64 {
    reach::b_over_d_max(match model {
        Model::TwoPlate => reach::Model::TwoPlate,
        Model::SinglePlate => reach::Model::SinglePlate,
        Model::Slab => reach::Model::Slab,
    })
}

struct Checker<'a> {
    text: &'a str,
}

impl Checker<'_> {
    fn fail(&self, path: &[Seg], value: impl std::fmt::Display, reason: &str) -> SceneError {
        SceneError::Invalid {
            key: path_name(path),
            line: line_of(self.text, path).unwrap_or(1),
            reason: format!("{value}: {reason}"),
        }
    }

    fn positive(&self, path: &[Seg], v: f64, what: &str) -> Result<(), SceneError> {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(self.fail(path, v, &format!("{what} must be a positive finite number")))
        }
    }

    fn output(&self, path: &[Seg], p: &Path) -> Result<(), SceneError> {
        let shown = p.display();
        if p.as_os_str().is_empty() || p.is_dir() || p.file_name().is_none() {
            return Err(self.fail(path, shown, "is not a file name"));
        }
        let dir = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        if !dir.is_dir() {
            return Err(self.fail(path, shown, "its directory does not exist"));
        }
        Ok(())
    }
}

fn k(s: &str) -> Seg {
    Seg::Key(s.into())
}

impl Scene {
    /// Parses a scene, fills what its `[bolt]` leaves out ([`super::bolt_spec::resolve`]) and
    /// checks it (errors name the key, the value and the line).
    pub fn parse(text: &str) -> Result<Self, SceneError> {
        let mut scene = Self::parse_keys(text)?;
        super::bolt_spec::resolve(&mut scene, text)?;
        check(&scene, text)?;
        Ok(scene)
    }

    /// Checks every value (the line of each error is looked up in `text`).
    pub fn check(&self, text: &str) -> Result<(), SceneError> {
        check(self, text)
    }
}

/// Checks `scene`, looking lines up in `text`.
pub fn check(scene: &Scene, text: &str) -> Result<(), SceneError> {
    let c = Checker { text };
    let t = scene.tolerance;
    if !(f64::EPSILON..1.0).contains(&t) {
        return Err(c.fail(
            &[k("tolerance")],
            t,
            "the relative tolerance must lie in [2.2e-16, 1) (f64 resolves R_o no finer than \
             2.2e-16)",
        ));
    }
    let a = scene.hole.radius;
    if !(a.is_finite() && a >= 0.0) {
        return Err(c.fail(
            &[k("hole"), k("radius")],
            a,
            "the hole radius A must be 0 or positive",
        ));
    }
    let b = scene.load.outer_radius;
    c.positive(&[k("load"), k("outer_radius")], b, "the bearing radius B")?;
    if b <= a {
        return Err(c.fail(
            &[k("load"), k("outer_radius")],
            b,
            &format!("the bearing radius B must exceed the hole radius A = {a}"),
        ));
    }
    if let Some(b2) = scene.load.nut_outer_radius {
        let p = [k("load"), k("nut_outer_radius")];
        c.positive(&p, b2, "the nut's bearing radius B2")?;
        if b2 <= a {
            return Err(c.fail(
                &p,
                b2,
                &format!("the nut's bearing radius B2 must exceed the hole radius A = {a}"),
            ));
        }
        if scene.model != Model::TwoPlate && b2 != b {
            return Err(c.fail(
                &p,
                b2,
                "the single-plate and slab models press both faces alike (B2 = B); a nut \
                 face of its own is the two-plate model's",
            ));
        }
    }
    check_load(scene, &c)?;
    check_plates(scene, &c)?;
    if let Some(cr) = scene.joint.outer_radius {
        let p = [k("joint"), k("outer_radius")];
        c.positive(&p, cr, "the outer radius C")?;
        if cr <= b {
            return Err(c.fail(&p, cr, &format!("C must exceed the bearing radius B = {b}")));
        }
        if let Some(b2) = scene.load.nut_outer_radius.filter(|&b2| cr <= b2) {
            return Err(c.fail(
                &p,
                cr,
                &format!("C must exceed the nut's bearing radius B2 = {b2}"),
            ));
        }
        if scene.model == Model::Slab {
            return Err(c.fail(&p, cr, "the slab is infinite: omit joint.outer_radius"));
        }
    }
    let mu = [k("joint"), k("mu")];
    match (scene.joint.interface, scene.joint.mu) {
        (InterfaceKind::Friction, Some(m)) if !(m >= 0.0 && m.is_finite()) => {
            return Err(c.fail(&mu, m, "the friction coefficient must be finite and ≥ 0"))
        }
        (InterfaceKind::Friction, None) => {
            let p = [k("joint"), k("interface")];
            return Err(c.fail(&p, "\"friction\"", "needs joint.mu"));
        }
        (InterfaceKind::Frictionless | InterfaceKind::Welded, Some(m)) => {
            return Err(c.fail(&mu, m, "needs joint.interface = \"friction\""))
        }
        _ => {}
    }
    check_model(scene, &c)?;
    check_heat(scene, &c)?;
    super::temperature::check(scene, text)?;
    check_outputs(scene, &c)
}

/// `[heat]` and `[outputs] conductance` ([`super::heat`]).
fn check_heat(scene: &Scene, c: &Checker) -> Result<(), SceneError> {
    let asked = [k("outputs"), k("conductance")];
    let Some(h) = &scene.heat else {
        return match scene.outputs.conductance {
            true => Err(c.fail(&asked, true, "needs a [heat] table")),
            false => Ok(()),
        };
    };
    if scene.outputs.conductance && scene.model != Model::TwoPlate {
        return Err(c.fail(&asked, true, "needs model = \"two-plate\""));
    }
    let at = |key: &str, i: Option<usize>| {
        let mut p = vec![k("heat"), k(key)];
        p.extend(i.map(Seg::Index));
        p
    };
    match &h.correlation {
        CorrelationSpec::Name(n)
            if !["cmy1969", "yovanovich1982", "mikic-elastic"].contains(&n.as_str()) =>
        {
            return Err(c.fail(
                &at("correlation", None),
                format!("\"{n}\""),
                &format!("give one of {CORRELATIONS} or {{ coefficient = c, exponent = n }}"),
            ));
        }
        CorrelationSpec::Law(l) => {
            let mut p = at("correlation", None);
            p.push(k("coefficient"));
            c.positive(&p, l.coefficient, "the coefficient c")?;
            p.pop();
            p.push(k("exponent"));
            c.positive(&p, l.exponent, "the exponent n")?;
        }
        CorrelationSpec::Name(_) => {}
    }
    for i in 0..2 {
        c.positive(
            &at("conductivity", Some(i)),
            h.conductivity[i],
            "a conductivity",
        )?;
        for (key, v) in [("roughness", h.roughness[i]), ("slope", h.slope[i])] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(c.fail(&at(key, Some(i)), v, "must be 0 or positive"));
            }
        }
    }
    for (key, v) in [("roughness", h.roughness), ("slope", h.slope)] {
        if v == [0.0, 0.0] {
            return Err(c.fail(
                &at(key, None),
                "[0, 0]",
                "both zero: the combined value must be positive",
            ));
        }
    }
    match h.hardness {
        Some(v) => c.positive(&at("hardness", None), v, "the hardness H"),
        None if h.needs_hardness() => Err(c.fail(
            &[k("heat")],
            "(no hardness)",
            "this correlation needs hardness = H (the scene's stress unit)",
        )),
        None => Ok(()),
    }
}

fn check_load(scene: &Scene, c: &Checker) -> Result<(), SceneError> {
    let l = &scene.load;
    let given: Vec<(&str, f64)> = [
        ("force", l.force),
        ("pressure", l.pressure),
        ("nut_displacement", l.nut_displacement),
    ]
    .into_iter()
    .filter_map(|(n, v)| v.map(|v| (n, v)))
    .collect();
    if let (Some(v), true) = (l.nut_displacement, l.profile != ProfileKind::Uniform) {
        return Err(c.fail(
            &[k("load"), k("nut_displacement")],
            v,
            "a prescribed nut displacement has no pressure profile: omit load.profile",
        ));
    }
    match given.as_slice() {
        [] => Err(c.fail(
            &[k("load")],
            "(none)",
            "give one of force, pressure or nut_displacement",
        )),
        [(n, v)] => c.positive(&[k("load"), k(n)], *v, n),
        _ => {
            // name the one written last: the one to delete
            let line = |n: &str| line_of(c.text, &[k("load"), k(n)]).unwrap_or(0);
            let (n, v) = given
                .iter()
                .copied()
                .max_by_key(|(n, _)| line(n))
                .unwrap_or(("force", 0.0));
            Err(c.fail(
                &[k("load"), k(n)],
                v,
                "give only one of force, pressure or nut_displacement",
            ))
        }
    }
}

fn check_plates(scene: &Scene, c: &Checker) -> Result<(), SceneError> {
    if !(1..=2).contains(&scene.plates.len()) {
        return Err(c.fail(
            &[k("plates")],
            format!("{} entries", scene.plates.len()),
            "give one [[plates]] entry (two equal plates) or two (top, bottom)",
        ));
    }
    let nu_max = match (scene.model, scene.method) {
        (Model::Slab, _) | (Model::SinglePlate, Method::Hankel) => 0.5,
        _ => reach::NU_MAX_FEM,
    };
    for (i, p) in scene.plates.iter().enumerate() {
        let at = |key: &str| vec![k("plates"), Seg::Index(i), k(key)];
        c.positive(&at("thickness"), p.thickness, "the plate thickness D")?;
        let d = p.thickness;
        let b = scene.load.outer_radius;
        let a = scene.hole.radius;
        if b / d > b_over_d_max(scene.model) {
            return Err(c.fail(
                &at("thickness"),
                d,
                &format!(
                    "B/D = {:e} exceeds this model's reach {:e}",
                    b / d,
                    b_over_d_max(scene.model)
                ),
            ));
        }
        let hankel_reach = reach::B_OVER_D_SINGLE_HANKEL;
        if scene.model == Model::SinglePlate
            && scene.method == Method::Hankel
            && b / d > hankel_reach
        {
            return Err(c.fail(
                &at("thickness"),
                d,
                &format!(
                    "B/D = {:e} exceeds the Hankel route's reach {hankel_reach:e}: method                      \"fem\" or \"auto\"",
                    b / d
                ),
            ));
        }
        if !reach::hole_in_reach(a, d) {
            return Err(c.fail(&at("thickness"), d, "A/D must lie within 1e-3..1e3"));
        }
        match &p.material {
            Some(MaterialSpec::Name(n)) if materials::lookup(n).is_none() => {
                return Err(c.fail(
                    &at("material"),
                    format!("\"{n}\""),
                    &format!("not in the library ({})", materials::names()),
                ));
            }
            None | Some(MaterialSpec::Name(_)) => {}
            Some(MaterialSpec::Constants(m)) => {
                let mut p = at("material");
                p.push(k("E"));
                c.positive(&p, m.e, "Young's modulus E")?;
                if !(m.nu > -1.0 && m.nu <= nu_max && m.nu < 0.5) {
                    p.pop();
                    p.push(k("nu"));
                    return Err(c.fail(
                        &p,
                        m.nu,
                        &format!("Poisson's ratio must lie in (-1, {nu_max}] for this route"),
                    ));
                }
            }
        }
    }
    if let [up, lo] = scene.plates.as_slice() {
        let r = lo.thickness / up.thickness;
        if !(1.0 / reach::THICKNESS_RATIO..=reach::THICKNESS_RATIO).contains(&r) {
            return Err(c.fail(
                &[k("plates"), Seg::Index(1), k("thickness")],
                lo.thickness,
                "the two thicknesses may differ by at most 1e3 times",
            ));
        }
    }
    Ok(())
}

fn check_model(scene: &Scene, c: &Checker) -> Result<(), SceneError> {
    let symmetric = match scene.plates.as_slice() {
        [_] => true,
        [up, lo] => up.thickness == lo.thickness && scene.material_of(0) == scene.material_of(1),
        _ => false,
    };
    let method = [k("method")];
    match scene.model {
        Model::TwoPlate | Model::SinglePlate if scene.method == Method::Table && symmetric => {
            let blocker = match scene.model {
                Model::SinglePlate => super::run::single_table_blocker(scene),
                _ => super::two_hankel::table_blocker(scene),
            };
            match blocker {
                Some((key, reason)) => {
                    let path: Vec<Seg> = key.split('.').map(k).collect();
                    let text = format!("{reason}; use method \"fem\" or \"auto\"");
                    Err(c.fail(&path, "with method \"table\"", &text))
                }
                None => Ok(()),
            }
        }
        Model::TwoPlate if scene.method == Method::Hankel => {
            match super::two_hankel::blocker(scene) {
                Some((key, reason)) => {
                    let path: Vec<Seg> = key.split('.').map(k).collect();
                    let text = format!("{reason}; use method \"fem\" or \"auto\"");
                    Err(c.fail(&path, "with method \"hankel\"", &text))
                }
                None => Ok(()),
            }
        }
        Model::Slab if scene.method == Method::Table => Err(c.fail(
            &method,
            "\"table\"",
            "the tables answer the two-plate and single-plate models: use \"hankel\" or \"auto\"",
        )),
        Model::Slab if scene.method == Method::Fem => Err(c.fail(
            &method,
            "\"fem\"",
            "the slab is solved by Hankel transforms: use \"hankel\" or \"auto\"",
        )),
        Model::SinglePlate | Model::Slab if !symmetric => Err(c.fail(
            &[k("plates")],
            "two unequal plates",
            "the single-plate and slab models need two equal plates (one [[plates]] entry)",
        )),
        Model::SinglePlate | Model::Slab
            if scene.model == Model::Slab || scene.method == Method::Hankel =>
        {
            if let Some(v) = scene.load.nut_displacement {
                return Err(c.fail(
                    &[k("load"), k("nut_displacement")],
                    v,
                    "the Hankel routes load the faces by a pressure (use model single-plate, method fem)",
                ));
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

fn check_outputs(scene: &Scene, c: &Checker) -> Result<(), SceneError> {
    let o = &scene.outputs;
    if o.stiffness && scene.model != Model::TwoPlate {
        let p = [k("outputs"), k("stiffness")];
        return Err(c.fail(&p, true, "needs model = \"two-plate\""));
    }
    if let Some(f) = &o.field {
        let path = [k("outputs"), k("field")];
        if scene.model == Model::Slab || scene.method == Method::Hankel {
            return Err(c.fail(
                &path,
                f.display(),
                "the field comes from finite elements: use model two-plate, or single-plate with method fem or auto",
            ));
        }
        c.output(&path, f)?;
    }
    if let Some(f) = &o.midplane {
        let path = [k("outputs"), k("midplane")];
        match scene.model {
            Model::TwoPlate => return Err(c.fail(
                &path,
                f.display(),
                "needs model single-plate or slab (the two-plate interface is interface_pressure)",
            )),
            Model::SinglePlate if scene.method == Method::Hankel => {
                return Err(c.fail(
                    &path,
                    f.display(),
                    "the single plate's midplane comes from finite elements: method fem or auto",
                ))
            }
            _ => c.output(&path, f)?,
        }
    }
    if let Some(p) = &o.interface_pressure {
        let path = [k("outputs"), k("interface_pressure")];
        if scene.model != Model::TwoPlate {
            return Err(c.fail(&path, p.display(), "needs model = \"two-plate\""));
        }
        c.output(&path, p)?;
    }
    if let Some(p) = &o.plot {
        let path = [k("outputs"), k("plot")];
        if scene.model != Model::TwoPlate {
            return Err(c.fail(&path, p.display(), "needs model = \"two-plate\""));
        }
        if !matches!(p.extension().and_then(|e| e.to_str()), Some("svg" | "png")) {
            return Err(c.fail(&path, p.display(), "must end in .svg or .png"));
        }
        c.output(&path, p)?;
    }
    if let Some(p) = &o.report {
        let path = [k("outputs"), k("report")];
        if scene.model != Model::TwoPlate {
            return Err(c.fail(&path, p.display(), "needs model = \"two-plate\""));
        }
        if !matches!(
            p.extension().and_then(|e| e.to_str()),
            Some("md" | "html" | "htm")
        ) {
            return Err(c.fail(&path, p.display(), "must end in .md, .html or .htm"));
        }
        c.output(&path, p)?;
    }
    if let Some(p) = &o.results {
        c.output(&[k("outputs"), k("results")], p)?;
    }
    if !o.r_o && !o.wants_curve() && !o.conductance && o.field.is_none() && o.midplane.is_none() {
        return Err(c.fail(
            &[k("outputs"), k("r_o")],
            false,
            "nothing asked: no output wanted",
        ));
    }
    Ok(())
}
