//! R_o: a sign change of direct σ_z(r, 0) at R_o, monotone growth with B/A, finite outputs over
//! the solver's range, clear errors outside it, and the example running on a small size.

use boltzone::hankel::{QuadParams, SeparationParams, Slab};
use boltzone::{FaceLoad, Material};

fn slab(a: f64, b: f64, d: f64) -> Slab {
    Slab::new(
        d,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(a, b, 1.0).unwrap(),
    )
    .unwrap()
}

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
        assert!(sep.error < 1e-10 * sep.r_o, "error {:e}", sep.error);
        let step = 10.0 * sep.error.max(1e-12);
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
    // D/A from 1e-1 to 1e3 (thinner slabs exceed the ξ-rule's node budget: see below),
    // B/A from 1.001 up to where (B + 12D)/D stays within the budget
    for &da in &[0.1, 1.0, 10.0, 1e3] {
        let mut last = 0.0;
        for &ba in &[1.001, 1.3, 3.1, 10.0, 100.0] {
            if ba / da > 150.0 {
                continue;
            }
            let s = slab(1.0, ba, da);
            let sep = s.separation_radius(&SeparationParams::default()).unwrap();
            assert!(sep.r_o.is_finite() && sep.error.is_finite() && sep.r_o > ba);
            assert!(sep.r_o > last, "D/A {da}: R_o not growing at B/A {ba}");
            last = sep.r_o;
            // fields far out (r = 1e3 B) are finite
            let st = s.stress(
                1e3 * ba,
                0.5 * da,
                &QuadParams {
                    max_panels: 2000,
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
fn too_thin_slabs_are_refused_with_a_clear_error() {
    let s = slab(1.0, 1e3, 1e-3);
    let e = s
        .separation_radius(&SeparationParams::default())
        .unwrap_err();
    assert!(e.to_string().contains("too thin"), "{e}");
    assert!(Slab::new(
        -1.0,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(0.1, 0.3, 1.0).unwrap()
    )
    .unwrap_err()
    .to_string()
    .contains("half-thickness D"));
}
