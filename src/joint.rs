//! The joint's geometry in the report's notation (Nomenclature; Fig. 5): hole radius A, load
//! annulus A..B, plate outer radius C (finite or infinite), plate thickness D (of ONE plate), and a
//! material per plate.
//!
//! Two descriptions are used:
//! - [`Joint`]: two plates pressed together by a bolt head on the outer face of the upper plate and a
//!   nut on the outer face of the lower plate (the two-plate model, report Figs. 4–5), by default
//!   over the same annulus A..B; [`Joint::with_nut_load`] gives the nut its own bearing face
//!   A..B₂ (the head's B₁ = B), carrying the same force;
//! - [`SinglePlate`]: the single-plate substitution of Fernlund, Greenwood and Lardner, one plate 2D
//!   thick loaded symmetrically on both faces (report Fig. 3(f)); its midplane σ_z approximates the
//!   interface pressure.
//!
//! Lengths in any one unit (inches in the report and the command-line tool).
//!
//! # Accuracy
//!
//! Exact (no numerics); every bad value is a typed error naming the field:
//! `tests/contact/two_plate.rs` (`bad_parameters_are_typed_errors`).
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::{Joint, Material};
//! let j = Joint::symmetric(0.1, 0.31, 0.1, Material::unit(0.3)?)?;
//! let s = j.single_plate_substitute().ok_or("unequal plates")?;
//! assert_eq!(s.half_thickness(), 0.1);
//! assert!(Joint::symmetric(0.1, 0.05, 0.1, Material::unit(0.3)?).is_err());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{non_negative, positive, InputError};
use crate::load::FaceLoad;
use crate::material::Material;
use serde::{Deserialize, Serialize};

/// Where a wide or infinite single plate is cut, in half-thicknesses D beyond B: the rim's
/// effect on the midplane σ_z decays like e^(−2.1 (C − r)/D), so beyond B + 30 D it is below
/// f64 resolution of R_o (used by the finite-element and the Hankel single plates).
pub const FAR_RIM: f64 = 30.0;
/// Outer radius C of the plates.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum OuterRadius {
    /// An infinite plate (the Hankel-transform solutions).
    Infinite,
    /// A finite plate of radius C with a traction-free rim unless supports say otherwise.
    Finite(f64),
}

impl OuterRadius {
    /// C as a number (`f64::INFINITY` for an infinite plate).
    pub fn value(&self) -> f64 {
        match self {
            Self::Infinite => f64::INFINITY,
            Self::Finite(c) => *c,
        }
    }

    fn check(&self, b: f64) -> Result<(), InputError> {
        if let Self::Finite(c) = *self {
            positive("plate outer radius C", c)?;
            if c <= b {
                return Err(InputError::OuterRadius { b, c });
            }
        }
        Ok(())
    }
}

/// One plate: thickness D and material.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Plate {
    thickness: f64,
    material: Material,
}

impl Plate {
    /// A plate `thickness` thick (> 0) of `material`.
    pub fn new(thickness: f64, material: Material) -> Result<Self, InputError> {
        positive("plate thickness D", thickness)?;
        Ok(Self {
            thickness,
            material,
        })
    }

    /// Thickness D.
    pub fn thickness(&self) -> f64 {
        self.thickness
    }

    /// Material.
    pub fn material(&self) -> Material {
        self.material
    }
}

fn check_load_on_plate(hole_radius: f64, load: &FaceLoad) -> Result<(), InputError> {
    non_negative("hole radius A", hole_radius)?;
    if load.inner() < hole_radius {
        return Err(InputError::LoadOffPlate {
            load_a: load.inner(),
            hole_a: hole_radius,
        });
    }
    Ok(())
}

/// Two plates clamped by a bolt: the upper plate's outer face carries the head's pressure
/// `load`, the lower plate's outer face the nut's, by default the same (report eq. 2.7 and
/// Fig. 11), or its own ([`Joint::with_nut_load`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Joint {
    hole_radius: f64,
    outer_radius: OuterRadius,
    upper: Plate,
    lower: Plate,
    load: FaceLoad,
    /// The nut's own face load (None: the head's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    nut_load: Option<FaceLoad>,
}

/// Relative difference of the head's and the nut's total forces beyond which
/// [`Joint::with_nut_load`] refuses the pair (the stack would not be in equilibrium).
pub const NUT_FORCE_TOLERANCE: f64 = 1e-9;

/// Why a joint is not one plate on its symmetry plane ([`Joint::asymmetry`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Asymmetry {
    /// The plates differ in thickness or material.
    Plates,
    /// The nut's bearing face differs from the head's (B₂ ≠ B₁, or another profile).
    NutFace,
}

impl Asymmetry {
    /// A sentence fragment for messages.
    pub fn reason(self) -> &'static str {
        match self {
            Self::Plates => "the two plates differ (thickness or material)",
            Self::NutFace => {
                "the nut's bearing face differs from the head's (B2 != B1, or another profile)"
            }
        }
    }
}

impl Joint {
    /// A joint of two plates with a hole of radius `hole_radius` (0: no hole).
    pub fn new(
        hole_radius: f64,
        outer_radius: OuterRadius,
        upper: Plate,
        lower: Plate,
        load: FaceLoad,
    ) -> Result<Self, InputError> {
        check_load_on_plate(hole_radius, &load)?;
        outer_radius.check(load.outer())?;
        Ok(Self {
            hole_radius,
            outer_radius,
            upper,
            lower,
            load,
            nut_load: None,
        })
    }

    /// Two equal infinite plates `d` thick, uniform unit pressure on `a ≤ r ≤ b`.
    pub fn symmetric(a: f64, b: f64, d: f64, material: Material) -> Result<Self, InputError> {
        let plate = Plate::new(d, material)?;
        Self::new(
            a,
            OuterRadius::Infinite,
            plate,
            plate,
            FaceLoad::uniform(a, b, 1.0)?,
        )
    }

    /// The same joint with outer radius `c`.
    pub fn with_outer_radius(mut self, c: OuterRadius) -> Result<Self, InputError> {
        c.check(self.widest_bearing())?;
        self.outer_radius = c;
        Ok(self)
    }

    /// The same joint with another load on both bearing faces (a nut load given before is
    /// replaced by this one too).
    pub fn with_load(mut self, load: FaceLoad) -> Result<Self, InputError> {
        check_load_on_plate(self.hole_radius, &load)?;
        self.outer_radius.check(load.outer())?;
        self.load = load;
        self.nut_load = None;
        Ok(self)
    }

    /// The same joint with the nut's own bearing pressure `nut` on the lower plate's outer face
    /// (the head keeps [`Joint::load`]): its own annulus A₂..B₂ (A₂ ≥ A, B₂ < C) and profile,
    /// carrying the head's total force (within [`NUT_FORCE_TOLERANCE`]: the plates' free body
    /// is then in equilibrium). A nut load equal to the head's is stored as none: the joint is
    /// then the same, `==` and bit for bit, as without the call.
    ///
    /// ```
    /// use boltzone::{FaceLoad, Joint, Material};
    /// let j = Joint::symmetric(0.1, 0.31, 0.1, Material::unit(0.3)?)?;
    /// let f = j.load().total_force();
    /// let nut = FaceLoad::uniform(0.1, 0.25, f / (std::f64::consts::PI * (0.25f64.powi(2) - 0.01)))?;
    /// let k = j.clone().with_nut_load(nut)?;
    /// assert!(!k.is_symmetric() && k.nut_load().outer() == 0.25 && k.load().outer() == 0.31);
    /// assert_eq!(j.clone().with_nut_load(j.load().clone())?, j);
    /// assert!(j.with_nut_load(FaceLoad::uniform(0.1, 0.25, 1.0)?).is_err()); // not F
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_nut_load(mut self, nut: FaceLoad) -> Result<Self, InputError> {
        check_load_on_plate(self.hole_radius, &nut)?;
        self.outer_radius.check(nut.outer())?;
        let (head, own) = (self.load.total_force(), nut.total_force());
        let balanced = (own - head).abs() <= NUT_FORCE_TOLERANCE * head.abs();
        if !balanced {
            return Err(InputError::Parameter {
                field: "nut load's total force",
                value: own,
                reason: "must equal the head's total force (the stack's equilibrium)",
            });
        }
        self.nut_load = (nut != self.load).then_some(nut);
        Ok(self)
    }

    /// [`Joint::with_nut_load`] with the nut's face A..`b2` (A the head load's inner radius)
    /// under the head's profile (uniform, or triangular with its peak at the same end) and the
    /// head's total force, mean pressure F/(π(B₂² − A²)). `b2` equal to B gives the same joint.
    /// A tabulated head load has no profile to carry over: [`Joint::with_nut_load`] then.
    ///
    /// ```
    /// use boltzone::{Joint, Material};
    /// let j = Joint::symmetric(0.1, 0.31, 0.1, Material::unit(0.3)?)?;
    /// let k = j.clone().with_nut_outer_radius(0.4)?;
    /// assert!((k.nut_load().total_force() - j.load().total_force()).abs() < 1e-15);
    /// assert_eq!(j.clone().with_nut_outer_radius(0.31)?, j);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_nut_outer_radius(self, b2: f64) -> Result<Self, InputError> {
        let head = &self.load;
        if b2 == head.outer() {
            return Ok(self);
        }
        let a = head.inner();
        let mean = head.total_force() / (std::f64::consts::PI * (b2 * b2 - a * a));
        let nut = match head.profile() {
            crate::load::Profile::Uniform => FaceLoad::uniform(a, b2, mean)?,
            crate::load::Profile::Triangular(peak) => FaceLoad::triangular(a, b2, mean, peak)?,
            crate::load::Profile::Tabulated => {
                return Err(InputError::Parameter {
                    field: "nut bearing radius B2",
                    value: b2,
                    reason: "a tabulated head load has no profile to carry to the nut: give \
                             the nut's own load (Joint::with_nut_load)",
                })
            }
        };
        self.with_nut_load(nut)
    }

    /// Hole radius A.
    pub fn hole_radius(&self) -> f64 {
        self.hole_radius
    }

    /// Outer radius C.
    pub fn outer_radius(&self) -> OuterRadius {
        self.outer_radius
    }

    /// The plate under the bolt head.
    pub fn upper(&self) -> Plate {
        self.upper
    }

    /// The plate under the nut.
    pub fn lower(&self) -> Plate {
        self.lower
    }

    /// The bearing pressure of the head (and of the nut unless it has its own,
    /// [`Joint::nut_load`]).
    pub fn load(&self) -> &FaceLoad {
        &self.load
    }

    /// The bearing pressure of the nut on the lower plate: its own
    /// ([`Joint::with_nut_load`]) or the head's.
    pub fn nut_load(&self) -> &FaceLoad {
        self.nut_load.as_ref().unwrap_or(&self.load)
    }

    /// Whether the nut has a bearing face of its own, different from the head's.
    pub fn has_own_nut_load(&self) -> bool {
        self.nut_load.is_some()
    }

    /// The largest bearing radius of head and nut, max(B₁, B₂).
    pub fn widest_bearing(&self) -> f64 {
        self.load.outer().max(self.nut_load().outer())
    }

    /// Whether the joint is mirror-symmetric about its interface: equal plates (same thickness
    /// and material) under the same face load on both sides. Then it is one plate on a
    /// frictionless rigid plane (report Chapter II.B).
    pub fn is_symmetric(&self) -> bool {
        self.asymmetry().is_none()
    }

    /// What breaks the mirror symmetry (the plates first), or None for a symmetric joint.
    pub fn asymmetry(&self) -> Option<Asymmetry> {
        if self.upper != self.lower {
            Some(Asymmetry::Plates)
        } else if self.nut_load.is_some() {
            Some(Asymmetry::NutFace)
        } else {
            None
        }
    }

    /// The single-plate substitute (a plate 2D thick loaded on both faces) of a symmetric joint;
    /// `None` for unequal plates or a nut face of its own, which have no symmetric substitute
    /// ([`Joint::asymmetry`] says which).
    pub fn single_plate_substitute(&self) -> Option<SinglePlate> {
        self.is_symmetric().then(|| SinglePlate {
            hole_radius: self.hole_radius,
            outer_radius: self.outer_radius,
            half_thickness: self.upper.thickness,
            material: self.upper.material,
            load: self.load.clone(),
        })
    }
}

/// The single-plate substitution: one plate 2D thick (midplane z = 0, faces z = ±D), both faces
/// pressed by the same `load`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SinglePlate {
    hole_radius: f64,
    outer_radius: OuterRadius,
    half_thickness: f64,
    material: Material,
    load: FaceLoad,
}

impl SinglePlate {
    /// A plate `2 half_thickness` thick with a hole of radius `hole_radius` (0: none).
    pub fn new(
        hole_radius: f64,
        outer_radius: OuterRadius,
        half_thickness: f64,
        material: Material,
        load: FaceLoad,
    ) -> Result<Self, InputError> {
        positive("plate thickness D", half_thickness)?;
        check_load_on_plate(hole_radius, &load)?;
        outer_radius.check(load.outer())?;
        Ok(Self {
            hole_radius,
            outer_radius,
            half_thickness,
            material,
            load,
        })
    }

    /// Hole radius A.
    pub fn hole_radius(&self) -> f64 {
        self.hole_radius
    }

    /// Outer radius C.
    pub fn outer_radius(&self) -> OuterRadius {
        self.outer_radius
    }

    /// D: half the thickness of the substitute, the thickness of one plate of the joint.
    pub fn half_thickness(&self) -> f64 {
        self.half_thickness
    }

    /// Material.
    pub fn material(&self) -> Material {
        self.material
    }

    /// The face load (on both faces).
    pub fn load(&self) -> &FaceLoad {
        &self.load
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel() -> Material {
        Material::steel_304_psi()
    }

    #[test]
    fn errors_name_the_field() {
        let e = Joint::symmetric(0.1, 0.3, 0.0, steel()).unwrap_err();
        assert!(e.to_string().contains("plate thickness D = 0"), "{e}");
        let e = Joint::symmetric(-0.1, 0.3, 0.1, steel()).unwrap_err();
        assert!(e.to_string().contains("A"), "{e}");
        let j = Joint::symmetric(0.1, 0.3, 0.1, steel()).unwrap();
        let e = j
            .clone()
            .with_outer_radius(OuterRadius::Finite(0.2))
            .unwrap_err();
        assert_eq!(e, InputError::OuterRadius { b: 0.3, c: 0.2 });
        let off = FaceLoad::uniform(0.05, 0.3, 1.0).unwrap();
        assert!(matches!(
            j.with_load(off),
            Err(InputError::LoadOffPlate { .. })
        ));
    }

    #[test]
    fn unequal_plates_have_no_substitute() {
        let load = FaceLoad::uniform(0.1285, 0.211, 1.0).unwrap();
        let j = Joint::new(
            0.1285,
            OuterRadius::Finite(2.0),
            Plate::new(0.124, steel()).unwrap(),
            Plate::new(0.257, steel()).unwrap(),
            load,
        )
        .unwrap();
        assert!(!j.is_symmetric());
        assert!(j.single_plate_substitute().is_none());
    }
}
