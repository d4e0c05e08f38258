//! R_o of the single plate with a hole, Hankel route against the finite-element single-plate
//! model (`boltzone::fem::single`): two of Table 1's geometries with the report's rim C = 1.54 in
//! (the widest load on the thinnest-relative plate and the narrowest on the thickest), and a rim
//! so close to the load (C = B + 1.3D, R_o within 0.05 of C) that the rim correction matters
//! (it moves R_o by 3 %). The models are independent (eigenfunctions and Hankel integrals vs
//! graded Q9 meshes, error from the level changes); the issue asks for 0.05 %.

use boltzone::fem::single::{single_plate_r_o, SingleParams};
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::SeparationParams;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

#[test]
fn hankel_with_hole_agrees_with_finite_elements_on_table1() {
    let a = 0.1;
    for (a_over_d, b_over_a, c) in [(1.0, 3.1, 1.54), (0.5, 1.3, 1.54), (1.0, 2.2, 0.35)] {
        let (d, b) = (a / a_over_d, a * b_over_a);
        let load = FaceLoad::uniform(a, b, 1.0).unwrap();
        let mat = Material::unit(0.3).unwrap();
        let plate = SinglePlate::new(a, OuterRadius::Finite(c), d, mat, load).unwrap();
        let fe_params = SingleParams {
            levels: 5,
            ..SingleParams::default()
        };
        let (r_fe, fe) = single_plate_r_o(&plate, &fe_params).unwrap();
        let (hk, hole) =
            single_plate_separation(&plate, &SeparationParams::default(), &HoleParams::default())
                .unwrap();
        let diff = (hk.r_o - r_fe).abs();
        println!(
            "A/D {a_over_d} B/A {b_over_a} C {c}: hankel {:.7} ± {:.1e} (N {}), fem {:.7} ± {:.1e}",
            hk.r_o / a,
            hk.r_o_error / a,
            hole.terms,
            r_fe / a,
            fe.error_estimate / a
        );
        assert!(
            diff <= 5e-4 * r_fe,
            "differ by {:.4} %",
            100.0 * diff / r_fe
        );
        // Each model's estimate bounds its own error (their module docs; measured here
        // diff/(sum of estimates) = 0.30, 0.06, 0.10): the difference is within their sum.
        assert!(diff <= hk.r_o_error + fe.error_estimate, "{diff:e}");
    }
}
