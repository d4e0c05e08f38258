//! Element invariants and patch tests for every element kind.
//!
//! References: exact identities. A stiffness matrix is symmetric; an axisymmetric element has
//! exactly one rigid-body mode (translation along z), so K·(0,1,0,1,…) = 0 and K has one zero
//! eigenvalue; the linear fields u = a r, w = b z + c are exact elasticity solutions with
//! constant stress σ = D(a, b, a, 0), which every consistent element must reproduce to round-off
//! on a distorted patch (displacement-driven and traction-driven, incl. skew rollers).

use boltzone::fem::*;
use boltzone::{FaceLoad, Material};

const KINDS: [ElementKind; 4] = [
    ElementKind::Cst4,
    ElementKind::Q4,
    ElementKind::Q4Bbar,
    ElementKind::Q9,
];

fn element_coords(kind: ElementKind) -> Vec<[f64; 2]> {
    // a distorted quadrilateral away from the axis (and for Q9 curved-free mid-side nodes)
    let c = [[0.4, 0.1], [1.3, -0.1], [1.5, 0.9], [0.5, 1.2]];
    let mut x = c.to_vec();
    if kind == ElementKind::Q9 {
        for i in 0..4 {
            let (a, b) = (c[i], c[(i + 1) % 4]);
            x.push([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]);
        }
        x.push([
            c.iter().map(|p| p[0]).sum::<f64>() / 4.0,
            c.iter().map(|p| p[1]).sum::<f64>() / 4.0,
        ]);
    }
    x
}

#[test]
fn stiffness_is_symmetric_with_one_rigid_mode() {
    let m = Material::new(3.0, 0.3).unwrap();
    for kind in KINDS {
        let x = element_coords(kind);
        let k = kind.stiffness(&x, &m);
        let nd = 2 * x.len();
        let kmax = k.iter().fold(0.0f64, |a, b| a.max(b.abs()));
        // round-off of a sum of O(10²) products: 1e-13 relative to the largest entry
        let tol = 1e-13 * kmax;
        for i in 0..nd {
            for j in 0..nd {
                assert!((k[i * nd + j] - k[j * nd + i]).abs() < tol, "{kind:?} asym");
            }
            let f: f64 = (0..nd / 2).map(|a| k[i * nd + 2 * a + 1]).sum();
            assert!(
                f.abs() < tol,
                "{kind:?}: force {f} under rigid z-translation"
            );
        }
        let km = nalgebra::DMatrix::from_row_slice(nd, nd, &k);
        let ev = km.symmetric_eigen().eigenvalues;
        let zeros = ev.iter().filter(|e| e.abs() < 1e-10 * kmax).count();
        assert!(
            ev.iter().all(|e| *e > -1e-10 * kmax),
            "{kind:?}: negative eigenvalue"
        );
        assert_eq!(zeros, 1, "{kind:?}: {ev}");
    }
}

/// A 3×3-element patch on r ∈ [0.5, 2], z ∈ [0, 1] with interior nodes moved.
fn patch(kind: ElementKind) -> Mesh {
    let r = Spacing::uniform(0.5, 2.0, 3).unwrap();
    let z = Spacing::uniform(0.0, 1.0, 3).unwrap();
    let mut mesh = Mesh::structured(kind, &r, &[PlateSpec { z, material: 0 }]).unwrap();
    mesh.transform_nodes(|[r, z]| {
        let bump = (r - 0.5) * (2.0 - r) * z * (1.0 - z);
        [r + 0.6 * bump, z + 0.4 * bump * (r - 1.0)]
    });
    mesh
}

fn solve(mesh: &Mesh, mat: &[Material], s: &Supports, loads: &Loads) -> Vec<[f64; 2]> {
    let dofs = DofMap::new(s);
    let k = assemble(mesh, mat, &dofs, &Pattern::new(mesh, &dofs)).unwrap();
    let mut b = dofs.gather(loads.forces());
    for (a, c) in b.iter_mut().zip(&k.prescribed_load) {
        *a += c;
    }
    dofs.expand(
        &Factorization::new(&k.matrix, &SolveParams::default())
            .unwrap()
            .solve(&b),
    )
}

/// Checks u = exact at nodes and σ = D(a, b, a, 0) at every Gauss point and node.
fn check(mesh: &Mesh, mat: &Material, u: &[[f64; 2]], a: f64, b: f64, c: f64, what: &str) {
    let (l, mu) = mat.lame();
    let sr = (l + 2.0 * mu) * a + l * (a + b);
    let sz = (l + 2.0 * mu) * b + 2.0 * l * a;
    // round-off: condition number of a tiny patch (~1e3) × ε, times the scale (1)
    let tol = 1e-11;
    for (x, ui) in mesh.nodes().iter().zip(u) {
        assert!(
            (ui[0] - a * x[0]).abs() < tol && (ui[1] - b * x[1] - c).abs() < tol,
            "{what}: u {ui:?} at {x:?}"
        );
    }
    let pts = gauss_stresses(mesh, &[*mat], u).unwrap();
    for p in &pts {
        let s = p.stress;
        assert!(
            (s.r - sr).abs() < tol
                && (s.theta - sr).abs() < tol
                && (s.z - sz).abs() < tol
                && s.rz.abs() < tol,
            "{what}: {s:?} vs {sr} {sz}"
        );
    }
    for s in nodal_stresses(mesh, &[*mat], u).unwrap() {
        assert!(
            (s.z - sz).abs() < tol && (s.theta - sr).abs() < tol,
            "{what}: nodal {s:?}"
        );
    }
}

#[test]
fn displacement_patch_test() {
    let mat = Material::new(2.0, 0.27).unwrap();
    let (a, b, c) = (1e-3, -2e-3, 5e-4);
    for kind in KINDS {
        let mesh = patch(kind);
        let mut s = Supports::new(mesh.n_nodes());
        let boundary: Vec<usize> =
            [mesh.bottom(0), mesh.top(0), mesh.inner(0), mesh.outer(0)].concat();
        for &n in &boundary {
            let x = mesh.nodes()[n];
            s.prescribe(n, Component::R, a * x[0]);
            s.prescribe(n, Component::Z, b * x[1] + c);
        }
        let u = solve(&mesh, &[mat], &s, &Loads::new(mesh.n_nodes()));
        check(
            &mesh,
            &mat,
            &u,
            a,
            b,
            c,
            &format!("{kind:?} displacement patch"),
        );
    }
}

#[test]
fn traction_patch_test_with_skew_rollers() {
    // uniform σ_z = −p: top pressure p, bottom on rollers, hole and rim free, so u = ν p r / E,
    // w = −p z / E. Half the bottom rollers use the report's code −180 (n = −z), and the rim
    // nodes are skew rollers at −30° with their exact n-displacement prescribed.
    let (e, nu, p) = (2.0, 0.27, 3.0);
    let mat = Material::new(e, nu).unwrap();
    let (a, b) = (nu * p / e, -p / e);
    for kind in KINDS {
        let mesh = patch(kind);
        let mut s = Supports::new(mesh.n_nodes());
        for (i, n) in mesh.bottom(0).into_iter().enumerate() {
            if i % 2 == 0 {
                s.roller_z(n);
            } else {
                s.skew(n, -180.0, 0.0).unwrap();
            }
        }
        let alpha = (-30.0f64).to_radians();
        for n in mesh.outer(0).into_iter().skip(1) {
            let x = mesh.nodes()[n];
            let un = -alpha.sin() * a * x[0] + alpha.cos() * b * x[1];
            s.skew(n, -30.0, un).unwrap();
        }
        let mut loads = Loads::new(mesh.n_nodes());
        loads
            .add_face_pressure(
                &mesh,
                &mesh.top(0),
                1.0,
                &FaceLoad::uniform(0.5, 2.0, p).unwrap(),
            )
            .unwrap();
        let u = solve(&mesh, &[mat], &s, &loads);
        check(
            &mesh,
            &mat,
            &u,
            a,
            b,
            0.0,
            &format!("{kind:?} traction patch"),
        );
        // reactions balance the applied force, and the bottom traction is p everywhere
        let reac = reactions(&mesh, &[mat], &u, &loads).unwrap();
        let bottom = mesh.bottom(0);
        let rz: Vec<f64> = bottom.iter().map(|&n| reac[n][1]).collect();
        let t = line_traction(&mesh, &bottom, &rz).unwrap();
        assert!(t.iter().all(|t| (t - p).abs() < 1e-10), "{kind:?}: {t:?}");
    }
}

#[test]
fn skew_code_rejects_positive_angles() {
    let mut s = Supports::new(1);
    assert!(s.skew(0, 10.0, 0.0).is_err());
    assert!(s.skew(0, -181.0, 0.0).is_err());
}
