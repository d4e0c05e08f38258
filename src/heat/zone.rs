//! The thermal resistance of a bolted joint's contact zone by axisymmetric conduction FE
//! ([`super::conduction`]): two plates from the hole A to a radius R_e, the upper plate's rim
//! r = R_e held at 1 K above the lower's, joined at the interface by h_c(p(r)) of a two-plate
//! solution ([`super::joint::JointParams`]; 0 beyond R_o: vacuum). The resistance R = ΔT/Q
//! holds the macroscopic constriction toward the contact zone and the microscopic contact
//! resistance together (report Chapter V: "a macroscopic constriction for heat flow is
//! encountered because the flow is being channeled toward the small contact zone").
//!
//! Method: Q9 elements, `radial` uniform in r over A..R_e and `axial` per plate in z; h(r) is
//! lumped at the interface nodes by the consistent weights of [`super::conduction`]; the heat
//! flow is the sum of the upper rim's reactions. Units: the solution's lengths (named by
//! [`super::joint::JointParams::length_unit`]); R in K/W ([`Resistance`]).
//!
//! # Accuracy
//!
//! `tests/heat/zone.rs` checks a uniform h against the closed form of thin plates (the fin equation
//! θ'' + θ'/r = m²θ, m² = 2h/(kt), solved by I₀, K₀): the difference falls in proportion to the
//! Biot number ht/k, the fin model's own error; and `examples/18_heat_speed.rs` prints error
//! against time for Chapter V's joint (h_c jumps to 0 at R_o, which limits the rate with `radial`).
//!
//! # Cost
//!
//! One sparse Cholesky of (2·axial·2 + 1)(2·radial + 1) nodes.
//!
//! ```
//! use boltzone::contact::two_plate::{solve, TwoPlateParams};
//! use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
//! use boltzone::heat::joint::JointParams;
//! use boltzone::heat::units::{Conductivity, Length, Pressure};
//! use boltzone::heat::zone::{zone_resistance, Zone};
//! use boltzone::{FaceLoad, Joint, Material};
//! let joint = Joint::symmetric(0.1, 0.13, 0.1, Material::new(1.0e7, 0.33)?)?
//!     .with_load(FaceLoad::uniform(0.1, 0.13, 46_500.0)?)?;
//! let s = solve(&joint, &TwoPlateParams { tolerance: 1e-2, ..Default::default() })?;
//! let k = Conductivity::btu_per_hr_ft_f(100.0);
//! let surfaces = Surfaces::new([k; 2], [Length::micro_inches(50.0); 2],
//!     [0.1 / 2f64.sqrt(); 2], Pressure::psi(150_000.0))?;
//! let params = JointParams::new(ContactConductance::new(Correlation::Cmy1969, surfaces)?);
//! let zone = Zone { outer_radius: 0.75, thickness: [0.1, 0.1], conductivity: k, radial: 16, axial: 2 };
//! let r = zone_resistance(&s, &params, &zone)?;
//! assert!(r.resistance.to_f_hr_per_btu() > 0.1 && r.resistance.to_f_hr_per_btu() < 2.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::conduction::solve_conduction;
use super::joint::JointParams;
use super::units::{Conductivity, Length, Pressure, Resistance};
use crate::contact::two_plate::TwoPlateSolution;
use crate::error::{positive, InputError};
use crate::fem::{ElementKind, Mesh, PlateSpec, Spacing};

/// The contact zone's extent and mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    /// Rim radius R_e (solution units, > R_o).
    pub outer_radius: f64,
    /// Thicknesses of the upper and lower plates (solution units).
    pub thickness: [f64; 2],
    /// The plates' conductivity.
    pub conductivity: Conductivity,
    /// Q9 elements in r.
    pub radial: usize,
    /// Q9 elements in z per plate.
    pub axial: usize,
}

/// The resistance and what it cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneResistance {
    /// R = ΔT/Q between the two rims.
    pub resistance: Resistance,
    /// Mesh nodes.
    pub nodes: usize,
    /// Seconds to assemble and solve.
    pub seconds: f64,
}

/// The contact zone's resistance (module docs): h_c(p(r)) of `sol` by the law of `params`
/// inside R_o, 0 beyond.
pub fn zone_resistance(
    sol: &TwoPlateSolution,
    params: &JointParams,
    zone: &Zone,
) -> Result<ZoneResistance, InputError> {
    let pu = positive("pressure unit", params.pressure_unit.si())?;
    let h = |r: f64| {
        if r <= sol.r_o {
            let p = Pressure::from_si(sol.pressure_at(r).max(0.0) * pu);
            params.contact.coefficient(p).map_or(0.0, |c| c.si())
        } else {
            0.0
        }
    };
    let a = sol.radius.first().copied().unwrap_or(0.0);
    resistance_with(a, &h, params.length_unit, zone)
}

/// The resistance between the rims of two plates from `a` to `zone.outer_radius` (lengths in
/// `length_unit`) joined by `h(r)` (r in `length_unit`, h in W/(m²·K)).
pub fn resistance_with(
    a: f64,
    h: &dyn Fn(f64) -> f64,
    length_unit: Length,
    zone: &Zone,
) -> Result<ZoneResistance, InputError> {
    let lu = positive("length unit", length_unit.si())?;
    if zone.outer_radius.is_nan() || zone.outer_radius <= a {
        return Err(InputError::Parameter {
            field: "zone outer radius R_e",
            value: zone.outer_radius,
            reason: "must exceed the hole radius",
        });
    }
    let [t1, t2] = zone.thickness;
    positive("upper plate thickness", t1)?;
    positive("lower plate thickness", t2)?;
    let r = Spacing::uniform(a * lu, zone.outer_radius * lu, zone.radial)?;
    let plates = [
        PlateSpec {
            z: Spacing::uniform(0.0, t2 * lu, zone.axial)?,
            material: 0,
        },
        PlateSpec {
            z: Spacing::uniform(t2 * lu, (t1 + t2) * lu, zone.axial)?,
            material: 0,
        },
    ];
    let mesh = Mesh::structured(ElementKind::Q9, &r, &plates)?;
    let mut fixed: Vec<(usize, f64)> = mesh.outer(1).into_iter().map(|i| (i, 1.0)).collect();
    fixed.extend(mesh.outer(0).into_iter().map(|i| (i, 0.0)));
    let s = solve_conduction(&mesh, &[zone.conductivity.si()], &|r_m| h(r_m / lu), &fixed)?;
    let q: f64 = mesh.outer(1).iter().map(|&i| s.flow[i]).sum();
    Ok(ZoneResistance {
        resistance: Resistance::from_si(1.0 / q),
        nodes: mesh.n_nodes(),
        seconds: s.seconds,
    })
}
