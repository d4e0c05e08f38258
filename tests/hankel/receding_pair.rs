//! Two unequal plates without a hole, frictionless (`hankel::receding::Pair`): equal plates
//! against the one layer on a rigid base, the swap identity, force balance of the interface
//! pressure, geometric convergence in the basis size, the rigid-base limit E₂ → ∞ with its
//! first-order rate, the bilateral limit against a direct Hankel integral (a second method),
//! and the finite-element two-plate solver (shares no code) within its error bar.

use boltzone::contact::two_plate::{solve as solve_two, InterfaceModel, TwoPlateParams};
use boltzone::hankel::receding::layer::{bottom_from_bottom, bottom_from_top, Stack};
use boltzone::hankel::receding::{Layer, Pair, RecedingParams};
use boltzone::numerics::convergence::slope;
use boltzone::numerics::quadrature::gauss_legendre;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};

fn plate(d: f64, e: f64, nu: f64) -> Plate {
    Plate::new(d, Material::new(e, nu).unwrap()).unwrap()
}

fn disk(b: f64) -> FaceLoad {
    FaceLoad::uniform(0.0, b, 1.0).unwrap()
}

/// R_o of the pair with the default knobs.
fn r_o(upper: Plate, lower: Plate, load: FaceLoad) -> f64 {
    Pair::new(upper, lower, load)
        .receding_contact(&RecedingParams::default())
        .unwrap()
        .r_o
}

#[test]
fn the_summed_kernels_are_kirchhoff_plates_and_half_spaces_in_series() {
    // (c₁ + c₂)·M̂(ξ)/ξ is the interface's transform compliance. Long waves (ξD ≪ 1): two
    // Kirchhoff plates bending in series, 1/(𝒟₁ξ⁴) + 1/(𝒟₂ξ⁴), 𝒟 = ED³/(12(1 − ν²)), to
    // O((ξD)²) (asserted (ξD_max)² = 1e-6 at ξD_max = 1e-3; observed 3.6e-8). Short waves: two half-spaces pressed
    // together, M̂_q(c₁ + c₂) = 2/E* with Hertz's 1/E* = Σ(1 − νᵢ²)/Eᵢ (Johnson, Contact
    // Mechanics § 4.2), M̂_p exponentially small, ~40e^(−40) ≈ 2e-16 at ξD_min = 40 (asserted
    // 1e-14; observed 2.2e-16).
    let ((d1, e1, nu1), (d2, e2, nu2)) = ((1.0, 2e5, 0.3), (0.4, 7e4, 0.33));
    let c = |e: f64, nu: f64| (1.0 - nu) / (e / (2.0 * (1.0 + nu)));
    let (c1, c2) = (c(e1, nu1), c(e2, nu2));
    let stack = Stack::pair((c1, d1), (c2, d2));
    let rigidity = |e: f64, d: f64, nu: f64| e * d * d * d / (12.0 * (1.0 - nu * nu));
    let xi = 1e-3 / d1;
    let plates = (1.0 / rigidity(e1, d1, nu1) + 1.0 / rigidity(e2, d2, nu2)) / xi.powi(4);
    for m in [stack.bottom_from_top(xi), stack.bottom_from_bottom(xi)] {
        let w = (c1 + c2) * m / xi;
        println!("plates in series: {:.1e}", w / plates - 1.0);
        assert!((w / plates - 1.0).abs() < 1e-6, "{w} vs {plates}");
    }
    let xi = 40.0 / d2;
    let e_star = 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
    let half_spaces = (c1 + c2) * stack.bottom_from_bottom(xi);
    println!("half-spaces: {:.1e}", half_spaces * e_star / 2.0 - 1.0);
    assert!(
        (half_spaces * e_star / 2.0 - 1.0).abs() < 1e-14,
        "{half_spaces}"
    );
    assert!(stack.bottom_from_top(xi) < 1e-14);
}

#[test]
fn equal_plates_are_the_layer_on_a_rigid_base() {
    // λ = (½, ½): the weighted kernels equal the layer's bit for bit (½k + ½k = k), so R_o must
    // agree to rounding (asserted 1e-13 relative; observed 0)
    for (b, d, e, nu) in [
        (1.0, 1.0, 2e5, 0.3),
        (2.5, 0.7, 7e4, 0.0),
        (0.4, 1.3, 1.0, 0.45),
    ] {
        let m = Material::new(e, nu).unwrap();
        let layer = Layer::new(d, m, disk(b))
            .unwrap()
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let pair = r_o(plate(d, e, nu), plate(d, e, nu), disk(b));
        assert!(
            (pair - layer.r_o).abs() <= 1e-13 * layer.r_o,
            "{pair} vs {}",
            layer.r_o
        );
    }
}

#[test]
fn swapping_the_plates_leaves_r_o_unchanged() {
    // the same load on both outer faces: the problem is symmetric under z → −z with the plates
    // exchanged (asserted 1e-13 relative)
    let (p1, p2) = (plate(1.0, 2e5, 0.3), plate(0.4, 7e4, 0.33));
    for b in [0.5, 1.5] {
        let (x, y) = (r_o(p1, p2, disk(b)), r_o(p2, p1, disk(b)));
        assert!((x - y).abs() <= 1e-13 * x, "{x} vs {y}");
    }
}

#[test]
fn interface_pressure_balances_the_load() {
    // 2π∫q r dr (pressure from the Abel formula, quadrature independent of the constraint
    // ∫φ = p̄(0) the solver imposes) against the load's force, 1e-10
    let cases = [
        (plate(1.0, 2e5, 0.3), plate(0.3, 2e3, 0.1), disk(1.0)),
        (plate(0.5, 1.0, 0.45), plate(2.0, 50.0, 0.2), disk(0.8)),
        (
            plate(1.0, 1.0, 0.25),
            plate(0.6, 0.1, 0.25),
            FaceLoad::triangular(0.0, 1.2, 1.0, boltzone::Peak::AtB).unwrap(),
        ),
    ];
    for (p1, p2, load) in cases {
        let f = load.total_force();
        let c = Pair::new(p1, p2, load)
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let force = c.solution.total_force();
        assert!((force / f - 1.0).abs() < 1e-10, "{force} vs {f}");
        // complementarity: pressure inside, an opening gap outside
        assert!(c.info.min_pressure >= 0.0 && c.info.min_gap >= 0.0);
    }
}

#[test]
fn geometric_convergence_in_the_basis_size() {
    // D₂/D₁ = 0.4, E₂/E₁ = 0.1, B = D₁: R_o(n) − R_o(56) for n = 8 … 24 must fall geometrically
    // (the kernels are analytic in a strip ~D_min wide). Observed e^(−1.41 n); assert at least
    // e^(−n) on the log–linear fit; the default run's estimate must bound its actual error.
    let pair = Pair::new(plate(1.0, 1.0, 0.3), plate(0.4, 0.1, 0.2), disk(1.0));
    let fixed = |n: usize| RecedingParams {
        min_nodes: n,
        nodes_per_thickness: 0.0,
        ..Default::default()
    };
    let best = pair.receding_contact(&fixed(56)).unwrap().r_o;
    let pts: Vec<(f64, f64)> = (8..=24)
        .step_by(4)
        .map(|n| {
            let r = pair.receding_contact(&fixed(n)).unwrap().r_o;
            (n as f64, (r - best).abs().ln())
        })
        .collect();
    let rate = slope(&pts);
    println!("observed rate e^({rate:.2} n): {pts:?}");
    assert!(rate < -1.0, "rate {rate}");
    let c = pair.receding_contact(&RecedingParams::default()).unwrap();
    let actual = (c.r_o - best).abs();
    assert!(
        actual <= c.info.r_o_error,
        "{actual} > {}",
        c.info.r_o_error
    );
    assert!(c.info.r_o_error < 1e-9 * c.r_o, "{}", c.info.r_o_error);
}

#[test]
fn a_stiff_lower_plate_tends_to_the_rigid_base_at_first_order() {
    // E₂ → ∞ at fixed D₂: the weight λ₂ = c₂/(c₁ + c₂) → 0 and R_o → the upper plate on a rigid
    // base, with a difference proportional to λ₂ (first order): each factor 100 in E₂ must cut
    // it by 100 (asserted within 1 %: λ₂ ≤ 1e-3 leaves second-order terms ~1e-3) down to the solver's accuracy
    let (b, d1) = (1.2, 1.0);
    let rigid = Layer::new(d1, Material::new(1.0, 0.3).unwrap(), disk(b))
        .unwrap()
        .receding_contact(&RecedingParams::default())
        .unwrap()
        .r_o;
    let diffs: Vec<f64> = [1e3, 1e5, 1e7]
        .iter()
        .map(|&e2| r_o(plate(d1, 1.0, 0.3), plate(0.5, e2, 0.3), disk(b)) - rigid)
        .collect();
    println!("R_o − R_rigid at E2/E1 = 1e3, 1e5, 1e7: {diffs:?}");
    for w in diffs.windows(2) {
        let ratio = w[0] / w[1];
        assert!((ratio / 100.0 - 1.0).abs() < 0.01, "{ratio}");
    }
}

/// q(r) of the plates in contact everywhere (bilateral, frictionless): per ξ, g̅ = 0 gives
/// q̄ = p̄ M̂_p/M̂_q, and q(r) = ∫₀^∞ q̄ J₀(ξr) ξ dξ with p̄ = B J₁(ξB)/ξ (unit pressure): a
/// direct Hankel integral by 20-point Gauss–Legendre panels 0.25/D_min wide up to 45/D_min
/// (the integrand falls like e^(−ξD_min)).
fn bilateral_pressure(b: f64, (l1, d1): (f64, f64), (l2, d2): (f64, f64), r: f64) -> f64 {
    let dmin = d1.min(d2);
    let gl = gauss_legendre(20);
    let (width, panels) = (0.25 / dmin, 180);
    (0..panels)
        .flat_map(|k| gl.iter().map(move |&(x, w)| (k, x, w)))
        .map(|(k, x, w)| {
            let xi = (k as f64 + 0.5 + 0.5 * x) * width;
            let mp = l1 * bottom_from_top(xi * d1) + l2 * bottom_from_top(xi * d2);
            let mq = l1 * bottom_from_bottom(xi * d1) + l2 * bottom_from_bottom(xi * d2);
            0.5 * width * w * b * libm::j1(xi * b) * mp / mq * libm::j0(xi * r)
        })
        .sum()
}

#[test]
fn bilateral_limit_is_the_direct_hankel_integral() {
    // contact enforced on r ≤ B + 14 D_max: inside B + D the pressure must be the bilateral one
    // of the infinite interface (a per-ξ solve, no integral equation), up to its decay beyond c;
    // 1e-11 of the load's pressure (observed 1.0e-13)
    let (b, (d1, e1, nu1), (d2, e2, nu2)) = (1.0, (1.0, 1.0, 0.3), (0.5, 0.2, 0.1));
    let pair = Pair::new(plate(d1, e1, nu1), plate(d2, e2, nu2), disk(b));
    let params = RecedingParams {
        nodes_per_thickness: 6.0,
        ..Default::default()
    };
    let sol = pair.contact_over(b + 14.0 * d1, &params).unwrap();
    let c = |e: f64, nu: f64| 2.0 * (1.0 - nu) * (1.0 + nu) / e;
    let (c1, c2) = (c(e1, nu1), c(e2, nu2));
    let (l1, l2) = (c1 / (c1 + c2), c2 / (c1 + c2));
    let mut worst = 0.0f64;
    for k in 0..=20 {
        let r = 0.1 * k as f64;
        let (q, s) = (
            sol.pressure(r),
            bilateral_pressure(b, (l1, d1), (l2, d2), r),
        );
        worst = worst.max((q - s).abs());
    }
    println!("largest difference {worst:.2e}");
    assert!(worst < 1e-11, "{worst}");
}

#[test]
fn the_finite_elements_agree_within_their_error_bar() {
    // FE two-plate, frictionless, A = 0, infinite plates, at --tol 1e-4: |R_FE − R_ref| must be
    // within the FE's estimate plus the reference's
    let cases = [
        (1.0, plate(1.0, 1.0, 0.3), plate(0.5, 3.0, 0.25)),
        (0.6, plate(1.0, 1.0, 0.1), plate(2.0, 0.05, 0.4)),
        (2.0, plate(1.0, 1.0, 0.33), plate(0.7, 0.3, 0.33)),
    ];
    for (b, p1, p2) in cases {
        let reference = Pair::new(p1, p2, disk(b))
            .receding_contact(&RecedingParams::default())
            .unwrap();
        let joint = Joint::new(0.0, OuterRadius::Infinite, p1, p2, disk(b)).unwrap();
        let params = TwoPlateParams {
            tolerance: 1e-4,
            interface: InterfaceModel::Frictionless,
            ..Default::default()
        };
        let fe = solve_two(&joint, &params).unwrap();
        let actual = (fe.r_o - reference.r_o).abs();
        println!(
            "B = {b}: FE {} ± {:.2e} ({}), reference {} ± {:.1e}: actual {actual:.2e}",
            fe.r_o, fe.r_o_error, fe.converged, reference.r_o, reference.info.r_o_error
        );
        assert!(fe.converged);
        assert!(actual <= fe.r_o_error + reference.info.r_o_error);
    }
}
