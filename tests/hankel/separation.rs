//! R_o: a sign change of direct σ_z(r, 0) at R_o, monotone growth with B/A, finite outputs over
//! the solver's range, the thin-slab route against the ξ-route, and clear input errors.

use boltzone::hankel::{realspace, Midplane, MidplaneRule, QuadParams, SeparationParams, Slab};
use boltzone::{FaceLoad, Material};

use crate::common;
use common::uniform_slab as slab;

#[test]
fn r_o_is_the_first_upward_zero_of_direct_midplane_stress() {
    // checked with the adaptive quadrature, a route independent of the shared-node rule
    let p = QuadParams {
        rel_tol: 1e-14,
        ..Default::default()
    };
    for &(b, d) in &[(0.31, 0.1), (0.13, 0.2), (0.16, 0.1333333333333333)] {
        let s = slab(0.1, b, d);
        let sep = s.separation_radius(&SeparationParams::default()).unwrap();
        assert!(sep.r_o_error < 1e-10 * sep.r_o, "error {:e}", sep.r_o_error);
        let step = 10.0 * sep.r_o_error.max(1e-12);
        assert!(s.sigma_z(sep.r_o - step, 0.0, &p).value < 0.0);
        assert!(s.sigma_z(sep.r_o + step, 0.0, &p).value > 0.0);
        // compressive all the way from B to R_o (the FIRST upward crossing)
        for k in 0..50 {
            let r = b + (sep.r_o - b) * k as f64 / 50.0;
            assert!(s.sigma_z(r, 0.0, &p).value < 0.0, "r = {r}");
        }
    }
}

#[test]
fn stability_sweep_is_finite_and_monotone_in_b() {
    // D/A ∈ [1e-3, 1e3], B/A ∈ [1.001, 1e3]: R_o finite, beyond B, with a finite error, and
    // growing with B/A; midplane σ_z and the full stress finite out to r = 1e3·B
    for &da in &[1e-3, 1e-1, 1.0, 10.0, 1e3] {
        let mut last = 0.0;
        for &ba in &[1.001, 1.3, 3.1, 10.0, 1e3] {
            let s = slab(1.0, ba, da);
            let sep = s.separation_radius(&SeparationParams::default()).unwrap();
            assert!(sep.r_o.is_finite() && sep.r_o_error.is_finite() && sep.r_o > ba);
            assert!(
                sep.r_o_error < 1e-9 * sep.r_o,
                "D/A {da} B/A {ba}: error {:e}",
                sep.r_o_error
            );
            assert!(sep.r_o > last, "D/A {da}: R_o not growing at B/A {ba}");
            last = sep.r_o;
            let far = Midplane::new(&s, 1e3 * ba, 1e-12).unwrap();
            for r in [0.0, 0.5 * ba, ba, 2.0 * ba, 1e3 * ba] {
                let e = far.eval(r);
                assert!(
                    e.value.is_finite() && e.error.is_finite(),
                    "D/A {da} B/A {ba} r {r}"
                );
            }
            let st = s.stress(
                1e3 * ba,
                0.5 * da,
                &QuadParams {
                    max_panels: 500,
                    ..Default::default()
                },
            );
            for e in [st.sigma_r, st.sigma_theta, st.sigma_z, st.tau_rz] {
                assert!(e.value.is_finite() && !e.error.is_nan());
            }
        }
    }
}

#[test]
fn thin_slabs_switch_to_real_space_and_reach_the_strip_limit() {
    // the ξ-rule refuses (B + 12D)/D ≈ 1e6 with an error naming the cause; the midplane
    // evaluator switches to the real-space route. For D ≪ B the load edge is locally a
    // plane-strain strip edge, so (R_o − B)/D tends to a constant: B/A = 10 and 1000 agree.
    let s = slab(1.0, 1e3, 1e-3);
    let e = MidplaneRule::new(&s, 1e3 + 12e-3, 1e-12).unwrap_err();
    assert!(e.to_string().contains("too thin"), "{e}");
    assert!(matches!(
        Midplane::new(&s, 1e3, 1e-12).unwrap(),
        Midplane::RealSpace { .. }
    ));
    let gap = |ba: f64| {
        let sep = slab(1.0, ba, 1e-3)
            .separation_radius(&SeparationParams::default())
            .unwrap();
        (sep.r_o - ba) / 1e-3
    };
    let (g10, g1000) = (gap(10.0), gap(1e3));
    // the curvature correction is O(D/B) = 1e-4 at B/A = 10
    assert!((g10 - g1000).abs() < 1e-3 * g1000, "{g10} vs {g1000}");
    // uniform load over r ≤ B, B/D = 1e3: σ_z(0, 0) = −P up to e^(−2.1·1000)
    let wide = Slab::new(
        1e-3,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(0.0, 1.0, 1.0).unwrap(),
    )
    .unwrap();
    let c = Midplane::new(&wide, 1.0, 1e-12).unwrap().eval(0.0);
    assert!((c.value + 1.0).abs() <= c.error && c.error < 1e-10, "{c:?}");
}

#[test]
fn real_space_and_xi_routes_agree() {
    // two independent routes to σ_z(r, 0): the real-space point kernel (tabulated once) and
    // the ξ-rule; each within the sum of the two error estimates
    for &(a, b, d) in &[
        (0.1, 0.31, 0.1),
        (0.1, 1.0, 0.02),
        (1.0, 3.0, 10.0),
        (0.0, 1.0, 0.01),
    ] {
        let s = Slab::new(
            d,
            Material::unit(0.3).unwrap(),
            FaceLoad::uniform(a, b, 1.0).unwrap(),
        )
        .unwrap();
        let rule = MidplaneRule::new(&s, b + 10.0 * d, 1e-14).unwrap();
        for r in [0.0, 0.5 * b, b - d, b, b + d, b + 3.0 * d] {
            let x = realspace::midplane_sigma_z(s.transform(), d, r);
            let y = rule.eval(r);
            assert!(
                (x.value - y.value).abs() <= x.error + y.error,
                "({a},{b},{d}) r={r}"
            );
            assert!(x.error < 1e-10);
        }
    }
}

#[test]
fn bad_input_is_named() {
    assert!(Slab::new(
        -1.0,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(0.1, 0.3, 1.0).unwrap()
    )
    .unwrap_err()
    .to_string()
    .contains("half-thickness D"));
    let s = slab(0.1, 0.3, 0.1);
    let e = s.separation_radius(&SeparationParams {
        rel_tol: -1.0,
        ..Default::default()
    });
    assert!(e
        .unwrap_err()
        .to_string()
        .contains("R_o relative tolerance"));
}

#[test]
fn point_kernel_matches_mpmath() {
    // g(x) = (1/2π)∫ t K(t) J₀(tx) dt by mpmath 1.3 (quad / quadosc, 30 digits)
    for (x, want) in [
        (0.0, 0.822_520_724_830_781_4),
        (2.0, -0.006_000_936_701_794_124),
    ] {
        let g = realspace::point_kernel(x);
        assert!(
            (g - want).abs() <= realspace::point_kernel_error(),
            "g({x}) = {g} vs {want}"
        );
    }
    assert!(realspace::point_kernel_error() < 1e-13);
}

#[test]
fn triangular_loads_separate_beyond_the_load() {
    // report Figs. 19–20: the peak at A concentrates the load inward, so R_o is smaller than
    // for the peak at B (same force); both across the thickness range
    for &da in &[1e-3, 0.1, 1.0, 1e3] {
        let r_o = |peak| {
            let load = FaceLoad::triangular(1.0, 3.1, 1.0, peak).unwrap();
            let s = Slab::new(da, Material::unit(0.3).unwrap(), load).unwrap();
            let sep = s.separation_radius(&SeparationParams::default()).unwrap();
            assert!(
                sep.r_o > 3.1 && sep.r_o_error < 1e-9 * sep.r_o,
                "D/A {da}: {sep:?}"
            );
            sep.r_o
        };
        let (at_a, at_b) = (r_o(boltzone::Peak::AtA), r_o(boltzone::Peak::AtB));
        assert!(at_a < at_b, "D/A {da}: {at_a} vs {at_b}");
    }
}
