//! Receding contact of an elastic layer on a frictionless rigid base: the contact radius R_o,
//! the contact pressure and the gap, semi-analytically — an independent check of the
//! finite-element two-plate solver that shares no FE code.
//!
//! **Problem** (report Ch. II.B). Two equal plates bolted together are, by symmetry, one plate
//! 0 ≤ z ≤ D on a frictionless rigid plane: top face pressed by p(r) (disk r ≤ B, or an annulus
//! with no hole in the plate); bottom face τ_rz = 0 and unilateral contact, q(r) ≥ 0,
//! gap g(r) ≥ 0, q·g = 0. The contact zone is the disk r ≤ R_o, and R_o does not depend on the
//! load's magnitude (receding contact: Keer, Dundurs & Tsai 1972, *J. Appl. Mech.* 39,
//! 1115–1120; Gladwell 1976, *Int. J. Eng. Sci.* 14, 899–907). Compression is positive in p
//! and q here (they press on the layer); w is positive upward; lengths in the units of D.
//!
//! **Derivation.** The bottom face moves by
//! w(r) = ((1−ν)/G) ∫₀^∞ [q̄M_q − p̄M_p] J₀(ξr) dξ ([`super::layer`]). Write
//! M_q = 1 + M_p + k₁ (k₁ = S − 1 bounded, M_p ~ 6/(ξD)³ the plate's bending) and represent
//! the contact pressure by an Abel-type function φ on [0, c]:
//!
//! q̄(ξ) = ∫₀^c φ(t) cos ξt dt,  q(r) = φ(c)/√(c² − r²) − ∫_r^c φ′(t)/√(t² − r²) dt,
//!
//! so that ∫₀^∞ q̄ J₀(ξr) dξ = ∫₀^r φ(t)/√(r² − t²) dt (from ∫₀^∞ cos ξt J₀(ξr) dξ =
//! H(r − t)/√(r² − t²)). The contact condition w = const on r ≤ c, inverted by Abel's formula
//! (which maps J₀(ξr) to (2/π) cos ξt and a constant to a constant), becomes a Fredholm equation
//! of the second kind (module `system`). The bending kernel is made integrable by
//! equilibrium: with ∫₀^c φ dt = q̄(0) = p̄(0), the product M_p(q̄ − p̄) is used with J₀(ξr) − 1
//! (displacements relative to the axis; the constant joins the unknown rigid translation C₀).
//! φ(c) is the coefficient of the inverse-square-root edge singularity: a smooth receding
//! contact has φ(c) = 0, so R_o is the root of φ(c; c) = 0, found by a scan from the load's
//! outer radius and Brent's method ([`crate::numerics::root`]). Since the equation is linear
//! in the load and none of its kernels depends on ν, R_o depends on the load's shape and B/D
//! only.
//!
//! **Discretisation and error.** Nyström's method with an n-point Gauss–Legendre rule on
//! [0, c]: the kernels are analytic, so R_o converges geometrically in n. The error estimate of
//! R_o is the change from a run with ⌈3n/4⌉ points (an over-estimate under geometric
//! convergence) plus the root tolerance. The pressure follows from φ′ by the formula above with
//! t² = r² + τ² (a smooth τ-integral); the gap beyond c from
//! g(r) = ((1−ν)/G)[H(r) − H(c) + ∫ (k₁q̄ + M_p(q̄ − p̄))(J₀(ξr) − J₀(ξc)) dξ],
//! H(r) = ∫₀^c φ(t)/√(r² − t²) dt. The solution is verified before it is returned: contact
//! pressure ≥ 0 inside R_o and gap ≥ 0 beyond, sampled (else [`RecedingError::NotUnilateral`]:
//! the contact zone is then not a disk, as under a wide ring on a thin plate).
//!
//! # Accuracy
//!
//! (`tests/hankel/receding_contact.rs`, `tests/hankel/receding_kernels.rs`,
//! `tests/contact/receding_vs_fe.rs`): the kernels against a general Love solution and the
//! Kirchhoff plate; the bilateral limit (contact forced on r ≤ B + 12D) reproduces the midplane σ_z
//! of the slab of half-thickness D ([`crate::hankel::midplane`]) to 1e-12·p; 2π∫q r dr = F to
//! 1e-15; q ~ (R_o − r)^(1/2) and g ~ (r − R_o)^(3/2); R_o independent of the load's scale and of
//! ν; and the FE two-plate solver, which converges to the same R_o as its outer radius C grows
//! (difference ∝ C⁻², extrapolated agreement ~1e-5·R_o).
//!
//! # Cost
//!
//! About 20 Nyström solves per R_o, ~20 ms at B = D (example 06).
//!
//! ```
//! use boltzone::{FaceLoad, Material};
//! use boltzone::hankel::receding::{Layer, RecedingParams};
//! let layer = Layer::new(1.0, Material::unit(0.3)?, FaceLoad::uniform(0.0, 1.0, 1.0)?)?;
//! let contact = layer.receding_contact(&RecedingParams::default())?;
//! assert!(contact.r_o > 1.0 && contact.info.r_o_error < 1e-8);
//! // complementarity: pressure inside, an opening gap outside
//! assert!(contact.solution.pressure(0.5 * contact.r_o) > 0.0);
//! assert!(contact.solution.gap(1.2 * contact.r_o) > 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::layer::Stack;
use super::search::{root, unilateral, RuleCache, Scan};
use super::system::{Nystrom, XiRule};
use crate::error::{positive, InputError};
use crate::hankel::transform::LoadTransform;
use crate::load::FaceLoad;
use crate::material::Material;
use std::time::Instant;

/// Knobs of [`Layer::receding_contact`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecedingParams {
    /// Fewest Gauss–Legendre points n of the Nyström rule on [0, c] (default 16; at least 4).
    pub min_nodes: usize,
    /// Points per thickness: n = max(`min_nodes`, ⌈`nodes_per_thickness`·(B + 2D)/D⌉) for the
    /// R_o search (R_o ≈ B + 0.4…1.1 D), ⌈…·c/D⌉ for [`Layer::contact_over`] (default 4). The
    /// study behind the defaults: R_o converges geometrically in n (e^(−2.2n) at B = D,
    /// e^(−1.3n) at B = 4D), to ~1e-12·D with about 4 points per D of contact radius
    /// (examples/06_receding_contact.rs).
    pub nodes_per_thickness: f64,
    /// Root tolerance on R_o, relative to D (default 1e-12).
    pub rel_tol: f64,
    /// Truncation tolerance of the ξ-integrals, relative (default 1e-15).
    pub quad_tol: f64,
    /// Scan step as a fraction of D (default 0.25).
    pub step: f64,
    /// The scan gives up at B + `reach`·D (default 20).
    pub reach: f64,
    /// Root-finder iterations allowed (default 100).
    pub max_iterations: usize,
}

impl Default for RecedingParams {
    fn default() -> Self {
        Self {
            min_nodes: 16,
            nodes_per_thickness: 4.0,
            rel_tol: 1e-12,
            quad_tol: 1e-15,
            step: 0.25,
            reach: 20.0,
            max_iterations: 100,
        }
    }
}

/// Cost and accuracy of a receding-contact solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecedingInfo {
    /// Estimated absolute error of R_o (change from the ⌈3n/4⌉-point run, plus the root
    /// tolerance).
    pub r_o_error: f64,
    /// R_o of the ⌈3n/4⌉-point run.
    pub r_o_coarse: f64,
    /// Nyström points n.
    pub nodes: usize,
    /// ξ-nodes of the last solve.
    pub xi_nodes: usize,
    /// Nyström systems solved (scan and root finder, both runs).
    pub solves: usize,
    /// Smallest contact pressure sampled at r = k·R_o/8, k = 0…7 (≥ 0, else an error).
    pub min_pressure: f64,
    /// Smallest gap sampled at r = R_o(1 + k/8), k = 1…8 (≥ 0, else an error).
    pub min_gap: f64,
    /// Wall-clock time in seconds.
    pub seconds: f64,
}

/// Why no receding-contact solution was found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RecedingError {
    /// Bad parameters.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The edge coefficient φ(c) kept one sign over the whole scan (outward from B to
    /// B + reach·D, or inward from B to one step from the axis).
    #[error(
        "the edge coefficient keeps its sign from c = {from} to c = {to}: no contact radius found"
    )]
    NotFound {
        /// Start of the scan.
        from: f64,
        /// End of the scan.
        to: f64,
    },
    /// The solution violates the unilateral conditions: a tensile contact pressure inside
    /// R_o (the contact zone is not a disk, e.g. under a wide annulus on a thin plate) or a
    /// penetration beyond it.
    #[error("{what} = {value} at r = {r}: the contact zone is not the disk r <= R_o")]
    NotUnilateral {
        /// "contact pressure" or "gap".
        what: &'static str,
        /// Where.
        r: f64,
        /// The offending value.
        value: f64,
    },
    /// The Nyström system was singular at this contact radius.
    #[error("singular Nystrom system at contact radius c = {c}")]
    Singular {
        /// The contact radius tried.
        c: f64,
    },
}

impl RecedingError {
    /// Whether the failure is bad input (the caller's to fix) rather than a solver failure.
    pub fn is_input(&self) -> bool {
        matches!(self, Self::Input(_))
    }
}

/// An elastic layer of thickness D on a frictionless rigid base, pressed on its top face.
#[derive(Debug, Clone)]
pub struct Layer {
    /// The thickness (of a stack, the thinnest layer's: the kernels' length scale).
    pub(super) d: f64,
    /// The kernels: one layer, or two in series ([`super::pair`]).
    stack: Stack,
    /// The interface's compliance Σ(1 − νᵢ)/Gᵢ (one term for a layer on a rigid base).
    compliance: f64,
    load: FaceLoad,
    pub(super) transform: LoadTransform,
}

/// The layer in contact with the base over r ≤ c (bilateral there, free beyond).
#[derive(Debug, Clone)]
pub struct ContactSolution {
    system: Nystrom,
    d: f64,
    compliance: f64,
}

/// The receding-contact solution: R_o, the solution there, and the cost.
#[derive(Debug, Clone)]
pub struct RecedingContact {
    /// The contact radius R_o.
    pub r_o: f64,
    /// Error estimate and cost.
    pub info: RecedingInfo,
    /// Pressure and gap at R_o.
    pub solution: ContactSolution,
}

impl ContactSolution {
    /// The contact radius c.
    pub fn radius(&self) -> f64 {
        self.system.radius()
    }

    /// φ(c): the coefficient of the 1/√(c² − r²) edge singularity of the pressure (zero for a
    /// smooth receding contact; negative means the contact zone is too large).
    pub fn edge_coefficient(&self) -> f64 {
        self.system.phi(self.radius())
    }

    /// Contact pressure q(r) ≥ 0 (pressing on the layer; the base's σ_z = −q), zero for r ≥ c.
    pub fn pressure(&self, r: f64) -> f64 {
        self.system.pressure(r.abs(), self.d)
    }

    /// Gap g(r) = w(r, 0) − w(c, 0) between the layer's bottom and the base for
    /// c < r ≤ 2c, zero inside the contact zone; in length units when E is in pressure units.
    pub fn gap(&self, r: f64) -> f64 {
        if r.abs() <= self.radius() {
            return 0.0;
        }
        self.lift(r)
    }

    /// The lift w(r, 0) − w(c, 0) for 0 ≤ r ≤ 2c (clamped there) computed from the displacement
    /// integral with the solved pressure, not from the contact condition: the gap beyond c, and
    /// inside c a residual that must vanish (a check of the solution).
    pub fn lift(&self, r: f64) -> f64 {
        let r = r.abs().min(2.0 * self.radius());
        self.compliance * self.system.lift_scaled(r)
    }

    /// The contact force 2π∫₀^c q r dr, by 40-point Gauss–Legendre in u with r = c(1 − u²)
    /// (smooth integrand for a smooth receding contact, q ~ √(c − r)). Independent of the
    /// equilibrium constraint imposed on φ, so comparing it with the load's force checks the
    /// pressure formula and its implementation.
    pub fn total_force(&self) -> f64 {
        let c = self.radius();
        2.0 * std::f64::consts::PI
            * crate::numerics::quadrature::gauss_legendre(40)
                .iter()
                .map(|&(x, w)| {
                    let u = 0.5 * (1.0 + x);
                    let r = c * (1.0 - u * u);
                    0.5 * w * self.pressure(r) * r * 2.0 * c * u
                })
                .sum::<f64>()
    }

    /// ξ-nodes of the kernel integrals.
    pub fn xi_nodes(&self) -> usize {
        self.system.xi_nodes()
    }
}

impl Layer {
    /// A layer of thickness `d` (> 0) of `material` pressed by `load` on its top face.
    pub fn new(d: f64, material: Material, load: FaceLoad) -> Result<Self, InputError> {
        positive("plate thickness D", d)?;
        let compliance = (1.0 - material.poisson_ratio()) / material.shear_modulus();
        Ok(Self::stacked(Stack::single(d), compliance, load))
    }

    /// The layer of `stack`'s kernels with interface compliance `compliance`: one layer, or
    /// the two plates of [`super::pair::Pair`] (thicknesses already checked).
    pub(super) fn stacked(stack: Stack, compliance: f64, load: FaceLoad) -> Self {
        let transform = LoadTransform::new(&load);
        Self {
            d: stack.thinnest(),
            stack,
            compliance,
            load,
            transform,
        }
    }

    /// Thickness D.
    pub fn thickness(&self) -> f64 {
        self.d
    }

    /// The top-face load.
    pub fn load(&self) -> &FaceLoad {
        &self.load
    }

    /// The layer in bilateral contact over r ≤ `c` (no contact beyond), solved with
    /// [`nodes`]`(params, c/D)` points: the building block of [`Self::receding_contact`].
    pub fn contact_over(
        &self,
        c: f64,
        params: &RecedingParams,
    ) -> Result<ContactSolution, RecedingError> {
        self.check(params)?;
        positive("contact radius c", c)?;
        let n = nodes(params, c / self.d)?;
        self.solve(&self.rule(c, params.quad_tol), c, n)
    }

    fn check(&self, params: &RecedingParams) -> Result<(), InputError> {
        if params.min_nodes < 4 {
            return Err(InputError::Parameter {
                field: "Nystrom min_nodes",
                value: params.min_nodes as f64,
                reason: "at least 4 points",
            });
        }
        if !(0.0..=1e3).contains(&params.nodes_per_thickness) {
            return Err(InputError::Parameter {
                field: "Nystrom nodes_per_thickness",
                value: params.nodes_per_thickness,
                reason: "between 0 and 1000",
            });
        }
        positive("R_o relative tolerance", params.rel_tol)?;
        positive("quadrature tolerance", params.quad_tol)?;
        positive("scan step", params.step)?;
        positive("scan reach", params.reach)?;
        Ok(())
    }

    /// A ξ-rule for contact radii up to `cap`: ω covers cos ξ(t ± s) (≤ 2c), p̄'s J₁(ξB)·cos ξt
    /// (≤ B + c) and the gap's J₀(ξr) for r ≤ 2c.
    pub(super) fn rule(&self, cap: f64, tol: f64) -> XiRule {
        let omega = 3.0 * cap + self.transform.outer();
        XiRule::stacked(&self.stack, &self.transform, omega, tol)
    }

    /// The system for contact radius `c` with `n` points on `rule` (built for radii ≥ c).
    pub(super) fn solve(
        &self,
        rule: &XiRule,
        c: f64,
        n: usize,
    ) -> Result<ContactSolution, RecedingError> {
        let system = Nystrom::solve(rule.clone(), c, n, self.transform.eval(0.0))
            .ok_or(RecedingError::Singular { c })?;
        Ok(ContactSolution {
            system,
            d: self.d,
            compliance: self.compliance,
        })
    }

    /// The Nyström size n of [`Self::receding_contact`]: [`nodes`] for a contact radius of
    /// B + 2D (R_o ≈ B + 0.4…1.1 D; of a stack B + 2D_max in units of D_min); an error beyond 256.
    pub fn basis_size(&self, params: &RecedingParams) -> Result<usize, InputError> {
        let reach = self.stack.thickest();
        nodes(
            params,
            self.transform.outer() / self.d + 2.0 * reach / self.d,
        )
    }

    /// The receding contact: R_o with φ(R_o) = 0, its pressure and gap, and an error estimate
    /// from a second run with ⌈3n/4⌉ points.
    pub fn receding_contact(
        &self,
        params: &RecedingParams,
    ) -> Result<RecedingContact, RecedingError> {
        let start = Instant::now();
        self.check(params)?;
        // R_o ≈ B + 0.4…1.1 D (examples/06_receding_contact.rs): size the rule for B + 2D (of
        // a stack: B + 2D_max, resolved on D_min)
        let reach = self.stack.thickest();
        let n = self.basis_size(params)?;
        let coarse_n = (3 * n).div_ceil(4).max(4);
        // one ξ-rule (it does not depend on n) for radii up to B + 2D, widened if the search
        // goes beyond: the load transform is evaluated once per node, not once per solve
        let mut cache = RuleCache {
            cap: self.transform.outer() + 2.0 * reach,
            rule: self.rule(self.transform.outer() + 2.0 * reach, params.quad_tol),
            solves: 0,
        };
        let p0 = self.transform.eval(0.0);
        let solve = |c: f64, n: usize, cache: &mut RuleCache| {
            let rule = cache.rule_for(c, self.d, |cap| self.rule(cap, params.quad_tol));
            self.solve(rule, c, n)
        };
        let b = self.transform.outer();
        let scan = Scan {
            b,
            d: self.d,
            step: params.step * self.d,
            end: b + params.reach * reach,
            tol: params.rel_tol * self.d,
            max_iterations: params.max_iterations,
        };
        let not_found = RecedingError::NotFound {
            from: b,
            to: scan.end,
        };
        let mut root_with = |n: usize, near: Option<f64>| {
            let mut edge = |c: f64| {
                Ok::<f64, RecedingError>(c * solve(c, n, &mut cache)?.edge_coefficient() / p0)
            };
            root(&mut edge, &scan, near)?.ok_or_else(|| not_found.clone())
        };
        let r_o = root_with(n, None)?;
        let coarse = root_with(coarse_n, Some(r_o))?;
        let solution = solve(r_o, n, &mut cache)?;
        let solves = cache.solves;
        let (min_pressure, min_gap) =
            unilateral(r_o, p0, |r| solution.pressure(r), |r| solution.gap(r))
                .map_err(|(what, r, value)| RecedingError::NotUnilateral { what, r, value })?;
        let info = RecedingInfo {
            min_pressure,
            min_gap,
            r_o_error: (r_o - coarse).abs() + params.rel_tol * self.d,
            r_o_coarse: coarse,
            nodes: n,
            xi_nodes: solution.xi_nodes(),
            solves,
            seconds: start.elapsed().as_secs_f64(),
        };
        Ok(RecedingContact {
            r_o,
            info,
            solution,
        })
    }
}

/// R_o and its record for a layer `d` thick under `load` on a frictionless rigid base (ν does
/// not enter R_o): [`Layer::receding_contact`] without the pressure and gap curves.
pub fn contact_radius(
    d: f64,
    load: &FaceLoad,
    params: &RecedingParams,
) -> Result<(f64, RecedingInfo), RecedingError> {
    let layer = Layer::new(d, Material::unit(0.25)?, load.clone())?;
    let c = layer.receding_contact(params)?;
    Ok((c.r_o, c.info))
}

/// The Nyström size for a contact radius of `c_over_d` thicknesses: at least `min_nodes` and
/// `nodes_per_thickness`·c/D, refused beyond 256 points. The cost of one solve grows like
/// (c/D)³ (n ∝ c/D points, ξ-nodes ∝ c/D): with the defaults B/D up to about 60 (~1 s per
/// solve, ~25 solves) is accepted; the project's plates have B/D ≲ 5 (~20 ms per R_o).
pub fn nodes(params: &RecedingParams, c_over_d: f64) -> Result<usize, InputError> {
    let per_d = (params.nodes_per_thickness * c_over_d).ceil();
    let n = (params.min_nodes as f64).max(per_d);
    if n.is_nan() || n > 256.0 {
        return Err(InputError::Parameter {
            field: "Nystrom points n",
            value: n,
            reason: "at most 256 (dense systems; B/D up to about 60): the contact zone is too many thicknesses wide",
        });
    }
    Ok(n as usize)
}
