//! The independent check of issue 4: the finite-element two-plate solver (`contact::two_plate`,
//! symmetric model: one plate on a frictionless rigid plane) against the semi-analytic receding
//! contact of `hankel::receding`, which shares no FE code.
//!
//! The Hankel solution is for an infinite plate; the FE plate ends at a free edge r = C. The
//! outer annulus beyond R_o carries no load, and its bending stiffness seen at R_o differs from
//! the infinite plate's by O((R_o/C)²) (Kirchhoff: w = a + b r² + c ln r there, and M_r(C) = 0
//! makes b ∝ c/C²). So:
//! 1. the FE–Hankel difference must fall by ≈ 4 per doubling of C where this effect dominates
//!    (C = 8R_o → 16R_o; accepted 3 to 5.5: the next term is O(C⁻⁴) and the FE's own error
//!    ~1e-5 R_o): the FE converges to the Hankel value, not to another;
//! 2. with the C-effect removed by Richardson extrapolation in C⁻² from 16R_o and 32R_o,
//!    R_∞ = R₃₂ + (R₃₂ − R₁₆)/3, the two agree within issue 4's target of 0.05 % of R_o;
//! 3. at the FE's default tolerance (0.05 %), they agree within the sum of both error
//!    estimates (the FE's propagated through the extrapolation, (4e₃₂ + e₁₆)/3): observed
//!    0.0–0.6 of that budget on five geometries.
//!
//! Measured (Nov 2026): the extrapolated differences are ~1e-5 R_o (+1.2e-5 for B = D = 1,
//! +0.9e-5 for the annulus), below the 0.05 % target but above the FE's own error estimates
//! (~2e-6 R_o at its 1e-5 tolerance). The Hankel side: error estimate < 1e-9, the displacement
//! integral flat on the contact zone to 4e-14, the slab midplane stress met to 1e-12 in the
//! bilateral limit (tests/hankel/receding_contact.rs). Independently of the Hankel solution, the FE's
//! extrapolated R_o moves with ν (+1.7e-5, +1.2e-5, −0.8e-5 relative at ν = 0, 0.3, 0.45;
//! example 06) although the exact R_o cannot (no kernel of the layer depends on ν): the
//! ~1e-5 discrepancy is an FE bias its estimate does not see at tight tolerances (at the
//! default one it is far below the estimate). The comparison within both estimates at the
//! FE tolerance 1e-5 is `within_both_error_estimates_at_1e5`, ignored until the FE's R_o error
//! estimate covers that bias.

use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::hankel::receding::{Layer, RecedingContact, RecedingParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};

/// FE R_o and its error estimate for the plate `d` thick with hole `a`, outer radius `c`, at
/// the FE tolerance `tol`.
fn fe(a: f64, load: &FaceLoad, d: f64, c: f64, tol: f64) -> (f64, f64) {
    let m = Material::unit(0.3).unwrap();
    let plate = Plate::new(d, m).unwrap();
    let joint = Joint::new(a, OuterRadius::Finite(c), plate, plate, load.clone()).unwrap();
    let params = TwoPlateParams {
        tolerance: tol,
        ..Default::default()
    };
    let s = solve(&joint, &params).unwrap();
    // (at TIGHT the FE refines until its level estimate is below the 2e-5 of R_o that every
    // two-plate estimate carries, and says not converged: `contact::two_plate`)
    assert!(s.converged || tol < 2e-5, "FE not converged at C = {c}");
    (s.r_o, s.r_o_error)
}

struct Comparison {
    hankel: RecedingContact,
    /// FE (R_o, error) at C = 8, 16, 32 R_o (the first only when asked for).
    fe: [(f64, f64); 3],
}

impl Comparison {
    /// Hankel R_o and FE at tolerance `tol` on C = 16, 32 R_o, and on 8 R_o if `signature`.
    fn new(a: f64, load: FaceLoad, d: f64, tol: f64, signature: bool) -> Self {
        let hankel = Layer::new(d, Material::unit(0.3).unwrap(), load.clone())
            .unwrap()
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let r = hankel.r_o;
        let run = |k: f64| fe(a, &load, d, k * r, tol);
        let fe = [
            if signature { run(8.0) } else { (f64::NAN, 0.0) },
            run(16.0),
            run(32.0),
        ];
        let c = Self { hankel, fe };
        println!(
            "Hankel {:.9} ± {:.1e}; FE (tol {tol:e}) {:?}; extrapolated {:.9} ({:+.1e}), budget {:.1e}",
            r,
            c.hankel.info.r_o_error,
            c.fe,
            c.extrapolated(),
            c.extrapolated() - r,
            c.budget()
        );
        c
    }

    /// (R₈ − R_H)/(R₁₆ − R_H).
    fn ratio(&self) -> f64 {
        (self.fe[0].0 - self.hankel.r_o) / (self.fe[1].0 - self.hankel.r_o)
    }

    /// R₃₂ + (R₃₂ − R₁₆)/3.
    fn extrapolated(&self) -> f64 {
        self.fe[2].0 + (self.fe[2].0 - self.fe[1].0) / 3.0
    }

    /// Both error estimates, the FE's propagated through the extrapolation.
    fn budget(&self) -> f64 {
        self.hankel.info.r_o_error + (4.0 * self.fe[2].1 + self.fe[1].1) / 3.0
    }

    fn check_target(&self) {
        let r = self.hankel.r_o;
        let ratio = self.ratio();
        assert!((3.0..=5.5).contains(&ratio), "C-effect ratio {ratio}");
        let diff = (self.extrapolated() - r).abs();
        assert!(diff <= 5e-4 * r, "FE {} vs Hankel {r}", self.extrapolated());
    }

    fn check_budget(&self) {
        let diff = (self.extrapolated() - self.hankel.r_o).abs();
        let budget = self.budget();
        assert!(diff <= budget, "difference {diff:e} > budget {budget:e}");
    }
}

/// The FE tolerance for the C-signature: 50× tighter than the 0.05 % target, so that the FE's
/// error stays below the C-effect.
const TIGHT: f64 = 1e-5;

/// Issue 4's target and the FE's default tolerance.
const DEFAULT: f64 = 5e-4;

#[test]
fn disk_load_on_a_solid_plate() {
    // A = 0: the FE mesh reaches the axis
    let load = FaceLoad::uniform(0.0, 1.0, 1.0).unwrap();
    Comparison::new(0.0, load.clone(), 1.0, TIGHT, true).check_target();
    Comparison::new(0.0, load, 1.0, DEFAULT, false).check_budget();
}

#[test]
fn annulus_with_a_tiny_hole() {
    // FE hole A = 0.001 = D/500; the Hankel plate has none, the same annular load
    let load = FaceLoad::uniform(1e-3, 1.0, 1.0).unwrap();
    Comparison::new(1e-3, load.clone(), 0.5, TIGHT, true).check_target();
    Comparison::new(1e-3, load, 0.5, DEFAULT, false).check_budget();
}

#[test]
#[ignore = "at FE tolerance 1e-5 the FE's R_o estimate is ~5x below the FE-Hankel difference"]
fn within_both_error_estimates_at_1e5() {
    for (a, d) in [(0.0, 1.0), (1e-3, 0.5)] {
        Comparison::new(a, FaceLoad::uniform(a, 1.0, 1.0).unwrap(), d, TIGHT, false).check_budget();
    }
}

#[test]
fn the_axis_pressure_of_a_solid_plate_is_finite_and_the_hankel_value() {
    // was: 2.1e9 for a mean pressure of 1 (force over the axis node's zero tributary area)
    let load = FaceLoad::uniform(0.0, 1.0, 1.0).unwrap();
    let m = Material::unit(0.3).unwrap();
    let hankel = Layer::new(1.0, m, load.clone())
        .unwrap()
        .receding_contact(&RecedingParams::default())
        .unwrap();
    let plate = Plate::new(1.0, m).unwrap();
    let joint = Joint::new(0.0, OuterRadius::Infinite, plate, plate, load).unwrap();
    let s = solve(&joint, &TwoPlateParams::default()).unwrap();
    let (fe, exact) = (s.pressure[0], hankel.solution.pressure(0.0));
    println!("q(0): FE {fe}, Hankel {exact}");
    // the nodal pressure near the axis, at the default tolerance: within 1e-3
    assert!((fe - exact).abs() < 1e-3 * exact, "FE {fe} against {exact}");
}
