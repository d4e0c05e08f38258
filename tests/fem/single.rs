//! Single-plate model by FE (src/fem/single.rs).
//!
//! References: (1) convergence: nested refinements must contract; (2) a second element family
//! (the report's 4-CST quadrilateral, B-bar Q4) must agree with Q9 within the two error
//! estimates; (3) the report's Table 1 single-plate column within its resolution, one nodal
//! interval of 0.015 in, i.e. 0.15 in R_o/A (A = 0.1 in); (4) equilibrium: the midplane traction
//! carries the applied force.

use boltzone::fem::single::{
    coarse_radial_spacing, single_plate_r_o, solve_midplane, FaceCondition, Refinement,
    SingleParams,
};
use boltzone::fem::{ElementKind, SolveParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

fn table1_plate(a_over_d: f64, b_over_a: f64) -> SinglePlate {
    let a = 0.1;
    let load = FaceLoad::uniform(a, a * b_over_a, 1.0).unwrap();
    SinglePlate::new(
        a,
        OuterRadius::Finite(1.54),
        a / a_over_d,
        Material::unit(0.3).unwrap(),
        load,
    )
    .unwrap()
}

#[test]
fn table1_row_converges_and_matches_the_report_within_its_mesh_spacing() {
    let row = boltzone::reference::table1()
        .into_iter()
        .find(|r| r.a_over_d == 0.5 && r.b_over_a == 2.2)
        .unwrap();
    let plate = table1_plate(row.a_over_d, row.b_over_a);
    let params = SingleParams {
        levels: 5,
        ..SingleParams::default()
    };
    let (r_o, info) = single_plate_r_o(&plate, &params).unwrap();
    let v = &info.levels;
    // successive differences contract by at least 2 per level (graded levels; measured 4–11)
    for w in v.windows(3) {
        assert!((w[2] - w[1]).abs() < 0.5 * (w[1] - w[0]).abs(), "{v:?}");
    }
    assert!(info.error_estimate < 5e-4 * r_o, "{info:?}");
    assert!(
        (r_o / 0.1 - row.single).abs() < 0.15,
        "R_o/A = {} vs report {}",
        r_o / 0.1,
        row.single
    );

    // a second element family, with its own refinement study, agrees within both estimates
    for kind in [ElementKind::Cst4, ElementKind::Q4Bbar] {
        let p = SingleParams {
            kind,
            refinement: Refinement::Uniform,
            levels: 5,
            coarse_size: 0.5,
            ..SingleParams::default()
        };
        let (r2, i2) = single_plate_r_o(&plate, &p).unwrap();
        assert!(
            (r2 - r_o).abs() <= 2.0 * (i2.error_estimate + info.error_estimate),
            "{kind:?}: {r2} ± {} vs Q9 {r_o} ± {}: {:?}",
            i2.error_estimate,
            info.error_estimate,
            i2.levels
        );
    }
}

#[test]
fn midplane_traction_carries_the_applied_force() {
    let plate = table1_plate(1.0, 2.2);
    let params = SingleParams::default();
    let radial = coarse_radial_spacing(&plate, &params).unwrap().refined(2);
    let m = solve_midplane(
        &plate,
        FaceCondition::Pressure,
        ElementKind::Q9,
        &radial,
        4,
        &SolveParams::default(),
    )
    .unwrap();
    // ∫ σ_z 2πr dr over the midplane = −F; integrate the nodal values with the edges' Simpson
    // rule (σ_z·r is a cubic on each edge: Simpson is exact)
    let mut total = 0.0;
    for i in (0..m.r.len() - 2).step_by(2) {
        let h = m.r[i + 2] - m.r[i];
        let f = |k: usize| m.sigma_z[k] * m.r[k];
        total += 2.0 * std::f64::consts::PI * h / 6.0 * (f(i) + 4.0 * f(i + 1) + f(i + 2));
    }
    let f = plate.load().total_force();
    // the recovered traction is the exact L2 projection of the reactions, whose sum is exactly
    // −F; Simpson integrates N_i·r exactly, so only round-off remains
    assert!((total + f).abs() < 1e-10 * f, "{total} vs {f}");
}

#[test]
fn bad_parameters_are_rejected() {
    let plate = table1_plate(1.0, 2.2);
    let p = SingleParams {
        levels: 1,
        ..SingleParams::default()
    };
    assert!(single_plate_r_o(&plate, &p)
        .unwrap_err()
        .to_string()
        .contains("refinement levels"));
    let p = SingleParams {
        coarse_size: -1.0,
        ..SingleParams::default()
    };
    assert!(single_plate_r_o(&plate, &p).is_err());
}
