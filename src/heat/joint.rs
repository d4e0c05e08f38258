//! The thermal conductance of a bolted joint's interface, from the interface pressure p(r) of a
//! two-plate solution ([`crate::contact::two_plate::solve`]): the report's Chapter V,
//!
//! G_c = ∫_A^{R_o} h_c(p(r)) 2πr dr   (h_c from [`super::correlation`]),
//!
//! ring by ring as Chapter V's table ([`rings`]), and, as options, conduction through a gas across
//! the open gap g(r) beyond R_o, h = k_gas/(g + M), and radiation between the facing surfaces.
//! Units: the solution's lengths and pressures are in any consistent units named by
//! [`JointParams::length_unit`] and [`JointParams::pressure_unit`] (e.g. inches and psi);
//! conductances come out in W/K ([`Conductance`], `.to_btu_per_hr_f()` for the report's).
//!
//! Method. The contact solver gives nodal forces f_i = ∫ N_i p 2πr dr (the consistent integrals of
//! its traction, summing to the bolt force) and nodal pressures p_i = f_i / w_i with the weights
//! w_i = ∫ N_i 2πr dr. The contact integral is the same nodal rule,
//!
//! G_c ≈ Σ_i w_i h_c(p_i) = Σ_i f_i h_c(p_i)/p_i   (nodes with p_i > 0),
//!
//! which for a law linear in p is exact whatever the √(R_o − r) edge does: Σ f_i = F. For
//! h_c ∝ p^n the rule's error is that of replacing the mean of p^n over a node's support by the
//! n-th power of the mean, of order |n − 1| times the relative spread of p over one element, and
//! largest in the last element before R_o, where the solver's refinement concentrates. The gas
//! integral uses the gap interpolated linearly between nodes and integrates
//! 2πr k/(g(r) + M) exactly on each interval (a logarithm, with its series near zero slope); its
//! edge is R_o itself. Radiation is uniform over R_o ≤ r ≤ C.
//!
//! # Accuracy
//!
//! `tests/heat/joint.rs` checks G_c = c (m/σ) k F/H for exponent 1 to 1e-9 for the three load
//! profiles and an unequal pair; over contact mesh levels 2–8 of Chapter V's joint, eq. (1.1)'s G_c
//! moves by < 2e-6 from level 4 on, and a law with n = 0.5 converges at the predicted rate 1 + n/2
//! = 1.25 (measured 1.28); the gas integral matches closed forms to 1e-14; ring means carry the
//! bolt force to 1 %.
//!
//! # Cost
//!
//! The contact solve dominates (the example `examples/15_lap_joint_heat.rs` prints both).
//!
//! ```
//! use boltzone::contact::two_plate::{solve, TwoPlateParams};
//! use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
//! use boltzone::heat::joint::{joint_conductance, JointParams};
//! use boltzone::heat::units::{Conductivity, Length, Pressure};
//! use boltzone::{FaceLoad, Joint, Material};
//! let joint = Joint::symmetric(0.1, 0.13, 0.1, Material::new(1.0e7, 0.33)?)?
//!     .with_load(FaceLoad::uniform(0.1, 0.13, 46_500.0)?)?;
//! let s = solve(&joint, &TwoPlateParams { tolerance: 1e-2, ..Default::default() })?;
//! let surfaces = Surfaces::new([Conductivity::btu_per_hr_ft_f(100.0); 2],
//!     [Length::micro_inches(50.0); 2], [0.1 / 2f64.sqrt(); 2], Pressure::psi(150_000.0))?;
//! let law = Correlation::PowerLaw { coefficient: 1.45, exponent: 1.0 };
//! let params = JointParams::new(ContactConductance::new(law, surfaces)?);
//! let g = joint_conductance(&s, &params)?;
//! // Exponent 1: G = c (m/σ) k F/H, F the bolt force.
//! let f = Pressure::psi(46_500.0).si() * std::f64::consts::PI * (0.13f64.powi(2) - 0.01) * 0.0254f64.powi(2);
//! let expect = 1.45 * 0.1 / Length::micro_inches(50.0 * 2f64.sqrt()).si()
//!     * Conductivity::btu_per_hr_ft_f(100.0).si() * f / Pressure::psi(150_000.0).si();
//! assert!((g.contact.si() / expect - 1.0).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::correlation::{radiation, ContactConductance};
use super::units::{Coefficient, Conductance, Conductivity, Length, Pressure};
use crate::contact::two_plate::TwoPlateSolution;
use crate::error::{non_negative, positive, InputError};
use serde::Serialize;
use std::f64::consts::PI;

/// Gas in the open gap beyond R_o.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GasGap {
    /// Conductivity of the gas.
    pub conductivity: Conductivity,
    /// Rarefaction length M (> 0: the continuum limit M = 0 makes k/g non-integrable at R_o,
    /// where g ∝ (r − R_o)^{3/2}).
    pub rarefaction: Length,
}

/// Radiation between the facing surfaces beyond R_o (linearised, [`radiation`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Radiation {
    /// Emissivities ε₁, ε₂ in (0, 1].
    pub emissivity: [f64; 2],
    /// Mean absolute temperature of the surfaces, K.
    pub kelvin: f64,
}

/// What [`joint_conductance`] needs besides the solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JointParams {
    /// The contact conductance law with its surfaces.
    pub contact: ContactConductance,
    /// The solution's unit of length (default one inch).
    pub length_unit: Length,
    /// The solution's unit of pressure (default one psi).
    pub pressure_unit: Pressure,
    /// An interstitial fluid's h_f added to h_c inside the contact zone (eq. 1.6; default none).
    pub fluid: Option<Coefficient>,
    /// Gas conduction across the open gap (default none: vacuum).
    pub gas: Option<GasGap>,
    /// Radiation across the open gap (default none).
    pub radiation: Option<Radiation>,
}

impl JointParams {
    /// A vacuum joint with the solution in inches and psi.
    pub fn new(contact: ContactConductance) -> Self {
        Self {
            contact,
            length_unit: Length::inches(1.0),
            pressure_unit: Pressure::psi(1.0),
            fluid: None,
            gas: None,
            radiation: None,
        }
    }
}

/// The joint's interface conductance, by path (all totals around the circle).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JointConductance {
    /// ∫ h_c dA over the contact zone (with h_f if given).
    pub contact: Conductance,
    /// Gas conduction across the open gap.
    pub gas: Conductance,
    /// Radiation across the open gap.
    pub radiation: Conductance,
    /// The sum.
    pub total: Conductance,
    /// The contact zone's area Σ w_i, m².
    pub contact_area: f64,
    /// Interface nodes in contact.
    pub contact_nodes: usize,
}

/// One annulus of a ring table (Chapter V).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Ring {
    /// Inner radius (solution units).
    pub r_inner: f64,
    /// Outer radius (solution units).
    pub r_outer: f64,
    /// Area-weighted mean interface pressure over the ring (solution units).
    pub pressure: f64,
    /// h_c at that pressure.
    pub h_c: Coefficient,
    /// The ring's area, m².
    pub area: f64,
    /// area · h_c over the whole annulus.
    pub conductance: Conductance,
}

fn check_units(params: &JointParams) -> Result<(f64, f64), InputError> {
    Ok((
        positive("length unit", params.length_unit.si())?,
        positive("pressure unit", params.pressure_unit.si())?,
    ))
}

/// The interface conductance of a solved joint (module docs).
pub fn joint_conductance(
    sol: &TwoPlateSolution,
    params: &JointParams,
) -> Result<JointConductance, InputError> {
    let (lu, pu) = check_units(params)?;
    let h_f = match params.fluid {
        Some(h) => non_negative("interstitial fluid h_f", h.si())?,
        None => 0.0,
    };
    let (mut g_c, mut area, mut nodes) = (0.0, 0.0, 0);
    for (&f, &p) in sol.force.iter().zip(&sol.pressure) {
        if p > 0.0 && f > 0.0 {
            let w = f / p * lu * lu;
            g_c += w * (params.contact.coefficient_si(p * pu) + h_f);
            area += w;
            nodes += 1;
        }
    }
    let outer = sol.radius.last().copied().unwrap_or(sol.r_o);
    let g_gas = match params.gas {
        Some(gas) => {
            let k = non_negative("gas conductivity k_gas", gas.conductivity.si())?;
            let m = positive("rarefaction length M", gas.rarefaction.si())? / lu;
            k * lu * gap_integral(&sol.radius, &sol.gap, sol.r_o, m)
        }
        None => 0.0,
    };
    let g_rad = match params.radiation {
        Some(r) => {
            radiation(r.emissivity, r.kelvin)?.si()
                * PI
                * (outer * outer - sol.r_o * sol.r_o).max(0.0)
                * lu
                * lu
        }
        None => 0.0,
    };
    Ok(JointConductance {
        contact: Conductance::from_si(g_c),
        gas: Conductance::from_si(g_gas),
        radiation: Conductance::from_si(g_rad),
        total: Conductance::from_si(g_c + g_gas + g_rad),
        contact_area: area,
        contact_nodes: nodes,
    })
}

/// ∫_{r ≥ start} 2πr / (g(r) + m) dr for g linear between the nodes (any one length unit; the
/// gas conductance is k_gas times this, as [`super::correlation::gas_gap`] per area).
pub fn gap_integral(radius: &[f64], gap: &[f64], start: f64, m: f64) -> f64 {
    let mut sum = 0.0;
    for k in 1..radius.len().min(gap.len()) {
        let (r0, r1) = (radius[k - 1], radius[k]);
        if r1 <= start || r1 <= r0 {
            continue;
        }
        let slope = (gap[k] - gap[k - 1]) / (r1 - r0);
        let a = r0.max(start);
        let c = gap[k - 1].max(0.0) + slope * (a - r0) + m;
        let l = r1 - a;
        let t = slope * l / c;
        sum += 2.0 * PI * (l * l / c * phi(t) + a * l / c * psi(t));
    }
    sum
}

/// ψ(t) = ln(1+t)/t, with its series near 0 (t > −1).
fn psi(t: f64) -> f64 {
    if t.abs() < 1e-3 {
        1.0 - t / 2.0 + t * t / 3.0 - t * t * t / 4.0
    } else {
        t.ln_1p() / t
    }
}

/// φ(t) = (t − ln(1+t))/t², with its series near 0 (t > −1).
fn phi(t: f64) -> f64 {
    if t.abs() < 1e-3 {
        0.5 - t / 3.0 + t * t / 4.0 - t * t * t / 5.0
    } else {
        (t - t.ln_1p()) / (t * t)
    }
}

/// Chapter V's table: over the annuli between consecutive `edges` (solution units, increasing),
/// the area-weighted mean of the interface pressure (linear between nodes, integrated exactly),
/// h_c at that mean, and area · h_c.
pub fn rings(
    sol: &TwoPlateSolution,
    edges: &[f64],
    params: &JointParams,
) -> Result<Vec<Ring>, InputError> {
    let (lu, pu) = check_units(params)?;
    let mut out = Vec::new();
    for (k, pair) in edges.windows(2).enumerate() {
        let (r0, r1) = (pair[0], pair[1]);
        if !(r0.is_finite() && r1.is_finite() && r1 > r0 && r0 >= 0.0) {
            return Err(InputError::Table {
                reason: format!(
                    "ring {}: edges {r0}, {r1} must be finite, increasing and not negative",
                    k + 1
                ),
            });
        }
        // Break at the nodes inside the ring: p·r is quadratic on each piece, Simpson is exact.
        let mut cuts = vec![r0];
        cuts.extend(sol.radius.iter().copied().filter(|&r| r > r0 && r < r1));
        cuts.push(r1);
        let mut force = 0.0;
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            let m = 0.5 * (a + b);
            let f = |r: f64| sol.pressure_at(r) * r;
            force += 2.0 * PI * (b - a) / 6.0 * (f(a) + 4.0 * f(m) + f(b));
        }
        let area = PI * (r1 * r1 - r0 * r0);
        let pressure = force / area;
        let h_c = params
            .contact
            .coefficient(Pressure::from_si(pressure.max(0.0) * pu))?;
        let area_si = area * lu * lu;
        out.push(Ring {
            r_inner: r0,
            r_outer: r1,
            pressure,
            h_c,
            area: area_si,
            conductance: Conductance::from_si(h_c.si() * area_si),
        });
    }
    Ok(out)
}
