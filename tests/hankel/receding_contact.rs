//! The receding contact of a layer on a frictionless rigid base (`hankel::receding`) against
//! independent checks: equilibrium of the reconstructed pressure, complementarity and the
//! edge exponents of a smooth receding contact, load-scale and ν independence, geometric
//! convergence in the basis size with an honest error estimate, and the bilateral limit (the
//! slab midplane stress of `hankel::midplane`, a second route through the slab kernels).

use boltzone::hankel::receding::{Layer, RecedingError, RecedingParams};
use boltzone::hankel::{MidplaneRule, Slab};
use boltzone::numerics::convergence::slope;
use boltzone::{FaceLoad, InputError, Material};

fn layer(d: f64, load: FaceLoad, nu: f64) -> Layer {
    Layer::new(d, Material::new(2.0e5, nu).unwrap(), load).unwrap()
}

fn disk(b: f64, p: f64) -> FaceLoad {
    FaceLoad::uniform(0.0, b, p).unwrap()
}

#[test]
fn contact_force_balances_the_load() {
    // disk, annulus with a tiny inner radius, triangular: 2π∫q r dr over r ≤ R_o = F
    // (`total_force`: r = R_o(1 − u²), smooth integrand, 40-point Gauss–Legendre in u; observed
    // 1e-15). 1e-9: the solution's own accuracy is ~1e-11 (its error estimate).
    let loads = [
        disk(0.8, 3.0),
        FaceLoad::uniform(0.01, 1.5, 2.0).unwrap(),
        FaceLoad::triangular(0.0, 1.2, 1.0, boltzone::Peak::AtB).unwrap(),
    ];
    for load in loads {
        let f = load.total_force();
        let c = layer(0.5, load, 0.3)
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let force = c.solution.total_force();
        assert!((force / f - 1.0).abs() < 1e-9, "{force} vs {f}");
    }
}

#[test]
fn complementarity_and_edge_exponents() {
    let c = layer(1.0, disk(1.0, 1.0), 0.3)
        .receding_contact(&RecedingParams::default())
        .unwrap();
    let r_o = c.r_o;
    for k in 0..50 {
        let r = r_o * k as f64 / 50.0;
        assert!(c.solution.pressure(r) > 0.0, "q({r}) ≤ 0");
        let r = r_o * (1.0 + (k + 1) as f64 / 50.0);
        assert!(c.solution.gap(r) > 0.0, "gap({r}) ≤ 0");
    }
    // smooth receding contact: q ~ (R_o − r)^(1/2), gap ~ (r − R_o)^(3/2). Fit log–log slopes
    // over e = 1e-2 … 1e-4·D (below, the gap's cancellation of O(1) terms sets in); the next
    // terms are O(e), so the slopes are within ~0.05 of 1/2 and 3/2.
    let es: Vec<f64> = (0..9)
        .map(|k| 1e-2 * 10f64.powf(-0.25 * k as f64))
        .collect();
    let le: Vec<f64> = es.iter().map(|e| e.ln()).collect();
    let lq: Vec<f64> = es
        .iter()
        .map(|e| c.solution.pressure(r_o - e).ln())
        .collect();
    let lg: Vec<f64> = es.iter().map(|e| c.solution.gap(r_o + e).ln()).collect();
    let zip = |x: &[f64], y: &[f64]| -> Vec<(f64, f64)> {
        x.iter().copied().zip(y.iter().copied()).collect()
    };
    let (sq, sg) = (slope(&zip(&le, &lq)), slope(&zip(&le, &lg)));
    assert!(
        (sq - 0.5).abs() < 0.05 && (sg - 1.5).abs() < 0.05,
        "{sq} {sg}"
    );
    // the edge singularity's coefficient is zero at R_o (to the root tolerance)
    assert!(c.solution.edge_coefficient().abs() < 1e-9);
}

#[test]
fn contact_radius_does_not_depend_on_load_scale_or_nu() {
    let params = RecedingParams::default();
    let base = layer(0.4, disk(0.6, 1.0), 0.3)
        .receding_contact(&params)
        .unwrap();
    for (scale, nu) in [(1e-3, 0.3), (1e3, 0.3), (1.0, 0.0), (1.0, 0.49)] {
        let c = layer(0.4, disk(0.6, scale), nu)
            .receding_contact(&params)
            .unwrap();
        assert!(
            (c.r_o - base.r_o).abs() <= base.info.r_o_error,
            "scale {scale} nu {nu}: {} vs {}",
            c.r_o,
            base.r_o
        );
    }
}

#[test]
fn geometric_convergence_in_the_basis_size() {
    // B/D = 1: R_o(n) − R_o(40) for n = 4 … 12 must fall geometrically. Observed rate
    // ≈ e^(−2.2 n); assert at least e^(−1.5 n) on the log–linear fit (and a fit residual that
    // confirms the straight line).
    let l = layer(1.0, disk(1.0, 1.0), 0.3);
    let fixed = |n: usize| RecedingParams {
        min_nodes: n,
        nodes_per_thickness: 0.0,
        ..Default::default()
    };
    let best = l.receding_contact(&fixed(40)).unwrap().r_o;
    let ns: Vec<f64> = (4..=12).step_by(2).map(|n| n as f64).collect();
    let errs: Vec<f64> = ns
        .iter()
        .map(|&n| {
            (l.receding_contact(&fixed(n as usize)).unwrap().r_o - best)
                .abs()
                .ln()
        })
        .collect();
    let pts: Vec<(f64, f64)> = ns.iter().copied().zip(errs.iter().copied()).collect();
    let rate = slope(&pts);
    assert!(rate < -1.5, "rate {rate}");
    // the default run's error estimate is not below its actual error
    let c = l.receding_contact(&RecedingParams::default()).unwrap();
    assert!(
        (c.r_o - best).abs() <= c.info.r_o_error,
        "{} > {}",
        (c.r_o - best).abs(),
        c.info.r_o_error
    );
    assert!(c.info.r_o_error < 1e-9);
}

#[test]
fn bilateral_limit_is_the_slab_midplane_stress() {
    // contact enforced on r ≤ B + 12D: the pressure must be minus the midplane σ_z of the slab
    // of half-thickness D loaded on both faces (two welded plates), up to the bilateral
    // solution's decay beyond c (observed 3e-6 at B + 4D, 2e-12 at B + 12D): 1e-10 of P.
    // 6 points per D: the default 4 leave ~1e-10 on this 14-D-wide zone.
    let (b, d) = (1.0, 0.5);
    let load = disk(b, 1.0);
    let params = RecedingParams {
        nodes_per_thickness: 6.0,
        ..Default::default()
    };
    let sol = layer(d, load.clone(), 0.3)
        .contact_over(b + 12.0 * d, &params)
        .unwrap();
    let slab = Slab::new(d, Material::unit(0.3).unwrap(), load).unwrap();
    let rule = MidplaneRule::new(&slab, 3.0 * b, 1e-14).unwrap();
    for k in 0..=30 {
        let r = 0.1 * k as f64;
        let (q, s) = (sol.pressure(r), -rule.eval(r).value);
        assert!((q - s).abs() < 1e-10, "r={r}: {q} vs {s}");
    }
}

#[test]
fn bad_parameters_are_typed_errors() {
    let l = layer(1.0, disk(1.0, 1.0), 0.3);
    let p = RecedingParams {
        min_nodes: 2,
        ..Default::default()
    };
    assert!(matches!(
        l.receding_contact(&p),
        Err(RecedingError::Input(InputError::Parameter { .. }))
    ));
    let p = RecedingParams {
        rel_tol: f64::NAN,
        ..Default::default()
    };
    assert!(matches!(
        l.receding_contact(&p),
        Err(RecedingError::Input(_))
    ));
    // a scan that stops before R_o reports where it looked
    let p = RecedingParams {
        reach: 0.2,
        ..Default::default()
    };
    assert!(matches!(
        l.receding_contact(&p),
        Err(RecedingError::NotFound { .. })
    ));
    assert!(Layer::new(-1.0, Material::unit(0.3).unwrap(), disk(1.0, 1.0)).is_err());
    // a plate far too thin for dense Nyström systems is refused, naming the size
    let thin = layer(1e-3, disk(1.0, 1.0), 0.3).receding_contact(&RecedingParams::default());
    assert!(matches!(
        thin,
        Err(RecedingError::Input(InputError::Parameter {
            field: "Nystrom points n",
            ..
        }))
    ));
    assert!(l.contact_over(0.0, &RecedingParams::default()).is_err());
}

#[test]
fn a_lifting_centre_is_reported_not_hidden() {
    // a wide ring on a thin plate: the plate bends down under the ring and lifts at the centre,
    // so the contact zone is no disk r ≤ R_o; the solver must say so (tensile pressure inside)
    let ring = FaceLoad::uniform(3.0, 4.0, 1.0).unwrap();
    match layer(0.25, ring, 0.3).receding_contact(&RecedingParams::default()) {
        Err(RecedingError::NotUnilateral { what, value, .. }) => {
            assert_eq!(what, "contact pressure");
            assert!(value < 0.0);
        }
        other => panic!("expected NotUnilateral, got {:?}", other.map(|c| c.r_o)),
    }
    // and a pulling load is no contact problem either
    let pull = disk(1.0, -1.0);
    assert!(matches!(
        layer(1.0, pull, 0.3).receding_contact(&RecedingParams::default()),
        Err(RecedingError::NotUnilateral { .. })
    ));
}

#[test]
fn contact_radius_shortcut_matches_the_layer() {
    let load = disk(0.7, 2.0);
    let (r, info) =
        boltzone::hankel::receding::contact_radius(0.3, &load, &RecedingParams::default()).unwrap();
    let c = layer(0.3, load, 0.1)
        .receding_contact(&RecedingParams::default())
        .unwrap();
    assert!((r - c.r_o).abs() <= info.r_o_error && info.min_pressure >= 0.0 && info.min_gap >= 0.0);
}

#[test]
fn contact_zone_narrower_than_the_load() {
    // a triangular load falling to zero at B = 10D: the plate separates before B (R_o/D ≈ 9.94
    // in example 06), so the search must look inward from B; the pressure still balances F
    let load = FaceLoad::triangular(0.0, 1.0, 1.0, boltzone::Peak::AtA).unwrap();
    let f = load.total_force();
    let c = layer(0.1, load, 0.3)
        .receding_contact(&RecedingParams::default())
        .unwrap();
    assert!(c.r_o < 1.0 && c.r_o > 0.9, "R_o = {}", c.r_o);
    assert!(c.info.min_pressure >= 0.0 && c.info.min_gap >= 0.0 && c.info.r_o_error < 1e-9);
    let force = c.solution.total_force();
    assert!((force / f - 1.0).abs() < 1e-9, "{force} vs {f}");
}

#[test]
fn the_displacement_integral_is_flat_on_the_contact_zone() {
    // w(r, 0) − w(R_o, 0) from the Hankel displacement integral with the solved pressure (not
    // from the Abel-inverted equation the solver uses) must vanish on r ≤ R_o: the Abel
    // inversion, the regularisation of the bending kernel and the discretisation in one check.
    // Scale: the gap at 1.5 R_o; observed ≤ 4e-14 of it, bound 1e-11 (the error estimate of
    // R_o is ~1e-11 relative; a wrong factor anywhere in the chain would show at O(1)).
    for (b, d) in [(1.0, 1.0), (2.0, 0.5), (0.3, 1.0)] {
        let c = layer(d, disk(b, 1.0), 0.3)
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let scale = c.solution.gap(1.5 * c.r_o);
        for k in 0..=20 {
            let r = c.r_o * k as f64 / 20.0;
            let lift = c.solution.lift(r);
            assert!(
                lift.abs() < 1e-11 * scale,
                "B={b} D={d} r={r}: {lift:e} vs {scale:e}"
            );
        }
    }
}
