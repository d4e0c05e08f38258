//! System-level checks of the API the contact solver builds on: stacked plates with their own
//! materials and interface nodes, multi-right-hand-side solves (flexibility reciprocity),
//! refactorization with new values on the same pattern, prescribed displacements with
//! reactions, and the axis r = 0.
//!
//! References: exact uniform-stress solutions (σ_z = −p in every plate whatever its E, u = ν p r/E)
//! and Maxwell–Betti reciprocity (a flexibility matrix of a symmetric K is symmetric).

use boltzone::fem::FemError;
use boltzone::fem::*;
use boltzone::{FaceLoad, Material};
use faer::Mat;

fn factor(mesh: &Mesh, mats: &[Material], s: &Supports) -> (DofMap, Stiffness, Factorization) {
    let dofs = DofMap::new(s);
    let k = assemble(mesh, mats, &dofs, &Pattern::new(mesh, &dofs)).unwrap();
    let f = Factorization::new(&k.matrix, &SolveParams::default()).unwrap();
    (dofs, k, f)
}

/// The stack's materials: E = 1, ν = 0.3 below, E = 3, ν = 0.2 above.
fn materials() -> [Material; 2] {
    [
        Material::new(1.0, 0.3).unwrap(),
        Material::new(3.0, 0.2).unwrap(),
    ]
}

/// Two plates (E = 1 and 3) stacked on z ∈ [0, 0.3] ∪ [0.3, 0.5], r ∈ [0.2, 1].
fn stack(kind: ElementKind) -> Mesh {
    let r = Spacing::graded(0.2, 1.0, &[0.5], &[0.2, 0.5], 0.05, 1.3, 0.2).unwrap();
    let lower = PlateSpec {
        z: Spacing::uniform(0.0, 0.3, 3).unwrap(),
        material: 0,
    };
    let upper = PlateSpec {
        z: Spacing::uniform(0.3, 0.5, 2).unwrap(),
        material: 1,
    };
    Mesh::structured(kind, &r, &[lower, upper]).unwrap()
}

#[test]
fn stacked_plates_have_distinct_interface_nodes_and_their_own_materials() {
    let mats = materials();
    let p = 2.0;
    for kind in [ElementKind::Q4, ElementKind::Q9, ElementKind::Cst4] {
        let mesh = stack(kind);
        let iface = mesh.nodes_at_z(0.3, 1e-12);
        assert_eq!(iface.len(), 2 * mesh.radial_nodes().len());
        let (lo, up) = (mesh.top(0), mesh.bottom(1));
        assert!(lo
            .iter()
            .zip(&up)
            .all(|(a, b)| a != b && mesh.nodes()[*a] == mesh.nodes()[*b]));
        assert!(lo
            .windows(2)
            .all(|w| mesh.nodes()[w[0]][0] < mesh.nodes()[w[1]][0]));
        // each plate on its own rollers, each pressed on top by p: the plates do not touch, so
        // each is in the uniaxial state σ_z = −p of its own material
        let mut s = Supports::new(mesh.n_nodes());
        for n in [mesh.bottom(0), mesh.bottom(1)].concat() {
            s.roller_z(n);
        }
        let mut loads = Loads::new(mesh.n_nodes());
        let load = FaceLoad::uniform(0.2, 1.0, p).unwrap();
        loads
            .add_face_pressure(&mesh, &mesh.top(0), 1.0, &load)
            .unwrap();
        loads
            .add_face_pressure(&mesh, &mesh.top(1), 1.0, &load)
            .unwrap();
        let (dofs, _, f) = factor(&mesh, &mats, &s);
        let u = dofs.expand(&f.solve(&dofs.gather(loads.forces())));
        for (plate, m) in mats.iter().enumerate() {
            let z0 = mesh.plate_z(plate)[0];
            for n in mesh.top(plate) {
                let [r, z] = mesh.nodes()[n];
                let (e, nu) = (m.youngs_modulus(), m.poisson_ratio());
                // round-off of a well-conditioned small system
                assert!(
                    (u[n][0] - nu * p * r / e).abs() < 1e-11,
                    "{kind:?} plate {plate}"
                );
                assert!(
                    (u[n][1] + p * (z - z0) / e).abs() < 1e-11,
                    "{kind:?} plate {plate}"
                );
            }
        }
        for c in centre_stresses(&mesh, &mats, &u).unwrap() {
            assert!(
                (c.stress.z + p).abs() < 1e-10 && c.stress.r.abs() < 1e-10,
                "{kind:?}: {c:?}"
            );
        }
    }
}

#[test]
fn flexibility_by_many_right_hand_sides_is_symmetric_and_matches_single_solves() {
    // one plate on a frictionless plane except: the interface (bottom) normal dofs are free but
    // one reference node, as the contact solver will do it
    let mesh = stack(ElementKind::Q9);
    let mats = materials();
    let mut s = Supports::new(mesh.n_nodes());
    let bottom = mesh.bottom(0);
    s.roller_z(*bottom.last().unwrap());
    for n in [mesh.top(0), mesh.bottom(1)].concat() {
        s.roller_z(n); // upper plate clamped in z at the interface: plates independent
    }
    let (dofs, _, f) = factor(&mesh, &mats, &s);
    let eqs: Vec<usize> = bottom[..bottom.len() - 1]
        .iter()
        .map(|&n| dofs.equation(n, Component::Z).unwrap())
        .collect();
    let m = eqs.len();
    let rhs = Mat::from_fn(
        dofs.n_equations(),
        m,
        |i, j| if i == eqs[j] { 1.0 } else { 0.0 },
    );
    let x = f.solve_many(rhs.as_ref());
    let flex = Mat::from_fn(m, m, |i, j| x[(eqs[i], j)]);
    let scale = (0..m).map(|i| flex[(i, i)].abs()).fold(0.0, f64::max);
    for i in 0..m {
        assert!(flex[(i, i)] > 0.0);
        for j in 0..m {
            // reciprocity, to the round-off of the factorization (cond ~1e6 × ε)
            assert!(
                (flex[(i, j)] - flex[(j, i)]).abs() < 1e-9 * scale,
                "({i},{j})"
            );
        }
    }
    let mut b = vec![0.0; dofs.n_equations()];
    b[eqs[3]] = 1.0;
    let single = f.solve(&b);
    assert!(single
        .iter()
        .enumerate()
        .all(|(i, v)| (v - x[(i, 3)]).abs() <= 1e-14 * scale.max(1.0)));
}

#[test]
fn refactor_reuses_the_pattern() {
    let mesh = stack(ElementKind::Q4);
    let mut s = Supports::new(mesh.n_nodes());
    for n in [mesh.bottom(0), mesh.bottom(1)].concat() {
        s.roller_z(n);
    }
    let dofs = DofMap::new(&s);
    let pattern = Pattern::new(&mesh, &dofs);
    let m1 = materials();
    let m2 = [
        Material::new(2.0, 0.1).unwrap(),
        Material::new(0.5, 0.45).unwrap(),
    ];
    let mut f = Factorization::new(
        &assemble(&mesh, &m1, &dofs, &pattern).unwrap().matrix,
        &SolveParams::default(),
    )
    .unwrap();
    let k2 = assemble(&mesh, &m2, &dofs, &pattern).unwrap();
    f.refactor(&k2.matrix).unwrap();
    let fresh = Factorization::new(&k2.matrix, &SolveParams::default()).unwrap();
    let b: Vec<f64> = (0..dofs.n_equations())
        .map(|i| (i as f64 * 0.37).sin())
        .collect();
    let (x1, x2) = (f.solve(&b), fresh.solve(&b));
    let xm = x2.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    assert!(x1.iter().zip(&x2).all(|(a, c)| (a - c).abs() <= 1e-12 * xm));
}

#[test]
fn prescribed_displacement_under_a_flat_punch_gives_exact_reactions_and_axis_is_handled() {
    // a solid cylinder 0 ≤ r ≤ 1 (axis: u = 0), 0 ≤ z ≤ 0.5, bottom on rollers, the whole top
    // pushed down by δ (the report's Fig. 21 displacement load, here over the whole face so the
    // answer is exact): σ_z = −E δ / h uniformly, total reaction π R² E δ / h
    let (e, h, delta) = (2.0, 0.5, 1e-3);
    let mats = [Material::new(e, 0.3).unwrap()];
    for kind in [
        ElementKind::Q4,
        ElementKind::Q4Bbar,
        ElementKind::Q9,
        ElementKind::Cst4,
    ] {
        let r = Spacing::graded(0.0, 1.0, &[], &[0.0], 0.05, 1.5, 0.3).unwrap();
        let mesh = Mesh::structured(
            kind,
            &r,
            &[PlateSpec {
                z: Spacing::uniform(0.0, h, 3).unwrap(),
                material: 0,
            }],
        )
        .unwrap();
        let mut s = Supports::new(mesh.n_nodes());
        for n in mesh.bottom(0) {
            s.roller_z(n);
        }
        for n in mesh.top(0) {
            s.prescribe(n, Component::Z, -delta);
        }
        for n in mesh.inner(0) {
            s.roller_r(n);
        }
        let (dofs, k, f) = factor(&mesh, &mats, &s);
        let x = f.solve(&k.prescribed_load);
        let u = dofs.expand(&x);
        let loads = Loads::new(mesh.n_nodes());
        let reac = reactions(&mesh, &mats, &u, &loads).unwrap();
        let top: f64 = mesh.top(0).iter().map(|&n| reac[n][1]).sum();
        let exact = std::f64::consts::PI * e * delta / h;
        assert!(
            (top + exact).abs() < 1e-10 * exact,
            "{kind:?}: {top} vs {exact}"
        );
        for n in mesh.nodes().iter().zip(&u) {
            assert!(
                (n.1[0] - 0.3 * delta / h * n.0[0]).abs() < 1e-12,
                "{kind:?}"
            );
        }
        let sz = -e * delta / h;
        for s in nodal_stresses(&mesh, &mats, &u).unwrap() {
            assert!(
                (s.z - sz).abs() < 1e-10 && s.theta.abs() < 1e-10,
                "{kind:?}: {s:?}"
            );
        }
    }
}

#[test]
fn a_pattern_of_another_dof_map_is_a_named_error() {
    let mesh = stack(ElementKind::Q4);
    let mats = materials();
    let mut s = Supports::new(mesh.n_nodes());
    s.fix(0);
    let other = DofMap::new(&Supports::new(mesh.n_nodes()));
    let dofs = DofMap::new(&s);
    let err = assemble(&mesh, &mats, &dofs, &Pattern::new(&mesh, &other)).unwrap_err();
    assert!(matches!(err, FemError::PatternSize { .. }), "{err}");
    // same size, other constrained component: an entry is missing from the pattern
    let mut s2 = Supports::new(mesh.n_nodes());
    s2.fix(mesh.n_nodes() - 1);
    let err = assemble(&mesh, &mats, &dofs, &Pattern::new(&mesh, &DofMap::new(&s2))).unwrap_err();
    assert!(matches!(err, FemError::PatternMismatch { .. }), "{err}");
    let err = assemble(&mesh, &mats[..1], &dofs, &Pattern::new(&mesh, &dofs)).unwrap_err();
    assert!(err.to_string().contains("material 1"), "{err}");
}

#[test]
fn parallel_and_sequential_factorizations_agree() {
    let mesh = stack(ElementKind::Q9);
    let mats = materials();
    let mut s = Supports::new(mesh.n_nodes());
    for n in [mesh.bottom(0), mesh.bottom(1)].concat() {
        s.roller_z(n);
    }
    let dofs = DofMap::new(&s);
    let k = assemble(&mesh, &mats, &dofs, &Pattern::new(&mesh, &dofs)).unwrap();
    let b: Vec<f64> = (0..dofs.n_equations()).map(|i| (i as f64).cos()).collect();
    let seq = Factorization::new(&k.matrix, &SolveParams { parallel: false })
        .unwrap()
        .solve(&b);
    let nd = nested_dissection(&mesh, &dofs);
    let par = Factorization::with_ordering(&k.matrix, Some(&nd), &SolveParams { parallel: true })
        .unwrap()
        .solve(&b);
    let xm = seq.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    // two orderings, two round-off histories: agreement to cond(K)·ε (~1e-10 here)
    assert!(seq
        .iter()
        .zip(&par)
        .all(|(a, c)| (a - c).abs() <= 1e-9 * xm));
    assert!(
        Factorization::with_ordering(&k.matrix, Some(&nd[1..]), &SolveParams::default()).is_err()
    );
}

/// Equations numbered in nested-dissection order and factored without permutation
/// (`DofMap::in_node_order`, `Factorization::natural`) compute what the mesh's own numbering
/// factored in the nested-dissection order computes: the same matrix, the same elimination, the
/// same displacements to the last bit (and the pattern stored with each numbering places every
/// entry where a search of its column finds it, or the two assemblies would differ).
#[test]
fn natural_order_in_dissection_numbering_equals_the_permuted_factorization() {
    let mesh = stack(ElementKind::Q9);
    let mats = materials();
    let mut s = Supports::new(mesh.n_nodes());
    for n in mesh.bottom(0) {
        s.roller_z(n);
    }
    s.prescribe(mesh.top(1)[0], Component::Z, -1e-3);
    let mut loads = Loads::new(mesh.n_nodes());
    let q = FaceLoad::uniform(0.2, 0.5, 1.0).unwrap();
    loads
        .add_face_pressure(&mesh, &mesh.top(1), 1.0, &q)
        .unwrap();
    let solve = |dofs: &DofMap, natural: bool| {
        let k = assemble(&mesh, &mats, dofs, &Pattern::new(&mesh, dofs)).unwrap();
        let mut f = dofs.gather(loads.forces());
        for (fi, pi) in f.iter_mut().zip(&k.prescribed_load) {
            *fi += pi;
        }
        let p = SolveParams::default();
        let x = if natural {
            Factorization::natural(&k.matrix, &p).unwrap().solve(&f)
        } else {
            let order = nested_dissection(&mesh, dofs);
            Factorization::with_ordering(&k.matrix, Some(&order), &p)
                .unwrap()
                .solve(&f)
        };
        dofs.expand(&x)
    };
    let own = solve(&DofMap::new(&s), false);
    let dissected = DofMap::in_node_order(&s, &node_dissection(&mesh)).unwrap();
    assert_eq!(
        nested_dissection(&mesh, &dissected),
        (0..dissected.n_equations()).collect::<Vec<_>>()
    );
    let natural = solve(&dissected, true);
    assert!(own.iter().any(|u| u[1] != 0.0));
    assert_eq!(own, natural);
}
