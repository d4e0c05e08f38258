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
//! +0.9e-5 for the annulus), below the 0.05 % target. The Hankel side: error estimate < 1e-9,
//! the displacement integral flat on the contact zone to 4e-14, the slab midplane stress met
//! to 1e-12 in the bilateral limit (tests/hankel/receding_contact.rs). Independently of the
//! Hankel solution, the FE's R_o moves with ν although the exact R_o cannot (no kernel of the
//! layer depends on ν): that is the FE's first-order error, whose coefficient depends on ν
//! (`levels_are_first_order_and_within_every_estimate` below, on infinite plates against the
//! receding contact directly). Every two-plate estimate now carries a floor of 2e-5 R_o for
//! the part of it that the level changes do not show (`contact::two_plate`), and the
//! comparison within both estimates at the FE tolerance 1e-5,
//! `within_both_error_estimates_at_1e5`, holds (it was ignored while the estimate missed it
//! ~5×).
//!
//! `levels_are_first_order_and_within_every_estimate` (ignored, ~1 min) is the study behind
//! that floor. Infinite plates without a hole; the FE cut with its exact exterior; levels 4…9
//! (h = D/16 … D/512) against the receding contact (~1e-12). What it shows (measured on 65
//! random plates, 25 of them with a hole against the semi-analytic route, 10 levels each):
//! - R_o's error is e ≈ c₁h + c₂h², with c₂ < 0 always (every plate is low at the coarse
//!   levels, −1e-4 … −3e-3 R_o at h = D/32).
//! - c₁'s sign and size depend on ν. At ν ≳ 0.35, c₁ < 0 and the error falls cleanly at rate
//!   2 (e.g. ν = 0.46, B = 0.75D: −1.0e-4, −4.8e-5, −2.3e-5, −1.1e-5), and the level
//!   changes show it. At ν ≲ 0.3, c₁ is small and positive. The two parts then cancel near
//!   levels 5–7 and leave a hump of up to +7.5e-6 R_o, which falls only 1.8–2× per level after
//!   (+3.5e-6, +2.0e-6, +1.0e-6 at levels 9–11 for B = D, ν = 0.01). At that turn the level
//!   changes are a few 1e-7: the floor covers this part.
//! - The node at the previous level's R_o ends the discrete contact zone within 0–8 % of an
//!   element of the exact R_o. Every sub-element estimator tried on the same solutions is
//!   first order, with another c₁: the gap through the first two open nodes (the one used),
//!   the next two, a three-point fit with curvature, and the pressure inside. Richardson in h
//!   with two terms, (8R_k − 6R_{k−1} + R_{k−2})/3, did not help: the sequences carry ~1e-6
//!   of irregular noise (where R_o falls in its element), and the extrapolation amplifies it.
//! - The external reference put three Table 1 joints 2.5e-6 … 1.4e-5 HIGH at
//!   `--tol 1e-6`, consistent with the positive c₁ at ν = 0.3 and below.

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

#[test]
#[ignore = "a study: ~1 min of FE levels down to h = D/512"]
fn levels_are_first_order_and_within_every_estimate() {
    // (B/D, ν): a hump at low ν, clean geometric at high ν, a wide and a narrow load
    for (b, nu) in [(1.0, 0.01), (1.0, 0.46), (0.3, 0.12), (3.0, 0.3)] {
        let (exact, joint) = super::edge_fit::plate(b, nu);
        let mut errors = Vec::new();
        for k in 4..=9 {
            let s = solve(
                &joint,
                &TwoPlateParams {
                    tolerance: 1e-12,
                    min_levels: k,
                    max_levels: k,
                    ..Default::default()
                },
            )
            .unwrap();
            let e = s.r_o - exact;
            println!(
                "B {b} nu {nu} levels {k}: R_o − exact {:+.3e} R_o, estimate {:.2e} R_o",
                e / exact,
                s.r_o_error / exact
            );
            assert!(
                e.abs() <= s.r_o_error,
                "level {k}: {e:e} beyond {:e}",
                s.r_o_error
            );
            errors.push(e);
        }
        // first order at the finest levels: each level halves h, and the error with it (2;
        // a second-order error would fall 4×, a hump not yet passed would not fall)
        let n = errors.len();
        let rate = errors[n - 2] / errors[n - 1];
        println!("B {b} nu {nu}: error ratio over the last level {rate:.2}");
        assert!((1.5..=2.5).contains(&rate), "rate {rate}");
        // the exact R_o does not depend on ν, the FE's first-order part does
        if nu < 0.05 {
            assert!(errors[n - 1] > 0.0);
        }
        if nu > 0.45 {
            assert!(errors[n - 1] < 0.0);
        }
    }
}
