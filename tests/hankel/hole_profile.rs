//! The slab's traction on the hole as a Chebyshev profile in z (`hankel::hole::profile`): its
//! values at heights off its grid against direct Hankel integrals, its coefficients' decay
//! against the Bernstein ellipse predicted from the load's knots, and R_o of the plate with a
//! hole through the profile against the direct per-height route.

use boltzone::hankel::hole::plate::extended_load;
use boltzone::hankel::hole::traction::hole_tractions;
use boltzone::hankel::hole::{single_plate_separation, HoleParams, SlabSampling, TractionProfile};
use boltzone::hankel::{QuadParams, SeparationParams, Slab};
use boltzone::{FaceLoad, Material, OuterRadius, Peak, SinglePlate};

fn slab_of(load: &FaceLoad, a: f64, d: f64) -> Slab {
    let ext = extended_load(load, a, d).unwrap().unwrap();
    Slab::new(d, Material::unit(0.3).unwrap(), ext).unwrap()
}

/// Tight direct integrals: their own estimate (pessimistic: ~1e-7 where they stop at the panel
/// budget next to the face) is added to the comparison's tolerance.
fn tight() -> QuadParams {
    QuadParams {
        rel_tol: 1e-14,
        abs_tol: 1e-14,
        max_panels: 100_000,
        ..QuadParams::default()
    }
}

#[test]
fn profile_matches_direct_integrals_off_its_grid() {
    let a = 0.1;
    let cases = [
        // (load, D, radius of the cylinder): Table 1's widest and narrowest loads, a sloped
        // load (its extension has a kink at A − D), and a rim r = C near the load's edge
        (FaceLoad::uniform(a, 0.31, 1.0).unwrap(), 0.1, a),
        (FaceLoad::uniform(a, 0.13, 1.0).unwrap(), 0.2, a),
        (
            FaceLoad::triangular(a, 0.16, 1.0, Peak::AtA).unwrap(),
            0.1,
            a,
        ),
        (FaceLoad::uniform(a, 0.22, 1.0).unwrap(), 0.1, 0.35),
    ];
    for (load, d, r) in cases {
        let slab = slab_of(&load, a, d);
        let tol = 1e-8;
        let p = TractionProfile::new(&slab, r, tol, &QuadParams::default());
        assert!(p.error() <= tol, "r {r}: estimate {:e}", p.error());
        // heights between the grid points, crowded toward the face where the traction varies
        // fastest, both signs of z
        let z: Vec<f64> = (1..30)
            .map(|i| d * (1.0 - (i as f64 / 30.0).powi(3)) * if i % 3 == 0 { -1.0 } else { 1.0 })
            .collect();
        let (direct, _) = hole_tractions(&slab, r, &z, &tight());
        let mut worst: f64 = 0.0;
        for (zi, t) in z.iter().zip(&direct) {
            let (sr, tau) = p.eval(*zi);
            let diff = (sr - t.sigma_r).abs().max((tau - t.tau_rz).abs());
            worst = worst.max(diff);
            assert!(
                diff <= p.error() + t.error,
                "r {r} z/D {}: {diff:e} > {:e} + {:e}",
                zi / d,
                p.error(),
                t.error
            );
        }
        println!(
            "r {r} D {d}: M {} ({} nodes), estimate {:.1e}, largest difference {worst:.1e}",
            p.intervals(),
            p.evaluations(),
            p.error()
        );
    }
}

#[test]
fn coefficients_fall_at_the_rate_of_the_nearest_load_edge() {
    // σ_r(A, z) is analytic up to z = ±D ± i(B − A) (the load's edge seen from the hole), so its
    // Chebyshev coefficients on [−D, D] fall like ρ^(−k) with ρ the Bernstein parameter of
    // 1 + i(B − A)/D. Fit log of the running envelope (max over 8 consecutive k) against k on
    // the part above the noise, and compare with −ln ρ.
    let a = 0.1;
    for (b, d) in [(0.13, 0.2), (0.13, 0.1), (0.16, 0.1)] {
        let slab = slab_of(&FaceLoad::uniform(a, b, 1.0).unwrap(), a, d);
        let p = TractionProfile::new(&slab, a, 1e-11, &tight());
        let (sigma, _) = p.coefficients_of();
        let env: Vec<(f64, f64)> = (0..sigma.len() - 8)
            .step_by(8)
            .map(|k| {
                let m = sigma[k..k + 8].iter().fold(0.0f64, |m, c| m.max(c.abs()));
                (k as f64 + 4.0, m.ln())
            })
            .filter(|(_, l)| *l > (1e-12f64).ln() && *l < (1e-3f64).ln())
            .collect();
        assert!(env.len() >= 3, "{env:?}");
        let slope = boltzone::numerics::convergence::slope(&env);
        let predicted = -p.rho().ln();
        println!(
            "B {b} D {d}: fitted decay {slope:.4} per k, predicted {predicted:.4} (ρ {:.3})",
            p.rho()
        );
        // the envelope carries an algebraic factor k^(−α) (α ≈ 1 for a jump) too, which shifts
        // the fitted slope by ~α/k ≈ 0.02–0.03 on k = 30…60, i.e. up to ~8 % of the smallest
        // rate: allow 15 %
        assert!(
            (slope - predicted).abs() < 0.15 * predicted.abs(),
            "{slope} vs {predicted}"
        );
    }
}

#[test]
fn r_o_through_the_profile_equals_the_direct_route() {
    // Same fit, same N sequence; only the slab data differ (interpolated vs integrated at every
    // height). Both errors are estimated: the R_o's must agree within the two data errors'
    // effect, (e₁ + e₂)·P/slope, plus the search tolerance — far below the hole's own share.
    let a = 0.1;
    let sep = SeparationParams::default();
    for (b, d, outer) in [
        (0.31, 0.1, OuterRadius::Infinite),
        (0.13, 0.2, OuterRadius::Infinite),
        (0.22, 0.1, OuterRadius::Finite(0.45)),
    ] {
        let plate = SinglePlate::new(
            a,
            outer,
            d,
            Material::unit(0.3).unwrap(),
            FaceLoad::uniform(a, b, 1.0).unwrap(),
        )
        .unwrap();
        let params = HoleParams {
            max_terms: 32,
            ..HoleParams::default()
        };
        let (s1, h1) = single_plate_separation(&plate, &sep, &params).unwrap();
        let direct = HoleParams {
            slab_sampling: SlabSampling::Direct,
            ..params
        };
        let (s2, h2) = single_plate_separation(&plate, &sep, &direct).unwrap();
        assert_eq!(h1.terms, h2.terms);
        let bound = (h1.slab_error + h2.slab_error) / s1.slope.abs() + 1e-9 * s1.r_o;
        let diff = (s1.r_o - s2.r_o).abs();
        println!(
            "B {b} D {d}: R_o {:.12} vs {:.12}, diff {diff:.1e} ≤ {bound:.1e}; slab nodes {} vs {}",
            s1.r_o, s2.r_o, h1.slab_evaluations, h2.slab_evaluations
        );
        assert!(diff <= bound, "{diff:e} > {bound:e}");
        // the fits see the same data: residuals agree to the data error
        let dres = (h1.residual_max - h2.residual_max).abs();
        assert!(dres <= 2.0 * (h1.slab_error + h2.slab_error), "{dres:e}");
        // and the profile is the cheaper route
        assert!(h1.slab_evaluations < h2.slab_evaluations);
    }
}
