//! Two unequal plates without a hole, frictionless interface: the report's two-plate model
//! (Ch. II.B) for plates of different thickness and material, by the receding-contact solver
//! of [`super::contact`] with the kernels of the two plates in series — a semi-analytic
//! reference for the finite-element two-plate solver that shares no FE code.
//!
//! **Problem.** Upper plate 0 ≤ z ≤ D₁ (E₁, ν₁), lower plate −D₂ ≤ z ≤ 0 (E₂, ν₂), both
//! infinite, no hole (A = 0). The upper plate's top face is pressed down by p(r), the lower
//! plate's bottom face up by the same p(r) (the bolt's head and nut, equal and opposite); the
//! outer faces carry no shear. The interface z = 0 is frictionless and unilateral: contact
//! pressure q(r) ≥ 0 on r ≤ R_o, an opening gap beyond. p and q are positive in compression
//! (they press on the plates; σ_z = −q at the interface); lengths in any unit, R_o in the same.
//!
//! **Derivation.** Each plate is a layer loaded by normal tractions only: p on its outer face
//! and q on its interface face, no shear on either (the interface is frictionless). By
//! [`super::layer`] the upper plate's interface face moves up by
//! w₁(r) = c₁∫₀^∞ [q̄ M_q(ξD₁) − p̄ M_p(ξD₁)] J₀(ξr) dξ, cᵢ = (1 − νᵢ)/Gᵢ. The lower plate is
//! the mirror image (z → −z) of such a layer, so its interface face moves *down* by
//! c₂∫[q̄ M_q(ξD₂) − p̄ M_p(ξD₂)] J₀ dξ. The gap between the faces is therefore
//! g(r) = g₀ + (c₁ + c₂)∫[q̄ M̂_q − p̄ M̂_p] J₀ dξ, M̂ = λ₁M(ξD₁) + λ₂M(ξD₂),
//! λᵢ = cᵢ/(c₁ + c₂), with g₀ the plates' rigid approach. Contact (g = 0 on r ≤ R_o, g ≥ 0
//! beyond, q ~ √(R_o − r) at a smooth receding edge) is then exactly the layer-on-rigid-base
//! problem of [`super::contact`] with its kernels replaced by the weighted sums
//! ([`super::layer::Stack`]) and its compliance by c₁ + c₂: since λ₁ + λ₂ = 1, M̂_q → 1 as
//! ξ → ∞ (two half-spaces in contact, Boussinesq) and the bounded part M̂_q − 1 − M̂_p =
//! Σλᵢ(S(ξDᵢ) − 1) keeps the solver's form; as ξ → 0, M̂_p ≈ M̂_q ≈ Σλᵢ 6/(ξDᵢ)³, i.e.
//! w̄ → (q̄ − p̄)(1/𝒟₁ + 1/𝒟₂)/ξ⁴ (two Kirchhoff plates bending in series), made integrable,
//! as for one layer, by the equilibrium q̄(0) = p̄(0) — which holds for each plate on its own,
//! since each carries only p and q. The unknown constant of the solver is the rigid approach
//! g₀. Receding contact of a layer on a half-space or on a second layer: Keer, Dundurs & Tsai
//! 1972, *J. Appl. Mech.* 39, 1115–1120; Gladwell 1976, *Int. J. Eng. Sci.* 14, 899–907.
//!
//! Consequences: R_o depends on D₁, D₂, the load's shape and the compliance ratio c₂/c₁ only
//! (not on the load's scale; on ν only through cᵢ); swapping the plates leaves it unchanged;
//! equal plates (λ = ½, ½) are the one layer on a rigid base of [`Layer`] bit for bit; c₂ → 0
//! (E₂ → ∞ at fixed D₂) is the upper plate on a rigid base. A thick lower plate (D₂ → ∞) is a
//! half-space, *not* a rigid base.
//!
//! **Discretisation.** That of [`super::contact`] (Nyström, geometric in the basis size; error
//! estimate from the ⌈3n/4⌉-point run) with the kernels' length scale the thinner plate's D
//! (their ξ-decay e^(−ξD_min) sets the ξ-rule and the points per length) and the scan's reach
//! the thicker plate's.
//!
//! # Accuracy
//!
//! `tests/hankel/receding_pair.rs`: equal plates against the one layer (bit for bit), the swap
//! identity, force balance of q against the load (1e-10), geometric convergence in the basis
//! size with its observed rate, the rigid-base limit E₂ → ∞, and the finite elements
//! (`contact::two_plate`, frictionless, unequal plates) within their error bar.
//!
//! # Cost
//!
//! That of one layer with the points per length set by the thinner plate: measured (release,
//! `two --method hankel --a 0 --d 1 --d2 0.5`, machine load 5 on 2 cores) 0.11 s at B = 0.3,
//! 0.2 s at B = 1, 0.7 s at B = 3 and 4.4 s at B = 8 (n = 19, 24, 40, 80 points); route
//! `two0u` of example 16 runs it beside the FE.
//!
//! ```
//! use boltzone::{FaceLoad, Material, Plate};
//! use boltzone::hankel::receding::{Layer, Pair, RecedingParams};
//! let load = FaceLoad::uniform(0.0, 1.0, 1.0)?;
//! let (steel, alu) = (Material::new(2.0e5, 0.3)?, Material::new(7.0e4, 0.33)?);
//! let pair = Pair::new(Plate::new(1.0, steel)?, Plate::new(0.5, alu)?, load.clone());
//! let params = RecedingParams::default();
//! let c = pair.receding_contact(&params)?;
//! assert!(c.r_o > 1.0 && c.info.r_o_error < 1e-8);
//! // a much stiffer lower plate is (almost) the rigid base under the upper plate
//! let rigid = Layer::new(1.0, steel, load.clone())?.receding_contact(&params)?;
//! let rigid_ish = Plate::new(0.5, Material::new(2.0e11, 0.3)?)?;
//! let stiff = Pair::new(Plate::new(1.0, steel)?, rigid_ish, load);
//! assert!((stiff.receding_contact(&params)?.r_o - rigid.r_o).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::contact::{ContactSolution, Layer, RecedingContact, RecedingError, RecedingParams};
use super::layer::Stack;
use crate::joint::Plate;
use crate::load::FaceLoad;

/// Two plates in frictionless contact, pressed together by the same load on their outer faces.
#[derive(Debug, Clone)]
pub struct Pair {
    upper: Plate,
    lower: Plate,
    layer: Layer,
}

impl Pair {
    /// The `upper` plate pressed by `load` on its top face and the `lower` plate by the same
    /// load on its bottom face (plates and load are checked by their constructors).
    pub fn new(upper: Plate, lower: Plate, load: FaceLoad) -> Self {
        let compliance = |p: &Plate| {
            let m = p.material();
            ((1.0 - m.poisson_ratio()) / m.shear_modulus(), p.thickness())
        };
        let (c1, c2) = (compliance(&upper), compliance(&lower));
        let stack = Stack::pair(c1, c2);
        Self {
            upper,
            lower,
            layer: Layer::stacked(stack, c1.0 + c2.0, load),
        }
    }

    /// The upper plate.
    pub fn upper(&self) -> Plate {
        self.upper
    }

    /// The lower plate.
    pub fn lower(&self) -> Plate {
        self.lower
    }

    /// The load on each outer face.
    pub fn load(&self) -> &FaceLoad {
        self.layer.load()
    }

    /// The Nyström size of [`Self::receding_contact`] ([`Layer::basis_size`]): an error when the
    /// contact zone is too many thinner-plate thicknesses wide (B/D_min beyond about 50).
    pub fn basis_size(&self, params: &RecedingParams) -> Result<usize, crate::error::InputError> {
        self.layer.basis_size(params)
    }

    /// The plates in contact over r ≤ `c` (bilateral there, open beyond); the solution's gap is
    /// the opening between the two faces.
    pub fn contact_over(
        &self,
        c: f64,
        params: &RecedingParams,
    ) -> Result<ContactSolution, RecedingError> {
        self.layer.contact_over(c, params)
    }

    /// The receding contact: R_o, the interface pressure and the gap between the plates, with
    /// the error estimate of [`Layer::receding_contact`].
    pub fn receding_contact(
        &self,
        params: &RecedingParams,
    ) -> Result<RecedingContact, RecedingError> {
        self.layer.receding_contact(params)
    }
}
