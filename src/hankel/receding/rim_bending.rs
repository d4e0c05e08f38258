//! The exact axisymmetric states of a free-faced plate that do not decay in r — membrane and
//! bending, each leaving a hole r = A traction-free — and the far-field moment and force of a
//! solution from its face tractions alone (Betti's reciprocity): the pieces a finite rim r = C
//! of the two-plate model needs ([`super::rim`]).
//!
//! **States** (plate A ≤ r, 0 ≤ z ≤ D, ζ = z − D/2, faces σ_z = τ_rz = 0, G, ν; compression
//! negative, u_z upward; per unit curvature or strain):
//! - *bending*: uniform bending u_r = rζ, u_z = −r²/2 − ν/(1−ν)ζ² plus log bending
//!   u_r = kζ/r, u_z = −k ln r with k = A²(1+ν)/(1−ν), so that
//!   σ_r = 2Gζ[(1+ν)/(1−ν) − k/r²] vanishes on the hole; σ_θ = 2Gζ[(1+ν)/(1−ν) + k/r²],
//!   σ_z = τ_rz = 0 (γ_rz = 0; the trace 2ζ(1−2ν)/(1−ν) makes σ_z vanish);
//!   M_r = ∫σ_rζ dz = (GD³/6)[(1+ν)/(1−ν) − k/r²] (the Kirchhoff D_f(1+ν) at k = 0, with
//!   D_f = GD³/(6(1−ν)));
//! - *membrane*: u_r = r + b/r, u_z = −2νz/(1−ν), b = A²(1+ν)/(1−ν): σ_r = 2G[(1+ν)/(1−ν) − b/r²],
//!   σ_z = τ_rz = 0; on the plane z = 0 it moves nothing vertically and carries no σ_z, so it
//!   leaves a frictionless contact alone.
//!
//! **Far field by reciprocity.** A solution S on A ≤ r < ∞ with a free hole and face tractions
//! p (top, pressing) and q (bottom, pressing), ∫p = ∫q, decays at large r into
//! u_z = −k_S ln r (log bending, M_r = −GD³k_S/(6r²)), u_r = b_S/r (membrane,
//! N_r = −2GDb_S/r²), a rigid translation and Papkovich–Fadle modes. Betti between S and the
//! bending state E over A ≤ r ≤ R: E is free on the faces and the hole, S on the hole, so the
//! face work of S on E's displacements equals minus the rim bilinear form
//! B(S, E) = ∫(σ_r^S u_r^E − σ_r^E u_r^S) 2πR dz, which is independent of R and vanishes for
//! decaying modes and between two log states; with log bending it is −2πGD³k_S/(3(1−ν)):
//!
//! k_S = −(3(1−ν)/(GD³)) ∫_A^∞ (q − p)(r²/2 + k ln r) r dr.
//!
//! At A = 0 this is the Kirchhoff plate's w = (3(1−ν)/(2GD³)) ln r ∫(q − p) r³ dr (the
//! biharmonic Green function r² ln r/(8πD_f), ring-averaged). The same with the membrane state
//! gives b_S = νP/(4πG) (P = 2π∫p r dr), N_r(C) = −νPD/(2πC²): the through-thickness squeeze
//! spreads the plate radially.
//!
//! # Accuracy
//!
//! `tests/hankel/two_plate_rim_hankel.rs`: the states' stresses, equilibrium, face and hole
//! conditions by central differences of the displacements through Hooke's law
//! (`the_rim_states_are_exact`, tolerances from the differences' truncation); the membrane
//! state on the plane (`the_membrane_state_leaves_the_plane_alone`); the far-field coefficient
//! at A = 0 against the Kirchhoff plate's biharmonic Green function ring-averaged
//! (`the_far_field_is_the_kirchhoff_green_function`: 1e-12); at A > 0 against the Kirchhoff
//! annular plate with a free hole solved as an ODE (two rings, 7 × 7 system:
//! `the_far_field_with_a_hole_is_the_kirchhoff_annular_plate`, agreement 1e-10, where the
//! hole's k ln r term moves k by 16 %); and through the holed rim route against the FE meshed
//! to C. From the 3D stress field (`tests/hankel/rim_moment_fields.rs`): the receding solution
//! without a hole, σ_r at two Gauss heights from the layer's Hankel kernels
//! ([`super::layer_field`]) with the solved contact pressure, integrated through the thickness,
//! gives M_r and N_r at r = 8, 10, 12 D equal to [`RimStates::log_moment`] and
//! [`RimStates::far_field_force`] to 1e-12–7e-12 (held to 1e-9). With the hole this check is
//! not done: the hole correction's fields (whose non-decaying part is the k ln r term) are not
//! reachable outside the holed route.
//!
//! # Cost
//!
//! Closed forms: a few flops per call (example 19 prints the rim moment).
//!
//! ```
//! use boltzone::Material;
//! use boltzone::hankel::receding::rim_bending::RimStates;
//! let s = RimStates::new(0.1, 0.1, Material::unit(0.3)?)?;
//! // the hole is free and the faces too
//! assert!(s.bending_stress(0.1, 0.03)[0].abs() < 1e-15);
//! assert!(s.bending_stress(0.2, 0.1)[3] == 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};
use crate::material::Material;

/// The non-decaying free-faced states of a plate with a free hole (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RimStates {
    a: f64,
    d: f64,
    nu: f64,
    g: f64,
}

impl RimStates {
    /// The states of a plate `d` thick (> 0) with hole radius `a` (≥ 0, 0 for a solid plate).
    pub fn new(a: f64, d: f64, material: Material) -> Result<Self, InputError> {
        positive("plate thickness D", d)?;
        if !(a >= 0.0 && a.is_finite()) {
            return Err(InputError::Parameter {
                field: "hole radius A",
                value: a,
                reason: "finite and at least 0",
            });
        }
        Ok(Self {
            a,
            d,
            nu: material.poisson_ratio(),
            g: material.shear_modulus(),
        })
    }

    /// (1 + ν)/(1 − ν).
    fn ratio(&self) -> f64 {
        (1.0 + self.nu) / (1.0 - self.nu)
    }

    /// k = A²(1+ν)/(1−ν): the log-bending (and membrane b) coefficient that frees the hole.
    pub fn log_ratio(&self) -> f64 {
        self.a * self.a * self.ratio()
    }

    /// The bending state's displacement (u_r, u_z) at (r, z), per unit curvature.
    pub fn bending_displacement(&self, r: f64, z: f64) -> [f64; 2] {
        let zeta = z - 0.5 * self.d;
        let k = self.log_ratio();
        [
            r * zeta + k * zeta / r,
            -0.5 * r * r - self.nu / (1.0 - self.nu) * zeta * zeta - k * r.ln(),
        ]
    }

    /// The bending state's stresses [σ_r, σ_θ, σ_z, τ_rz] at (r, z), per unit curvature.
    pub fn bending_stress(&self, r: f64, z: f64) -> [f64; 4] {
        let zeta = z - 0.5 * self.d;
        let k = self.log_ratio() / (r * r);
        let s = 2.0 * self.g * zeta;
        [s * (self.ratio() - k), s * (self.ratio() + k), 0.0, 0.0]
    }

    /// The bending state's M_r = ∫σ_r (z − D/2) dz at r, per unit curvature (zero at r = A).
    pub fn bending_moment(&self, r: f64) -> f64 {
        self.g * self.d.powi(3) / 6.0 * (self.ratio() - self.log_ratio() / (r * r))
    }

    /// M_r at r of log bending u_z = −k ln r (the far field of a solution, k from
    /// [`Self::far_field_log`]).
    pub fn log_moment(&self, k: f64, r: f64) -> f64 {
        -self.g * self.d.powi(3) * k / (6.0 * r * r)
    }

    /// u_z(r, 0) of the bending state on the plane z = 0 up to a constant: −r²/2 − k ln r.
    pub fn plane_displacement(&self, r: f64) -> f64 {
        -0.5 * r * r - self.log_ratio() * r.ln()
    }

    /// The membrane state's displacement (u_r, u_z) at (r, z), per unit strain.
    pub fn membrane_displacement(&self, r: f64, z: f64) -> [f64; 2] {
        [
            r + self.log_ratio() / r,
            -2.0 * self.nu / (1.0 - self.nu) * z,
        ]
    }

    /// The membrane state's stresses [σ_r, σ_θ, σ_z, τ_rz] at (r, z), per unit strain.
    pub fn membrane_stress(&self, r: f64, _z: f64) -> [f64; 4] {
        let b = self.log_ratio() / (r * r);
        let s = 2.0 * self.g;
        [s * (self.ratio() - b), s * (self.ratio() + b), 0.0, 0.0]
    }

    /// The far-field log-bending coefficient k_S of a solution whose face tractions q − p
    /// (bottom minus top, pressing positive) have the moments `second` = ∫(q − p) r³ dr and
    /// `log` = ∫(q − p) r ln r dr over A ≤ r (module docs).
    pub fn far_field_log(&self, second: f64, log: f64) -> f64 {
        -3.0 * (1.0 - self.nu) / (self.g * self.d.powi(3)) * (0.5 * second + self.log_ratio() * log)
    }

    /// N_r at r of the far-field membrane state of a solution pressed by the total force
    /// `force` = 2π∫p r dr: −νPD/(2πr²).
    pub fn far_field_force(&self, force: f64, r: f64) -> f64 {
        -self.nu * force * self.d / (2.0 * std::f64::consts::PI * r * r)
    }
}
