//! The interface pressure of the holed two-plate route
//! (`hankel::receding::holed::two_plate_hole_pressure`): equilibrium of the contact force with
//! the applied load, bounded by the hole's residual traction; the pressure's signs and its
//! √(R_o − r) end.

use boltzone::hankel::receding::holed::{two_plate_hole_pressure, HoledParams};
use boltzone::numerics::quadrature::gauss_legendre;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use std::f64::consts::PI;

const A: f64 = 0.1;

fn plate(a_over_d: f64, b_over_a: f64) -> SinglePlate {
    let load = FaceLoad::uniform(A, b_over_a * A, 1.0).unwrap();
    SinglePlate::new(
        A,
        OuterRadius::Infinite,
        A / a_over_d,
        Material::new(3.0e7, 0.3).unwrap(),
        load,
    )
    .unwrap()
}

/// (contact force / applied force − 1, the bound from the hole's residual, R_o, hole residual):
/// the force 2π∫_A^{R_o} q r dr by `n`-point Gauss–Legendre in u with r = R_o − (R_o − A)u²
/// (q ~ √(R_o − r) becomes smooth in u). The plate's vertical equilibrium is
/// load = contact force + ∫ τ_rz over the hole's face 2πA·D: the residual shear
/// (≤ residual_max·P) bounds the force's error by residual_max·P·2πAD.
fn equilibrium(
    a_over_d: f64,
    b_over_a: f64,
    params: &HoledParams,
    n: usize,
) -> (f64, f64, f64, f64) {
    let us: Vec<(f64, f64)> = gauss_legendre(n)
        .iter()
        .map(|&(x, w)| (0.5 * (1.0 + x), 0.5 * w))
        .collect();
    let at: Vec<f64> = us.iter().map(|&(u, _)| 1.0 - u * u).collect();
    let (out, curve) = two_plate_hole_pressure(&plate(a_over_d, b_over_a), params, &at).unwrap();
    assert_eq!(curve.len(), n);
    let integral: f64 = us
        .iter()
        .zip(&curve)
        .map(|(&(u, w), &(r, q))| w * q * r * 2.0 * u)
        .sum();
    let force = 2.0 * PI * (out.r_o - A) * integral;
    let b = b_over_a * A;
    let applied = PI * (b * b - A * A);
    let d = A / a_over_d;
    let bound = out.info.residual_max * 2.0 * PI * A * d / applied;
    (force / applied - 1.0, bound, out.r_o, out.info.residual_max)
}

#[test]
fn contact_force_balances_the_load_within_the_hole_residual() {
    // Measured (Table 1 row 1, defaults): force error −7.8e-9 against the bound 5.7e-9 from the
    // residual 2.5e-8 P sampled at the fit's check heights (its sup is larger) — the factor 2
    // allows for that sampling; 40 and 80 points agree to 2e-12.
    let p = HoledParams {
        estimate: false,
        ..HoledParams::default()
    };
    let (err, bound, _, residual) = equilibrium(1.0, 3.1, &p, 40);
    assert!(residual < 1e-7, "{residual:e}");
    assert!(err.abs() <= 2.0 * bound, "{err:e} vs {bound:e}");
    assert!(err.abs() < 1e-8, "{err:e}");
}

#[test]
#[ignore = "study (about 10 s of CPU): the equilibrium error falls with the hole residual to 1e-10"]
fn equilibrium_follows_the_hole_residual_to_1e10() {
    // ξ_l = 70/D resolves l's transform further: the residual falls 2.5e-8 → 4e-10 P and the
    // force's error with it, −7.8e-9 → −1.3e-10 (measured)
    let p = HoledParams {
        estimate: false,
        xi_l: 70.0,
        ..HoledParams::default()
    };
    let (err, bound, _, _) = equilibrium(1.0, 3.1, &p, 40);
    println!("force error {err:e}, residual bound {bound:e}");
    assert!(
        err.abs() <= 2.0 * bound && err.abs() < 2e-10,
        "{err:e} vs {bound:e}"
    );
}

#[test]
fn pressure_is_compressive_and_ends_like_a_square_root() {
    let x = [0.0, 0.25, 0.5, 0.75, 0.999, 0.99975, 1.0];
    let p = HoledParams {
        estimate: false,
        ..HoledParams::default()
    };
    let (out, curve) = two_plate_hole_pressure(&plate(1.0, 3.1), &p, &x).unwrap();
    assert!((curve[0].0 - A).abs() < 1e-15 && (curve[6].0 - out.r_o).abs() < 1e-15);
    for &(r, q) in &curve[..6] {
        assert!(q > 0.0, "q({r}) = {q}");
    }
    assert_eq!(curve[6].1, 0.0);
    // q ∝ √(R_o − r) near the end: quartering the distance halves q (the next term, measured
    // as 3 % of the ratio between x = 0.99 and 0.999, changes it by about 0.25 % here)
    let ratio = curve[4].1 / curve[5].1;
    assert!((ratio - 2.0).abs() < 0.02, "{ratio}");
    // fractions outside [0, 1] are refused, naming the field
    let e = two_plate_hole_pressure(&plate(1.0, 3.1), &p, &[1.5]).unwrap_err();
    assert!(e.to_string().contains("pressure fraction"), "{e}");
}

#[test]
fn two_method_hankel_writes_the_pressure_curve() {
    // `two --method hankel --curve`: the FE's layout (r, p, g, τ), A to R_o, p ≥ 0 ending at 0;
    // its force by the trapezoidal rule on the 101 points (spacing ≤ 2 % of R_o − A, graded
    // toward R_o where q ~ √(R_o − r)) within 1e-3 of the load: the rule's error h²·q''/12 is
    // of order 1e-4 here (measured −6.7e-5)
    let dir = std::env::temp_dir().join(format!("boltzone-hankel-curve-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curve.csv");
    let mut args: Vec<&str> = "two --a 0.1 --b 0.31 --d 0.1 --force 100 --method hankel --curve"
        .split(' ')
        .collect();
    args.push(path.to_str().unwrap());
    let out = crate::common::boltzone(&args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.starts_with("r [in],p [psi],g [in],tau [psi]\n"),
        "{text}"
    );
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 101);
    assert!((rows[0][0] - 0.1).abs() < 1e-12);
    assert!(rows
        .iter()
        .all(|r| r[1] >= 0.0 && r[2] == 0.0 && r[3] == 0.0));
    assert_eq!(rows[100][1], 0.0);
    let force: f64 = rows
        .windows(2)
        .map(|w| PI * (w[1][0] - w[0][0]) * (w[0][1] * w[0][0] + w[1][1] * w[1][0]))
        .sum();
    println!("trapezoidal force error {:e}", force / 100.0 - 1.0);
    assert!((force / 100.0 - 1.0).abs() < 1e-3, "{force}");
    std::fs::remove_dir_all(&dir).ok();
}
