//! libm's J₀ and J₁ against mpmath at 50 digits (tests/data/bessel_j.csv, made by
//! tests/data/make_bessel.py). Error is measured relative to the local amplitude
//! min(1, √(2/(πx))) (J oscillates with that envelope, so near a zero only absolute error
//! relative to the envelope means anything). Bound: 4ε ≈ 8.9e-16 (CRATES.md measured 4.6e-16).

fn check(name: &str, f: fn(f64) -> f64, col: usize) {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/bessel_j.csv"
    ))
    .unwrap();
    let mut worst: f64 = 0.0;
    let mut n = 0;
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('x'))
    {
        let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let x = v[0];
        let amp = (2.0 / (std::f64::consts::PI * x)).sqrt().min(1.0);
        let err = (f(x) - v[col]).abs() / amp.max(v[col].abs());
        worst = worst.max(err);
        n += 1;
    }
    assert!(n > 450, "{name}: only {n} reference points");
    assert!(
        worst <= 4.0 * f64::EPSILON,
        "{name}: worst error {worst:e} relative to the amplitude"
    );
}

#[test]
fn j0_matches_mpmath() {
    check("J0", libm::j0, 1);
}

#[test]
fn j1_matches_mpmath() {
    check("J1", libm::j1, 2);
}

#[test]
fn integral_of_j0_matches_mpmath() {
    // Ji₀ = ∫₀^x J₀ (used by the transform of sloped load pieces) against mpmath's Struve form;
    // Ji₀ is O(1) everywhere (→ 1 as x → ∞), so the error is absolute. Bound: 16ε, for the
    // up-to-14 Gauss panels summed for 2 < x < 40 and the asymptotic sum beyond.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/bessel_j.csv"
    ))
    .unwrap();
    let mut worst: f64 = 0.0;
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('x'))
    {
        let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let err = (boltzone::numerics::integral_j0::integral_j0(v[0]) - v[3]).abs()
            / v[3].abs().clamp(1e-300, 1.0);
        assert!(err <= 16.0 * f64::EPSILON, "x = {}: error {err:e}", v[0]);
        worst = worst.max(err);
    }
    println!("worst Ji0 error {worst:e}");
}
