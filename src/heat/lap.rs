//! A bolted lap joint as a conductance network in the spirit of Appendix D (report Chapter V):
//! two strips of width W and thickness t overlap over a length l_o around a bolt; heat enters at
//! one strip's far edge (temperature ΔT above the other's) and crosses to the other strip only
//! through the contact zone A ≤ r ≤ R_o around the hole (vacuum, no radiation).
//!
//! Figure 29 (the report's node layout) is lost; what is assumed here, following its text: no
//! temperature variation through the thickness (thin, conductive plates); each strip is a grid of
//! square cells (W/n across) over the overlap and a margin beyond it, cells whose centre lies in
//! the hole removed; beyond the margin each strip is one-dimensional, k W t / length, out to
//! its edge, L/2 from the bolt; cells facing each other across the interface are joined by
//! ∫ h_c(p(r)) dA over the cell (p from a two-plate solution, sampled on s × s points per cell),
//! in series with the conduction through half of each plate over the cell's contact area.
//! Cell-to-cell links are k t (face length / centre distance); the grid's far column joins a
//! node standing for the strip's cross-section (isothermal there: the margin lets the transverse
//! variations decay, as e^{−πx/W}).
//!
//! Units: SI inside ([`super::units`]); the joint's temperature drop and heat flow in any unit
//! via the newtypes.
//!
//! # Accuracy
//!
//! With no hole and a uniform h_c over the whole overlap the problem is one-dimensional with a
//! closed form (two strips coupled along the overlap, resistance l/(2K) + coth(λl/2)/(Kλ), K = k W
//! t, λ² = 2hW/K); `tests/heat/lap.rs` matches it at the observed second order (errors 2.7e-3 →
//! 4.2e-5 over 4 → 32 cells, rates 1.99–2.00). The Chapter V example
//! (`examples/15_lap_joint_heat.rs`) shows the cell size, overlap, margin, sampling, width,
//! correlation, ν and plate radius each moving its heat flow by < 0.4 %; the through-thickness term
//! by 4 %: the modelling of the constriction, not the numerics, decides. The example's step 6
//! brackets it with the (r, z) conduction FE of [`super::conduction`] on the contact zone alone:
//! the term overestimates that zone's resistance about as much as leaving it out underestimates it
//! (0.844 and 0.627 against the FE's 0.737 °F·hr/Btu).
//!
//! # Cost
//!
//! One sparse Cholesky of 4 n² nodes (n = 150: 90,000 nodes, printed by the example).
//!
//! ```
//! use boltzone::heat::lap::LapJoint;
//! let lap = LapJoint::chapter5();
//! let q = lap.solid_heat_flow();
//! assert!((q.to_btu_per_hr() - 3.58).abs() < 1e-9);
//! ```

use super::joint::JointParams;
use super::network::{Network, NetworkError};
use super::units::{Conductance, Conductivity, Length, Power, Resistance, TemperatureDifference};
use crate::contact::two_plate::TwoPlateSolution;
use crate::error::{positive, InputError};
use serde::Serialize;
use std::time::Instant;
use thiserror::Error;

/// A lap joint that cannot be modelled.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LapError {
    /// A bad dimension or count.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The network failed.
    #[error(transparent)]
    Network(#[from] NetworkError),
}

/// The lap joint's geometry, material and the network's resolution (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LapJoint {
    /// Strip width W.
    pub width: Length,
    /// Strip thickness t.
    pub thickness: Length,
    /// Edge-to-edge length L (hot edge to cold edge; the bolt midway).
    pub length: Length,
    /// Overlap length l_o along the strips (rounded to whole cells).
    pub overlap: Length,
    /// Two-dimensional margin beyond the overlap on each strip (rounded to whole cells).
    pub margin: Length,
    /// Hole radius A.
    pub hole_radius: Length,
    /// Conductivity of both strips.
    pub conductivity: Conductivity,
    /// Hot edge minus cold edge.
    pub drop: TemperatureDifference,
    /// Cells across the width, n (≥ 2).
    pub cells: usize,
    /// Sample points per cell side for the contact conductance, s (≥ 1).
    pub samples: usize,
    /// Add the conduction through half of each plate's thickness, in series with each contact
    /// link: t / (k A_c) for the two halves over the cell's contact area A_c (the report: "heat
    /// flow in the z-direction in the nodes above and below the contact zone is considered").
    pub through_thickness: bool,
}

/// The network's answer.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LapSolution {
    /// Heat flow from the hot edge to the cold one.
    pub heat_flow: Power,
    /// The same through a solid strip of length L, k W t ΔT / L.
    pub solid_heat_flow: Power,
    /// ΔT / heat flow.
    pub resistance: Resistance,
    /// The joint's added resistance: ΔT / Q − L / (k W t).
    pub joint_resistance: Resistance,
    /// Sum of the contact links (∫ h_c dA over the cells, in series with the plates' thickness
    /// if [`LapJoint::through_thickness`]).
    pub contact_conductance: Conductance,
    /// Heat leaving by the cold edge (= heat_flow in a steady state).
    pub cold_flow: Power,
    /// Network nodes.
    pub nodes: usize,
    /// Cell size W/n.
    pub cell: Length,
    /// The network's residual (the program's |B| − |BC|, W).
    pub residual: f64,
    /// Seconds to build and solve.
    pub seconds: f64,
}

impl LapJoint {
    /// Chapter V's joint as assumed here: aluminium k = 100 Btu/hr·ft·°F, t = 0.1 in, A = 0.1 in,
    /// L = 7 in, ΔT = 20 °F, W from the report's 3.58 Btu/hr through a solid 7-in strip
    /// (W = 3.58 L / (k t ΔT) = 1.5036 in), a square overlap l_o = W, a margin W, n = 60 cells
    /// across and s = 4 samples.
    pub fn chapter5() -> Self {
        let k = Conductivity::btu_per_hr_ft_f(100.0);
        let (t, l) = (Length::inches(0.1), Length::inches(7.0));
        let drop = TemperatureDifference::fahrenheit_degrees(20.0);
        let q = Power::btu_per_hr(3.58);
        let w = Length::from_si(q.si() * l.si() / (k.si() * t.si() * drop.si()));
        Self {
            width: w,
            thickness: t,
            length: l,
            overlap: w,
            margin: w,
            hole_radius: Length::inches(0.1),
            conductivity: k,
            drop,
            cells: 60,
            samples: 4,
            through_thickness: true,
        }
    }

    /// k W t ΔT / L.
    pub fn solid_heat_flow(&self) -> Power {
        Power::from_si(self.strip(self.length.si()) * self.drop.si())
    }

    /// Conductance k W t / x of a strip of length x (m).
    fn strip(&self, x: f64) -> f64 {
        self.conductivity.si() * self.width.si() * self.thickness.si() / x
    }

    /// Builds and solves the network with the interface pressure of `contact` and the contact
    /// law of `params` (module docs).
    pub fn solve(
        &self,
        contact: &TwoPlateSolution,
        params: &JointParams,
    ) -> Result<LapSolution, LapError> {
        let start = Instant::now();
        for (f, v) in [
            ("strip width W", self.width.si()),
            ("strip thickness t", self.thickness.si()),
            ("edge-to-edge length L", self.length.si()),
            ("overlap length", self.overlap.si()),
            ("conductivity k", self.conductivity.si()),
            ("temperature drop", self.drop.si()),
            ("contact length unit", params.length_unit.si()),
        ] {
            positive(f, v)?;
        }
        let count = |field, n: usize, min| {
            if n >= min {
                Ok(n)
            } else {
                Err(InputError::Parameter {
                    field,
                    value: n as f64,
                    reason: "too few",
                })
            }
        };
        let ny = count("cells across the width", self.cells, 2)?;
        let ns = count("samples per cell side", self.samples, 1)?;
        let h = self.width.si() / ny as f64;
        let no = ((self.overlap.si() / h).round() as usize).max(1);
        let nm = (self.margin.si().max(0.0) / h).round() as usize;
        let (e, m) = (0.5 * no as f64 * h, nm as f64 * h);
        let rest = 0.5 * self.length.si() - e - m;
        if rest.is_nan() || rest <= 0.0 {
            return Err(InputError::Parameter {
                field: "overlap/2 + margin (m)",
                value: e + m,
                reason: "must be shorter than half the edge-to-edge length L",
            }
            .into());
        }
        let nx = no + nm;
        // Cell (plate, ix, iy): plate 0 spans x from -e - m to e, plate 1 from -e to e + m.
        let x0 = [-e - m, -e];
        let centre = |p: usize, ix: usize, iy: usize| {
            (
                x0[p] + (ix as f64 + 0.5) * h,
                -0.5 * self.width.si() + (iy as f64 + 0.5) * h,
            )
        };
        let a = self.hole_radius.si();
        let mut id = vec![0usize; 2 * nx * ny];
        let mut n = 0;
        for p in 0..2 {
            for ix in 0..nx {
                for iy in 0..ny {
                    let (x, y) = centre(p, ix, iy);
                    if x.hypot(y) >= a {
                        n += 1;
                        id[(p * nx + ix) * ny + iy] = n;
                    }
                }
            }
        }
        let (hot, cold) = (n + 1, n + 2);
        let mut net = Network::new(n + 2)?;
        let kt = self.conductivity.si() * self.thickness.si();
        let node = |p: usize, ix: usize, iy: usize| id[(p * nx + ix) * ny + iy];
        for p in 0..2 {
            for ix in 0..nx {
                for iy in 0..ny {
                    let i = node(p, ix, iy);
                    if i == 0 {
                        continue;
                    }
                    if ix + 1 < nx && node(p, ix + 1, iy) > 0 {
                        net.connect(i, node(p, ix + 1, iy), kt)?;
                    }
                    if iy + 1 < ny && node(p, ix, iy + 1) > 0 {
                        net.connect(i, node(p, ix, iy + 1), kt)?;
                    }
                }
            }
            // The far column to the strip's cross-section node: half a cell, k t h / (h/2).
            let (ix, end) = if p == 0 { (0, hot) } else { (nx - 1, cold) };
            for iy in 0..ny {
                if node(p, ix, iy) > 0 {
                    net.connect(node(p, ix, iy), end, 2.0 * kt)?;
                }
            }
        }
        net.ground(hot, self.strip(rest), self.drop.si())?;
        net.ground(cold, self.strip(rest), 0.0)?;
        // Contact links over the overlap: upper columns nm.., lower columns 0..no.
        let lu = params.length_unit.si();
        let pu = params.pressure_unit.si();
        let fluid = params.fluid.map_or(0.0, |f| f.si().max(0.0));
        let mut g_contact = 0.0;
        for k in 0..no {
            for iy in 0..ny {
                let (iu, il) = (node(0, nm + k, iy), node(1, k, iy));
                if iu == 0 || il == 0 {
                    continue;
                }
                let (xc, yc) = centre(1, k, iy);
                let (mut g, mut hits) = (0.0, 0usize);
                for sx in 0..ns {
                    for sy in 0..ns {
                        let x = xc + h * ((sx as f64 + 0.5) / ns as f64 - 0.5);
                        let y = yc + h * ((sy as f64 + 0.5) / ns as f64 - 0.5);
                        let r = x.hypot(y) / lu;
                        let p = contact.pressure_at(r) * pu;
                        if r <= contact.r_o && p > 0.0 {
                            g += params.contact.coefficient_si(p) + fluid;
                            hits += 1;
                        }
                    }
                }
                let da = h * h / (ns * ns) as f64;
                let mut g = g * da;
                if self.through_thickness && hits > 0 {
                    g = 1.0
                        / (1.0 / g
                            + self.thickness.si() / (self.conductivity.si() * da * hits as f64));
                }
                if g > 0.0 {
                    net.connect(iu, il, g)?;
                    g_contact += g;
                }
            }
        }
        let s = net.solve()?;
        let q = s.nodes[hot - 1].ground_flow;
        let r_total = self.drop.si() / q;
        Ok(LapSolution {
            heat_flow: Power::from_si(q),
            solid_heat_flow: self.solid_heat_flow(),
            resistance: Resistance::from_si(r_total),
            joint_resistance: Resistance::from_si(r_total - 1.0 / self.strip(self.length.si())),
            contact_conductance: Conductance::from_si(g_contact),
            cold_flow: Power::from_si(-s.nodes[cold - 1].ground_flow),
            nodes: n + 2,
            cell: Length::from_si(h),
            residual: s.residual,
            seconds: start.elapsed().as_secs_f64(),
        })
    }
}
