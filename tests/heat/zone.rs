//! The contact-zone resistance by conduction FE (`heat::zone`) against the thin-plate closed
//! form: two equal plates A ≤ r ≤ R_e joined by a uniform h, rims at 1 and 0. With T uniform
//! through each plate, θ = T₁ − T₂ obeys θ'' + θ'/r = m²θ, m² = 2h/(kt), θ'(A) = 0, θ(R_e) = 1,
//! and T₁ + T₂ = 1, so Q = kt·π R_e θ'(R_e) with θ = [I₀(mr)K₁(mA) + K₀(mr)I₁(mA)]/(same at R_e).
//! The FE resolves the through-thickness gradient the fin model neglects: their difference is
//! the fin model's error, of first order in the Biot number ht/k. Halving t at fixed m (h ∝ t)
//! (Bi = (mt)²/2) quarters the Biot number: the observed rate must be 2 in t.

use boltzone::heat::units::{Conductivity, Length};
use boltzone::heat::zone::{resistance_with, Zone};
use boltzone::numerics::bessel_i::i01_scaled;
use boltzone::numerics::bessel_k::k01_scaled;
use num_complex::Complex64;
use std::f64::consts::PI;

/// (I₀, I₁, K₀, K₁) at x > 0.
fn bessel(x: f64) -> [f64; 4] {
    let z = Complex64::new(x, 0.0);
    let (i0, i1) = i01_scaled(z);
    let (k0, k1) = k01_scaled(z);
    [
        i0.re * x.exp(),
        i1.re * x.exp(),
        k0.re / x.exp(),
        k1.re / x.exp(),
    ]
}

/// ΔT/Q of the fin model, K/W (SI lengths).
fn fin_resistance(a: f64, re: f64, k: f64, t: f64, m: f64) -> f64 {
    let [_, i1a, _, k1a] = bessel(m * a);
    let [i0r, i1r, k0r, k1r] = bessel(m * re);
    let theta_r = i0r * k1a + k0r * i1a;
    let dtheta = m * (i1r * k1a - k1r * i1a) / theta_r;
    1.0 / (k * t * PI * re * dtheta)
}

#[test]
fn uniform_h_approaches_the_fin_closed_form_at_rate_two_in_thickness() {
    let (a, re, k, m) = (0.1, 0.75, 100.0, 60.0); // in, in, W/(m·K), 1/m
    let inch = 0.0254;
    let mut diff = Vec::new();
    for t in [0.1, 0.05] {
        let h = 0.5 * m * m * k * t * inch; // m² = 2h/(kt)
        let zone = Zone {
            outer_radius: re,
            thickness: [t, t],
            conductivity: Conductivity::from_si(k),
            radial: 48,
            axial: 2,
        };
        let fe = resistance_with(a, &|_| h, Length::inches(1.0), &zone).unwrap();
        let fin = fin_resistance(a * inch, re * inch, k, t * inch, m);
        diff.push((fe.resistance.si() / fin - 1.0).abs());
        println!(
            "t = {t} in: Bi = {:.1e}, FE {:.6e} K/W, fin {fin:.6e} K/W, difference {:.2e}",
            h * t * inch / k,
            fe.resistance.si(),
            diff.last().unwrap()
        );
    }
    let rate = (diff[0] / diff[1]).log2();
    assert!(
        (rate - 2.0).abs() < 0.2,
        "rate {rate}, differences {diff:?}"
    );
    assert!(diff[1] < 1e-2, "{diff:?}");
}
