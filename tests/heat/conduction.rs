//! Axisymmetric conduction on the FE meshes (src/heat/conduction.rs) against closed forms.

use boltzone::fem::{ElementKind, Mesh, PlateSpec, Spacing};
use boltzone::heat::conduction::solve_conduction;
use std::f64::consts::PI;

fn fix(nodes: Vec<usize>, t: f64) -> Vec<(usize, f64)> {
    nodes.into_iter().map(|n| (n, t)).collect()
}

#[test]
fn two_plates_with_a_uniform_interface_conductance_match_the_series_resistance() {
    // Plate 0: D1 = 0.3, k1 = 2; plate 1: D2 = 0.5, k2 = 7; h = 4; bottom at -10, top at 30;
    // hole and rim insulated: T is linear in z in each plate, which both elements represent
    // exactly, so only rounding remains.
    let (d1, d2, k1, k2, h) = (0.3, 0.5, 2.0, 7.0, 4.0);
    for kind in [ElementKind::Q4, ElementKind::Q9] {
        let r = Spacing::from_points(vec![0.1, 0.12, 0.2, 0.45, 0.8, 1.5]).unwrap();
        let plates = [
            PlateSpec {
                z: Spacing::uniform(0.0, d1, 3).unwrap(),
                material: 0,
            },
            PlateSpec {
                z: Spacing::uniform(d1, d1 + d2, 4).unwrap(),
                material: 1,
            },
        ];
        let mesh = Mesh::structured(kind, &r, &plates).unwrap();
        let mut fixed = fix(mesh.bottom(0), -10.0);
        fixed.extend(fix(mesh.top(1), 30.0));
        let s = solve_conduction(&mesh, &[k1, k2], &|_| h, &fixed).unwrap();
        let area = PI * (1.5f64.powi(2) - 0.1f64.powi(2));
        let q = 40.0 * area / (d1 / k1 + 1.0 / h + d2 / k2);
        let q_top: f64 = mesh.top(1).iter().map(|&n| s.flow[n]).sum();
        let q_bottom: f64 = mesh.bottom(0).iter().map(|&n| s.flow[n]).sum();
        assert!((q_top / q - 1.0).abs() < 1e-12, "{kind:?}: {q_top} vs {q}");
        assert!(
            (q_top + q_bottom).abs() < 1e-12 * q,
            "{kind:?}: energy balance"
        );
        // The jump across the interface is q/(h area).
        let (lo, up) = (mesh.top(0)[0], mesh.bottom(1)[0]);
        let jump = s.temperature[up] - s.temperature[lo];
        assert!(
            (jump - q / (h * area)).abs() < 1e-11,
            "{kind:?}: jump {jump}"
        );
    }
}

#[test]
fn radial_flow_through_an_annulus_converges_at_the_predicted_rate() {
    // T(a) = 1, T(b) = 0, faces insulated: T = ln(b/r)/ln(b/a), Q = 2πkD/ln(b/a). The heat flow
    // (a reaction) is an energy functional: its error goes as the square of the energy norm's,
    // h^2 for Q4 and h^4 for Q9.
    let (a, b, d, k): (f64, f64, f64, f64) = (0.1, 1.0, 0.2, 3.0);
    let exact = 2.0 * PI * k * d / (b / a).ln();
    for (kind, rate) in [(ElementKind::Q4, 2.0), (ElementKind::Q9, 4.0)] {
        let errors: Vec<f64> = [4usize, 8, 16, 32, 64]
            .iter()
            .map(|&n| {
                let r = Spacing::uniform(a, b, n).unwrap();
                let plate = PlateSpec {
                    z: Spacing::uniform(0.0, d, 1).unwrap(),
                    material: 0,
                };
                let mesh = Mesh::structured(kind, &r, &[plate]).unwrap();
                let mut fixed = fix(mesh.inner(0), 1.0);
                fixed.extend(fix(mesh.outer(0), 0.0));
                let s = solve_conduction(&mesh, &[k], &|_| 0.0, &fixed).unwrap();
                let q: f64 = mesh.inner(0).iter().map(|&n| s.flow[n]).sum();
                (q / exact - 1.0).abs()
            })
            .collect();
        let rates: Vec<f64> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
        eprintln!("{kind:?}: errors {errors:?}, rates {rates:?}");
        let last = rates[rates.len() - 1];
        // Pre-asymptotic on coarse meshes (∇T ∝ 1/r varies tenfold): the rates climb to the
        // prediction (measured over 32 -> 64 elements: Q4 1.99, Q9 3.95).
        assert!(
            (last - rate).abs() < 0.1,
            "{kind:?}: rate {last} (predicted {rate})"
        );
        assert!(rates.windows(2).all(|w| w[1] > w[0]), "{kind:?}: {rates:?}");
    }
}

#[test]
fn bad_input_is_named() {
    let r = Spacing::uniform(1.0, 2.0, 2).unwrap();
    let mesh = Mesh::structured(
        ElementKind::Q4,
        &r,
        &[PlateSpec {
            z: Spacing::uniform(0.0, 1.0, 1).unwrap(),
            material: 0,
        }],
    )
    .unwrap();
    let e = solve_conduction(&mesh, &[1.0], &|_| 0.0, &[]).unwrap_err();
    assert!(e.to_string().contains("fixed temperatures"));
    let e = solve_conduction(&mesh, &[-1.0], &|_| 0.0, &[(0, 1.0)]).unwrap_err();
    assert!(e.to_string().contains("conductivity k = -1"));
    let e = solve_conduction(&mesh, &[1.0], &|_| 0.0, &[(99, 1.0)]).unwrap_err();
    assert!(e.to_string().contains("fixed node = 99"));
}
