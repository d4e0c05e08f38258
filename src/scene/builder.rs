//! A scene built in code, without TOML text: [`Scene::builder`] takes the unit system, each
//! method sets one key of the scene file (named in its doc) and [`SceneBuilder::build`] checks
//! every value as [`Scene::parse`] does, so that a built scene and the same scene parsed from a
//! file are equal (`==`) and give the same answer bit for bit.
//!
//! Errors are [`SceneError::Key`]: the scene file's key path (`plates[1].thickness`) and what is
//! wrong with its value; a built scene has no line to name.
//!
//! # Accuracy
//!
//! Not numerical: `tests/scene/builder.rs` builds the example scenes and compares them with the
//! parsed files (`==`) and their answers (bit for bit), and checks that each bad value is named
//! by its key.
//!
//! # Cost
//!
//! Microseconds (the checks of [`Scene::check`]).
//!
//! ```
//! use boltzone::scene::{Scene, UnitSystem};
//! // M10 through two 10 mm steel plates: hole 5.5 mm, bearing face out to 8 mm, 24.4 kN
//! let scene = Scene::builder(UnitSystem::MmMpaN)
//!     .hole(5.5)
//!     .bearing_face(8.0)
//!     .force(24_434.0)
//!     .plate(10.0)
//!     .material("steel-304")
//!     .tolerance(1e-4)
//!     .build()?;
//! let s = boltzone::solve(&scene)?;
//! assert!(s.converged && s.r_o > 8.0 && s.r_o < 20.0, "R_o = {} mm", s.r_o);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::file::{
    Constants, HoleSpec, InterfaceKind, LoadSpec, MaterialSpec, Method, Model, OutputSpec,
    ProfileKind, Scene, ScenePlate, DEFAULT_TOLERANCE,
};
use super::heat::HeatSpec;
use super::temperature::TemperatureSpec;
use super::units::UnitSystem;
use std::path::PathBuf;

/// A scene under construction ([`Scene::builder`]); nothing is checked before
/// [`SceneBuilder::build`].
#[derive(Debug, Clone)]
#[must_use = "a builder does nothing until `build` is called"]
pub struct SceneBuilder {
    scene: Scene,
}

impl Scene {
    /// A scene in `units` with the file's defaults: two-plate model, method auto, tolerance
    /// 5e-4, no hole (radius 0), load on 0..0 (set it), no plates (add them), infinite
    /// frictionless joint, R_o the only output.
    pub fn builder(units: UnitSystem) -> SceneBuilder {
        SceneBuilder {
            scene: Scene {
                units,
                model: Model::default(),
                method: Method::default(),
                tolerance: DEFAULT_TOLERANCE,
                hole: HoleSpec { radius: 0.0 },
                load: LoadSpec {
                    outer_radius: 0.0,
                    nut_outer_radius: None,
                    force: None,
                    pressure: None,
                    nut_displacement: None,
                    profile: ProfileKind::default(),
                },
                plates: Vec::new(),
                joint: Default::default(),
                outputs: OutputSpec::default(),
                heat: None,
                temperature: None,
                bolt: None,
                washer: None,
                preload: None,
                sweep: Default::default(),
            },
        }
    }
}

impl From<&str> for MaterialSpec {
    /// A name of the material library ([`super::materials::LIBRARY`]).
    fn from(name: &str) -> Self {
        Self::Name(name.to_string())
    }
}

impl From<Constants> for MaterialSpec {
    fn from(c: Constants) -> Self {
        Self::Constants(c)
    }
}

impl SceneBuilder {
    /// `model`: two-plate (default), single-plate or slab.
    pub fn model(mut self, model: Model) -> Self {
        self.scene.model = model;
        self
    }

    /// `method`: auto (default), fem or hankel.
    pub fn method(mut self, method: Method) -> Self {
        self.scene.method = method;
        self
    }

    /// `tolerance`: the relative error wanted of every value (default 5e-4).
    pub fn tolerance(mut self, tolerance: f64) -> Self {
        self.scene.tolerance = tolerance;
        self
    }

    /// `hole.radius` A (length unit; 0 for no hole).
    pub fn hole(mut self, radius: f64) -> Self {
        self.scene.hole.radius = radius;
        self
    }

    /// `load.outer_radius` B, the bearing face's outer radius (length unit).
    pub fn bearing_face(mut self, outer_radius: f64) -> Self {
        self.scene.load.outer_radius = outer_radius;
        self
    }

    /// `load.nut_outer_radius` B₂, the nut's own bearing face (length unit; default B).
    pub fn nut_face(mut self, outer_radius: f64) -> Self {
        self.scene.load.nut_outer_radius = Some(outer_radius);
        self
    }

    /// `load.force`: the bolt force (force unit).
    pub fn force(mut self, force: f64) -> Self {
        self.scene.load.force = Some(force);
        self
    }

    /// `load.pressure`: the mean bearing pressure (stress unit).
    pub fn pressure(mut self, pressure: f64) -> Self {
        self.scene.load.pressure = Some(pressure);
        self
    }

    /// `load.nut_displacement`: a uniform displacement of each face under the nut (length
    /// unit; report Fig. 21).
    pub fn nut_displacement(mut self, displacement: f64) -> Self {
        self.scene.load.nut_displacement = Some(displacement);
        self
    }

    /// `load.profile`: uniform (default), peak-a or peak-b.
    pub fn profile(mut self, profile: ProfileKind) -> Self {
        self.scene.load.profile = profile;
        self
    }

    /// One more `[[plates]]` entry, `thickness` D (length unit), under the plates added so far;
    /// its material is the plate above's unless [`SceneBuilder::material`] follows. One plate
    /// means two equal plates (two-plate model) or the plate 2D thick (single plate, slab).
    pub fn plate(mut self, thickness: f64) -> Self {
        self.scene.plates.push(ScenePlate {
            thickness,
            material: None,
        });
        self
    }

    /// `plates[i].material` of the last plate added: a library name (`"steel-304"`,
    /// `boltzone materials` lists them) or [`Constants`] `{ e, nu }` (E in the stress unit).
    /// Before any plate, it adds none: [`SceneBuilder::build`] then refuses `plates`.
    pub fn material(mut self, material: impl Into<MaterialSpec>) -> Self {
        if let Some(p) = self.scene.plates.last_mut() {
            p.material = Some(material.into());
        }
        self
    }

    /// `joint.outer_radius` C (length unit; default infinite).
    pub fn outer_radius(mut self, radius: f64) -> Self {
        self.scene.joint.outer_radius = Some(radius);
        self
    }

    /// `joint.interface`: frictionless (default), welded or friction (then `mu` by
    /// [`SceneBuilder::friction`]).
    pub fn interface(mut self, interface: InterfaceKind) -> Self {
        self.scene.joint.interface = interface;
        self
    }

    /// `joint.interface = "friction"` with `joint.mu` = `mu` ≥ 0.
    pub fn friction(mut self, mu: f64) -> Self {
        self.scene.joint.interface = InterfaceKind::Friction;
        self.scene.joint.mu = Some(mu);
        self
    }

    /// `joint.fixed_edge`: fix the outer edge r = C (report Fig. 20(c)).
    pub fn fixed_edge(mut self, fixed: bool) -> Self {
        self.scene.joint.fixed_edge = fixed;
        self
    }

    /// `[heat]`: the surfaces and the conductance law ([`super::heat`]); with `conductance`
    /// the answer carries the joint's interface conductance (`outputs.conductance`).
    pub fn heat(mut self, heat: HeatSpec, conductance: bool) -> Self {
        self.scene.heat = Some(heat);
        self.scene.outputs.conductance = conductance;
        self
    }

    /// `[temperature]`: the plates' temperatures ([`super::temperature`]).
    pub fn temperature(mut self, temperature: TemperatureSpec) -> Self {
        self.scene.temperature = Some(temperature);
        self
    }

    /// `outputs.interface_pressure`: a CSV of the interface curve (two-plate).
    pub fn interface_csv(mut self, path: impl Into<PathBuf>) -> Self {
        self.scene.outputs.interface_pressure = Some(path.into());
        self
    }

    /// `outputs.field`: a VTU of the finest mesh's field.
    pub fn field_vtu(mut self, path: impl Into<PathBuf>) -> Self {
        self.scene.outputs.field = Some(path.into());
        self
    }

    /// `outputs.midplane`: a CSV of the midplane σ_z(r) (single plate, slab).
    pub fn midplane_csv(mut self, path: impl Into<PathBuf>) -> Self {
        self.scene.outputs.midplane = Some(path.into());
        self
    }

    /// The scene, every value checked as [`Scene::parse`] checks a file's; the error names the
    /// key ([`SceneError::Key`]).
    pub fn build(self) -> Result<Scene, SceneError> {
        match self.scene.check("") {
            Ok(()) => Ok(self.scene),
            Err(SceneError::Invalid { key, reason, .. }) => Err(SceneError::Key { key, reason }),
            Err(e) => Err(e),
        }
    }
}
