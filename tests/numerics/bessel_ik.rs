//! e^z K₀(z), e^z K₁(z) of complex z against mpmath at 40 digits (`tests/data/hole_bessel_k.py`).

use boltzone::numerics::bessel_k::k01_scaled;
use num_complex::Complex64;

fn reference() -> Vec<[f64; 6]> {
    include_str!("../data/hole_bessel_k.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("re_z"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4], v[5]]
        })
        .collect()
}

#[test]
fn scaled_k0_k1_match_mpmath() {
    let rows = reference();
    assert!(rows.len() > 150);
    let mut worst = 0.0f64;
    for [x, y, k0r, k0i, k1r, k1i] in rows {
        let (k0, k1) = k01_scaled(Complex64::new(x, y));
        let e0 = (k0 - Complex64::new(k0r, k0i)).norm() / k0r.hypot(k0i);
        let e1 = (k1 - Complex64::new(k1r, k1i)).norm() / k1r.hypot(k1i);
        worst = worst.max(e0).max(e1);
        // Measured worst 1.0e-15 (~5 ε): ~100 summed terms no larger than the result (|arg z| ≤ 1.1
        // keeps the integrand's oscillation mild); 1e-14 leaves a factor 10 for other libms.
        assert!(e0 < 1e-14 && e1 < 1e-14, "z = {x} + {y}i: {e0:e} {e1:e}");
    }
    println!("worst relative error {worst:e}");
}

#[test]
fn derivative_recurrence_holds() {
    // Independent identity: K₁'(z) = −K₀(z) − K₁(z)/z, checked by a central difference of e^z K₁
    // along the real direction: d/dz[e^z K₁] = e^z(K₁ − K₀ − K₁/z).
    for z in [
        Complex64::new(0.7, 0.3),
        Complex64::new(5.0, 2.0),
        Complex64::new(19.0, 4.0),
    ] {
        let h = 1e-5;
        let (_, kp) = k01_scaled(z + h);
        let (_, km) = k01_scaled(z - h);
        let (k0, k1) = k01_scaled(z);
        let fd = (kp - km) / (2.0 * h);
        let exact = k1 - k0 - k1 / z;
        // central difference: truncation h²·|f'''|/6 ~ 1e-10, rounding ε/h ~ 1e-11
        assert!((fd - exact).norm() < 1e-8 * exact.norm().max(1.0), "{z}");
    }
}

#[test]
fn scaled_i0_i1_match_mpmath() {
    let rows: Vec<[f64; 6]> = include_str!("../data/hole_bessel_i.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("re_z"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4], v[5]]
        })
        .collect();
    let mut worst = 0.0f64;
    let mut checked = 0;
    for [x, y, i0r, i0i, i1r, i1i] in rows {
        // The module's domain is |arg z| ≤ 0.7 (the modes need ≤ 0.49).
        if y.atan2(x).abs() > 0.7 + 1e-12 {
            continue;
        }
        checked += 1;
        let (i0, i1) = boltzone::numerics::bessel_i::i01_scaled(Complex64::new(x, y));
        let e0 = (i0 - Complex64::new(i0r, i0i)).norm() / i0r.hypot(i0i);
        let e1 = (i1 - Complex64::new(i1r, i1i)).norm() / i1r.hypot(i1i);
        worst = worst.max(e0).max(e1);
        // The module's error budget: series rounding ε·e^(|z|(1−cos 0.7)) ≤ 2e-14, asymptotic
        // e^(−2 Re z) ≤ 5e-14 at |z| = 20; plus a few ε.
        assert!(e0 < 1e-13 && e1 < 1e-13, "z = {x} + {y}i: {e0:e} {e1:e}");
    }
    assert!(checked > 100);
    println!("worst relative error {worst:e}");
}
