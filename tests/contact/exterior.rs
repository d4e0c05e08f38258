//! The exact exterior of a cut plate (`fem::exterior`): a radial spring on the cut face.
//!
//! 1. Lamé (closed form): an annulus A ≤ r ≤ C′ with a pressure p on the hole and the spring of
//!    a free rim at C (or of an infinite plate) on its outer face has the hole displacement of the
//!    whole annulus A..C, u(A) = a A + b/A with E/(1 − ν) a − 2μ b/C² = 0 and
//!    E/(1 − ν) a − 2μ b/A² = −p (exact in 3D: u_z = −2λa z/(λ + 2μ), free faces); the FE error
//!    falls at least 8× per halving of the elements, and a free cut (no spring) misses it by far.
//! 2. Receding contact (second method, no shared code): the FE two-plate R_o of infinite plates
//!    (cut at 10B + 20D, the spring on the cut) agrees with `hankel::receding` within both error
//!    estimates at the FE tolerance 1e-5. Measured: 0.1–0.4 of both estimates at 1e-5; at 1e-6
//!    +7.1e-7 and +3.7e-7 relative on (B, D) = (0.1, 0.1) and (0.3, 0.1), 0.65 and 1.10 of both
//!    (the FE's own floor near 4e-7, issue 17 item 10; with a free cut at the same place the FE
//!    was 1.6e-4 low on the first).

use boltzone::contact::two_plate::{solve, InterfaceModel, TwoPlateParams};
use boltzone::fem::exterior::add_exterior;
use boltzone::fem::*;
use boltzone::hankel::receding::{Layer, RecedingParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};

/// FE hole displacement of the annulus 1 ≤ r ≤ `cut`, 1 thick, hole pressure 1, with the spring
/// of a rim at `rim` on the cut (None: a free cut), on `n` Q9 elements radially.
fn hole_displacement(cut: f64, rim: Option<f64>, n: usize) -> f64 {
    let m = Material::unit(0.3).unwrap();
    let r = Spacing::uniform(1.0, cut, n).unwrap();
    let z = Spacing::uniform(0.0, 1.0, 2).unwrap();
    let mesh = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }]).unwrap();
    let mut s = Supports::new(mesh.n_nodes());
    for node in mesh.bottom(0) {
        s.roller_z(node); // the midplane of a plate 2 thick
    }
    let dofs = DofMap::new(&s);
    let pattern = Pattern::new(&mesh, &dofs);
    let mut k = assemble(&mesh, &[m], &dofs, &pattern).unwrap();
    if let Some(rim) = rim {
        add_exterior(&mut k, &pattern, &mesh, &[m], &dofs, 0, rim).unwrap();
    }
    let mut loads = Loads::new(mesh.n_nodes());
    loads
        .add_side_pressure(&mesh, &mesh.inner(0), -1.0, 1.0)
        .unwrap();
    let f = Factorization::new(&k.matrix, &SolveParams::default()).unwrap();
    let u = dofs.expand(&f.solve(&dofs.gather(loads.forces())));
    u[mesh.inner(0)[0]][0]
}

/// Lamé's hole displacement of the free annulus 1..`c` (∞ allowed), hole pressure 1.
fn lame(c: f64) -> f64 {
    let m = Material::unit(0.3).unwrap();
    let (e, nu, mu) = (m.youngs_modulus(), m.poisson_ratio(), m.shear_modulus());
    let s = if c.is_finite() { c.powi(-2) } else { 0.0 };
    // E/(1 − ν) a = 2μ b s;  E/(1 − ν) a − 2μ b = −1  ⇒  2μ b (s − 1) = −1
    let b = 1.0 / (2.0 * mu * (1.0 - s));
    let a = 2.0 * mu * b * s * (1.0 - nu) / e;
    a + b
}

#[test]
fn a_cut_annulus_with_the_rims_spring_has_the_whole_annulus_hole_displacement() {
    for rim in [5.0, 30.0, f64::INFINITY] {
        let exact = lame(rim);
        let err: Vec<f64> = [8, 16, 32]
            .iter()
            .map(|&n| (hole_displacement(3.0, Some(rim), n) - exact).abs() / exact)
            .collect();
        println!("rim {rim}: relative errors {err:?}");
        assert!(err[2] < 1e-6, "rim {rim}: {err:?}");
        assert!(
            err[1] > 8.0 * err[2] && err[0] > 8.0 * err[1],
            "rim {rim}: {err:?}"
        );
        // without the spring the cut is a free rim at 3: far from the rim's answer
        let free = hole_displacement(3.0, None, 32);
        assert!(
            (free - exact).abs() > 1e-3 * exact,
            "rim {rim}: free cut {free}"
        );
    }
}

#[test]
fn infinite_plates_meet_the_receding_contact_within_both_estimates() {
    let m = Material::unit(0.3).unwrap();
    for (b, d) in [(0.1, 0.1), (0.3, 0.1), (0.1, 0.3)] {
        let load = FaceLoad::uniform(0.0, b, 1.0).unwrap();
        let hankel = Layer::new(d, m, load.clone())
            .unwrap()
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let plate = Plate::new(d, m).unwrap();
        let joint = Joint::new(0.0, OuterRadius::Infinite, plate, plate, load).unwrap();
        let params = TwoPlateParams {
            tolerance: 1e-5,
            interface: InterfaceModel::Frictionless,
            ..Default::default()
        };
        let s = solve(&joint, &params).unwrap();
        let diff = s.r_o - hankel.r_o;
        let budget = s.r_o_error + hankel.info.r_o_error;
        println!(
            "B {b} D {d}: FE {:.10} ± {:.1e} ({}), Hankel {:.10} ± {:.1e}: difference {:+.2e} = {:.2} of both",
            s.r_o,
            s.r_o_error,
            s.converged,
            hankel.r_o,
            hankel.info.r_o_error,
            diff / hankel.r_o,
            diff.abs() / budget
        );
        assert!(diff.abs() <= budget, "B {b} D {d}");
    }
}
