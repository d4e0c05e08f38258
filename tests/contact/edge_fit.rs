//! The fitted contact edge (`contact::edge_fit`): its root finder and trial edges on synthetic
//! systems with a known root, and the fitted study against the receding contact (no hole,
//! infinite plates, the Hankel R_o to ~1e-12).

use boltzone::contact::edge_fit::{extrapolated, fit, root, EdgeSystem};
use boltzone::contact::two_plate::{solve, TwoPlateParams, TwoPlateSolution};
use boltzone::hankel::receding::{Layer, RecedingParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use nalgebra::{DMatrix, DVector};

#[test]
fn the_root_is_exact_on_quadratics_and_lines() {
    for r_o in [0.31, 0.3456, 0.399] {
        let q = |x: f64| (r_o - x) * (2.0 + 5.0 * x);
        let t: Vec<(f64, f64)> = (0..5)
            .map(|i| 0.3 + 0.03 * i as f64)
            .map(|x| (x, q(x)))
            .collect();
        let r = root(&t).expect("a sign change");
        // rounding of a few divided differences of O(1) values
        assert!((r - r_o).abs() < 1e-14, "{r} against {r_o}");
        let line = [(0.3, 0.3 - r_o), (0.4, 0.4 - r_o)];
        assert!((root(&line).expect("a sign change") - r_o).abs() < 1e-15);
    }
    assert_eq!(root(&[(0.0, 1.0), (1.0, 2.0)]), None);
}

#[test]
fn trial_edges_find_the_root_of_the_edge_force() {
    // F = I: the closed points carry λ = −g⁰, so the edge force is −g⁰(ρ); with g⁰ linear in r
    // its root is the zero of g⁰, whatever the LCP's own edge (the window's 5th point here).
    // Uniform nodes (h = 0.01, quadratic elements: corners at even lines), root 0.1537.
    let radius: Vec<f64> = (0..30).map(|i| 0.05 + 0.005 * i as f64).collect();
    let r_o = 0.1537;
    let window: Vec<usize> = (8..30).collect();
    let m = window.len();
    let sys = EdgeSystem {
        flexibility: DMatrix::identity(m, m),
        gap0: DVector::from_fn(m, |q, _| radius[window[q]] - r_o),
        window,
    };
    let active: Vec<bool> = (0..m).map(|q| q <= 12).collect();
    let f = fit(&sys, &radius, &active, 2).expect("a fitted edge");
    let r = f.r_o_force.expect("a force root");
    assert!((r - r_o).abs() < 1e-14, "{r} against {r_o}");
    // and every extrapolated value of a first-order sequence is its limit
    let raw: Vec<f64> = (0..5).map(|k| r_o - 0.02 * 0.5f64.powi(k)).collect();
    assert!(extrapolated(&raw)[1..]
        .iter()
        .all(|x| (x - r_o).abs() < 1e-15));
}

/// Equal infinite plates 1 thick without a hole, pressed on r ≤ `b`, Poisson ratio `nu`: the
/// exact R_o (the receding contact) and the joint.
pub(crate) fn plate(b: f64, nu: f64) -> (f64, Joint) {
    let m = Material::unit(nu).unwrap();
    let load = FaceLoad::uniform(0.0, b, 1.0).unwrap();
    let exact = Layer::new(1.0, m, load.clone())
        .unwrap()
        .receding_contact(&RecedingParams::default())
        .unwrap()
        .r_o;
    let p = Plate::new(1.0, m).unwrap();
    (
        exact,
        Joint::new(0.0, OuterRadius::Infinite, p, p, load).unwrap(),
    )
}

/// The fitted study of `joint` on exactly six levels (h = D/4 … D/128).
fn six_fitted_levels(joint: &Joint) -> TwoPlateSolution {
    solve(
        joint,
        &TwoPlateParams {
            tolerance: 1e-13,
            min_levels: 6,
            max_levels: 6,
            fitted_edge: true,
            ..Default::default()
        },
    )
    .unwrap()
}

#[test]
fn the_edge_force_root_is_first_order_and_the_study_within_its_estimate() {
    // a low and a high ν: the gap-shape estimate's first-order term changes sign between them
    for (b, nu) in [(1.2, 0.15), (2.0, 0.45)] {
        let (exact, joint) = plate(b, nu);
        let s = six_fitted_levels(&joint);
        let e: Vec<f64> = s.info.levels.iter().map(|l| l.r_o - exact).collect();
        let ratio = e[4] / e[5];
        println!("B {b} ν {nu}: level errors {e:?}, last ratio {ratio:.3}");
        // the edge force's root is first order, of one sign, with the tip's mesh the same in
        // units of h on every level: ratio 2 (measured 1.93–1.99 at h = D/64 … D/1024 on five
        // random plates, example 22); 1.85–2.15 leaves twice that spread
        assert!((1.85..=2.15).contains(&ratio), "ratio {ratio}");
        assert!(e[3] > 0.0 && e[4] > 0.0 && e[5] > 0.0);
        let t = solve(
            &joint,
            &TwoPlateParams {
                tolerance: 1e-4,
                fitted_edge: true,
                ..Default::default()
            },
        )
        .unwrap();
        let err = (t.r_o - exact).abs();
        println!(
            "  study at 1e-4: error {err:.2e}, estimate {:.2e}",
            t.r_o_error
        );
        assert!(
            t.converged && err <= t.r_o_error,
            "{err:e} beyond {:e}",
            t.r_o_error
        );
    }
}

#[test]
fn the_reaction_fit_is_first_order_too_and_shares_the_force_roots_limit() {
    // K fitted to the last closed nodes' reactions removes the regular √ term from the edge
    // force, yet stays first order (the elements' own error at the edge scales like that
    // term on a mesh the same in units of h); its first-order term differs from the force
    // root's, and Richardson removes both alike.
    for (b, nu) in [(1.2, 0.15), (2.0, 0.45)] {
        let (exact, joint) = plate(b, nu);
        let s = six_fitted_levels(&joint);
        let l = &s.info.levels;
        // (the coarsest level's window may hold too few closed nodes for the fit: NaN there)
        let force: Vec<f64> = l.iter().map(|l| l.r_o_fit_force.unwrap() - exact).collect();
        let fit: Vec<f64> = l
            .iter()
            .map(|l| l.r_o_fit_reaction.unwrap_or(f64::NAN) - exact)
            .collect();
        assert!(fit[3..].iter().all(|e| e.is_finite()));
        let order = (fit[4] / fit[5]).abs().ln() / (l[4].h / l[5].h).ln();
        println!("B {b} ν {nu}: reaction-fit errors {fit:?}, order {order:.3}");
        // nearer first order than second (or zeroth)
        assert!((0.5..1.5).contains(&order), "order {order}");
        let rich = |e: &[f64]| 2.0 * e[5] - e[4];
        let (xf, xr) = (rich(&force), rich(&fit));
        println!("  Richardson: force {xf:.3e}, reaction fit {xr:.3e}");
        assert!((xf - xr).abs() < 0.1 * fit[5].abs().min(force[5].abs()));
    }
}
