//! Coulomb friction on the interface (src/contact/friction.rs and the two-plate model with
//! `InterfaceModel::Friction`): the solver against enumeration of every open/stick/slip state of
//! small problems, proportional loading in increments against one step, and on the two-plate
//! model the two limits (μ = 0 the frictionless model, μ = 10³ the welded one), complementarity
//! node by node, and dissimilar plates.

use boltzone::compare::table2;
use boltzone::contact::friction::{
    solve_friction, solve_friction_incremental, FrictionProblem, PointState,
};
use boltzone::contact::two_plate::{solve, InterfaceModel, TwoPlateParams, TwoPlateSolution};
use boltzone::contact::LcpParams;
use boltzone::{reference, FaceLoad, Joint, Material, OuterRadius, Plate};
use nalgebra::{DMatrix, DVector};

use super::lcp::Lcg;

/// A random problem of `m` points (and a held point when `held`): F = B Bᵀ + I, normal gaps
/// mostly penetrating, slips of either sign.
fn random_problem(rng: &mut Lcg, m: usize, held: bool, mu: f64) -> FrictionProblem {
    let n = 2 * m + usize::from(held);
    let b = DMatrix::from_fn(n, n, |_, _| 0.6 * rng.next());
    let f = &b * b.transpose() + DMatrix::identity(n, n);
    let g0 = DVector::from_fn(n, |i, _| if i < m { rng.next() - 0.6 } else { rng.next() });
    FrictionProblem {
        flexibility: f,
        gap0: g0,
        mu,
        held: held.then_some(10.0),
    }
}

/// Every combination of states (open, stick, slip out, slip in per point; the held point never
/// open), each solved as a linear system written here from the conditions and kept if all the
/// conditions hold: the forces of every solution.
fn enumerate(p: &FrictionProblem) -> Vec<DVector<f64>> {
    let n = p.gap0.len();
    let h = usize::from(p.held.is_some());
    let m = (n - h) / 2;
    let f = &p.flexibility;
    let mut found = Vec::new();
    let combos = 4usize.pow(m as u32) * if h == 1 { 3 } else { 1 };
    for mut code in 0..combos {
        let mut st = Vec::new();
        for k in 0..m + h {
            let base = if k < m { 4 } else { 3 };
            st.push(code % base + if k < m { 0 } else { 1 });
            code /= base;
        }
        // rows: one per unknown; state 0 open, 1 stick, 2 slip out (λt = −μN), 3 slip in
        let mut a = DMatrix::zeros(n, n);
        let mut rhs = DVector::zeros(n);
        for k in 0..m + h {
            let t = m + k;
            if k < m {
                if st[k] == 0 {
                    a[(k, k)] = 1.0;
                } else {
                    a.row_mut(k).copy_from(&f.row(k));
                    rhs[k] = -p.gap0[k];
                }
            }
            match st[k] {
                0 => a[(t, t)] = 1.0,
                1 => {
                    a.row_mut(t).copy_from(&f.row(t));
                    rhs[t] = -p.gap0[t];
                }
                s => {
                    let sigma = if s == 2 { -1.0 } else { 1.0 };
                    a[(t, t)] = 1.0;
                    if k < m {
                        a[(t, k)] = -sigma * p.mu;
                    } else {
                        for j in 0..m {
                            a[(t, j)] = sigma * p.mu;
                        }
                        rhs[t] = sigma * p.mu * p.held.unwrap();
                    }
                }
            }
        }
        let Some(x) = a.lu().solve(&rhs) else {
            continue;
        };
        let g = &p.gap0 + f * &x;
        let eps = 1e-11;
        let ok = (0..m + h).all(|k| {
            let normal = if k < m {
                x[k]
            } else {
                p.held.unwrap() - x.rows(0, m).sum()
            };
            let (lt, s) = (x[m + k], g[m + k]);
            let normal_ok = k >= m || (g[k] >= -eps && x[k] >= -eps);
            let cone = lt.abs() <= p.mu * normal + eps && normal >= -eps;
            let slip_ok = match st[k] {
                2 => s >= -eps,
                3 => s <= eps,
                _ => true,
            };
            normal_ok && cone && slip_ok
        });
        if ok && !found.iter().any(|y: &DVector<f64>| (y - &x).amax() < 1e-9) {
            found.push(x);
        }
    }
    found
}

#[test]
fn agrees_with_enumeration_of_all_states() {
    let mut rng = Lcg(7);
    let mut unique = 0;
    for trial in 0..120 {
        let m = 1 + trial % 3;
        let mu = [0.0, 0.2, 0.5, 1.0][trial % 4];
        let p = random_problem(&mut rng, m, trial % 2 == 1, mu);
        let all = enumerate(&p);
        let s = match solve_friction(&p, &LcpParams::default()) {
            Ok(s) => s,
            Err(e) => panic!("trial {trial}: {e}; enumeration: {all:?} {p:?}"),
        };
        assert!(
            s.lcp.info.residual < 1e-12,
            "trial {trial}: residual {}",
            s.lcp.info.residual
        );
        // the solver's answer is one of the enumerated solutions...
        let best = all
            .iter()
            .map(|y| (y - &s.lcp.force).amax())
            .fold(f64::INFINITY, f64::min);
        assert!(
            best < 1e-10 * s.lcp.force.amax().max(1.0),
            "trial {trial}: {best:e} from {} solutions",
            all.len()
        );
        unique += usize::from(all.len() == 1);
    }
    // ...and for these (small-μ-coupling) problems nearly always the only one
    assert!(unique >= 100, "unique in {unique} of 120");
}

#[test]
fn one_point_closed_forms() {
    // F = [[a, b], [b, d]], pressed in by g0 < 0, pushed by s0: stick when the stick force is
    // inside the cone, else slip with λt = ∓μλn and λn = −g0/(a ∓ bμ).
    let (a, b, d) = (2.0, 0.5, 1.0);
    for (s0, mu) in [(0.1, 0.5), (2.0, 0.3), (-2.0, 0.3)] {
        let p = FrictionProblem {
            flexibility: DMatrix::from_row_slice(2, 2, &[a, b, b, d]),
            gap0: DVector::from_vec(vec![-1.0, s0]),
            mu,
            held: None,
        };
        let s = solve_friction(&p, &LcpParams::default()).unwrap();
        let det = a * d - b * b;
        let g0 = -1.0;
        let (ln, lt) = ((-d * g0 + b * s0) / det, (b * g0 - a * s0) / det);
        let (en, et) = if lt.abs() <= mu * ln {
            (ln, lt)
        } else {
            let sigma = -lt.signum(); // the slip's sign
            let ln = -g0 / (a - sigma * b * mu);
            (ln, -sigma * mu * ln)
        };
        assert!(
            (s.lcp.force[0] - en).abs() < 1e-14 && (s.lcp.force[1] - et).abs() < 1e-14,
            "{s0} {mu}"
        );
    }
}

#[test]
fn proportional_loading_needs_one_increment() {
    let mut rng = Lcg(11);
    for trial in 0..20 {
        let p = random_problem(&mut rng, 4, trial % 2 == 0, 0.3);
        let one = solve_friction(&p, &LcpParams::default()).unwrap();
        for steps in [2, 5, 20] {
            let inc = solve_friction_incremental(&p, &LcpParams::default(), steps).unwrap();
            let d = (&inc.lcp.force - &one.lcp.force).amax();
            assert!(
                d < 1e-12 * one.lcp.force.amax(),
                "trial {trial}, {steps} steps: {d:e}"
            );
            assert_eq!(inc.state, one.state);
        }
    }
}

#[test]
fn rejects_bad_coefficients() {
    let mut p = random_problem(&mut Lcg(3), 2, false, -0.1);
    assert!(solve_friction(&p, &LcpParams::default()).is_err());
    p.mu = f64::NAN;
    assert!(solve_friction(&p, &LcpParams::default()).is_err());
    let case = reference::table2()
        .into_iter()
        .find(|c| c.case == 5)
        .unwrap();
    let j = table2::joint(&case).unwrap();
    let e = solve(&j, &params(InterfaceModel::Friction { mu: f64::INFINITY })).unwrap_err();
    assert!(e.is_input() && e.to_string().contains("mu"), "{e}");
}

fn params(interface: InterfaceModel) -> TwoPlateParams {
    TwoPlateParams {
        interface,
        ..Default::default()
    }
}

fn case5() -> Joint {
    let case = reference::table2()
        .into_iter()
        .find(|c| c.case == 5)
        .unwrap();
    table2::joint(&case).unwrap()
}

#[test]
fn mu_zero_is_the_frictionless_model() {
    let j = case5();
    let a = solve(&j, &params(InterfaceModel::Frictionless)).unwrap();
    let b = solve(&j, &params(InterfaceModel::Friction { mu: 0.0 })).unwrap();
    assert!(
        (a.r_o - b.r_o).abs() <= 1e-9 * a.r_o,
        "{} vs {}",
        a.r_o,
        b.r_o
    );
    assert_eq!(a.radius.len(), b.radius.len());
    let pmax = a.pressure.iter().fold(0.0f64, |m, x| m.max(*x));
    // The curves to 1e-8: the frictionless model ties the points inside the contact zone
    // exactly, the frictional one solves for them through the flexibility (cond ≈ 10⁵), so
    // p differs by round-off (measured 2.5e-9 of max p at the hole edge, ≤ 5e-11 elsewhere).
    for i in 0..a.radius.len() {
        assert!(
            (a.pressure[i] - b.pressure[i]).abs() <= 1e-8 * pmax,
            "p at node {i}"
        );
        assert!(b.shear[i].abs() <= 1e-9 * pmax, "τ at node {i}");
    }
}

#[test]
fn mu_large_is_the_welded_model_for_table2_case5() {
    let j = case5();
    let w = solve(&j, &params(InterfaceModel::Welded)).unwrap();
    let f = solve(&j, &params(InterfaceModel::Friction { mu: 1e3 })).unwrap();
    assert!(w.converged && f.converged);
    // both to the tolerance 5e-4: they agree within it
    let tol = 5e-4 * w.r_o;
    assert!(
        (w.r_o - f.r_o).abs() <= tol,
        "welded {} vs μ = 1e3 {}",
        w.r_o,
        f.r_o
    );
    let zones = f.friction.as_ref().unwrap();
    assert!(zones
        .state
        .iter()
        .all(|s| matches!(s, PointState::Open | PointState::Stick)));
}

/// The node-by-node conditions: p ≥ 0, g ≥ 0, p g = 0, |τ| ≤ μp, and |τ| = μp with τ opposing
/// the slip where the node slips; stick nodes do not slip.
///
/// Round-off: closed gaps, stick slips and the cone are solved for directly (LU on the closed
/// points, backward error ε·cond(F) ≈ 2e-16 · 10⁵ = 2e-11 of the scale; measured ≤ 1e-13):
/// 1e-9 of the largest gap, slip and pressure. Open nodes must not penetrate beyond the same
/// round-off, 1e-11 of the displacement scale (the largest gap, or the deflection under the
/// nut when larger); measured overlaps 3e-16 to 3.2e-14 of it (the largest with a fixed edge).
fn assert_complementarity(s: &TwoPlateSolution, mu: f64) {
    let z = s.friction.as_ref().expect("friction record");
    let pmax = s.pressure.iter().fold(0.0f64, |m, x| m.max(*x));
    let gmax = s.gap.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let smax = z.slip.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let (ep, eg, es) = (1e-9 * pmax, 1e-9 * gmax, 1e-9 * smax);
    let scale = gmax.max(s.nut_deflection.abs());
    assert!(
        s.overlap <= 1e-11 * scale,
        "overlap {:e} of {scale:e}",
        s.overlap
    );
    for i in 0..s.radius.len() {
        let (p, g, t, sl) = (s.pressure[i], s.gap[i], s.shear[i], z.slip[i]);
        // p ≥ 0 and g ≥ 0 everywhere; p g = 0 because open nodes carry p = 0 and closed ones
        // have g = 0 (checked per state below)
        assert!(
            p >= 0.0 && g >= -1e-11 * scale,
            "node {i}: p = {p:e}, g = {g:e}"
        );
        match z.state[i] {
            PointState::Open => assert!(p == 0.0 && t.abs() <= ep, "open node {i}: τ = {t:e}"),
            PointState::Stick => {
                assert!(
                    g.abs() <= eg && sl.abs() <= es,
                    "stick node {i}: g {g:e} s {sl:e}"
                );
                assert!(
                    t.abs() <= mu * p + ep,
                    "stick node {i}: |τ| {t:e} > μp {:e}",
                    mu * p
                );
            }
            PointState::SlipOut | PointState::SlipIn => {
                assert!(g.abs() <= eg, "slip node {i}: g {g:e}");
                assert!(
                    (t.abs() - mu * p).abs() <= ep,
                    "slip node {i}: |τ| {t:e} ≠ μp {:e}",
                    mu * p
                );
                assert!(
                    t * sl <= 0.0,
                    "slip node {i}: τ {t:e} does not oppose s {sl:e}"
                );
            }
        }
    }
}

fn dissimilar(lower: Material) -> Joint {
    let case = reference::table2()
        .into_iter()
        .find(|c| c.case == 5)
        .unwrap();
    let a = reference::TABLE2_HOLE_RADIUS;
    Joint::new(
        a,
        OuterRadius::Finite(reference::TABLE2_OUTER_RADIUS),
        Plate::new(case.d1, Material::steel_304_psi()).unwrap(),
        Plate::new(case.d2, lower).unwrap(),
        FaceLoad::uniform(a, case.two_b / 2.0, 1.0).unwrap(),
    )
    .unwrap()
}

#[test]
fn steel_on_aluminium_and_titanium_converge_without_overlap() {
    // aluminium 6061 (10.0e6 psi, 0.33) and Ti-6Al-4V (16.5e6 psi, 0.34)
    for (name, m) in [("aluminium", (10.0e6, 0.33)), ("titanium", (16.5e6, 0.34))] {
        let j = dissimilar(Material::new(m.0, m.1).unwrap());
        let free = solve(&j, &params(InterfaceModel::Frictionless)).unwrap();
        for mu in [0.2, 0.6] {
            let s = solve(&j, &params(InterfaceModel::Friction { mu })).unwrap();
            assert!(s.converged, "{name} μ = {mu}: not converged");
            assert_complementarity(&s, mu);
            let z = s.friction.as_ref().unwrap();
            assert!(
                z.state
                    .iter()
                    .any(|x| matches!(x, PointState::SlipOut | PointState::SlipIn)),
                "{name}: no slip"
            );
            // friction holds the plates together farther out than the frictionless model
            assert!(
                s.r_o > free.r_o - free.r_o_error - s.r_o_error,
                "{name} μ = {mu}"
            );
        }
    }
}

#[test]
fn complementarity_holds_node_by_node_on_table2_case5() {
    let s = solve(&case5(), &params(InterfaceModel::Friction { mu: 0.1 })).unwrap();
    assert!(s.converged);
    assert_complementarity(&s, 0.1);
}

#[test]
fn fixed_edge_and_nut_displacement_reach_the_welded_limit() {
    // Held by the edge or the nut, the stack needs no reference point: every point is an
    // unknown. μ = 10³ sticks everywhere, so R_o is the welded one within both estimates.
    use boltzone::contact::two_plate::{EdgeSupport, Loading};
    let j = case5();
    for (edge, loading) in [
        (EdgeSupport::Fixed, Loading::Pressure),
        (EdgeSupport::Free, Loading::NutDisplacement(5e-5)),
    ] {
        let at = |interface| TwoPlateParams {
            interface,
            edge,
            loading,
            tolerance: 2e-3,
            ..Default::default()
        };
        let w = solve(&j, &at(InterfaceModel::Welded)).unwrap();
        let f = solve(&j, &at(InterfaceModel::Friction { mu: 1e3 })).unwrap();
        assert!(w.converged && f.converged, "{edge:?} {loading:?}");
        assert!(
            (w.r_o - f.r_o).abs() <= w.r_o_error + f.r_o_error,
            "{edge:?} {loading:?}: welded {} ± {:.1e}, μ = 1e3 {} ± {:.1e}",
            w.r_o,
            w.r_o_error,
            f.r_o,
            f.r_o_error
        );
        assert_complementarity(&f, 1e3);
    }
}
