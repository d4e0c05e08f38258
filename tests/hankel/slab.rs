//! The slab solution against independent references: kernel identities, total force, face
//! conditions approached from inside, Boussinesq's half-space on the axis, the uniform-load
//! limit, equilibrium by finite differences, and the fast midplane rule against direct
//! quadrature.

use boltzone::hankel::kernel::{midplane, midplane_bound, Kernels};
use boltzone::hankel::{MidplaneCurve, MidplaneRule, QuadParams, Slab};
use boltzone::numerics::quadrature::gauss_legendre;
use boltzone::{FaceLoad, Material, Peak};

use crate::common;
use common::uniform_slab as slab;

#[test]
fn kernels_meet_the_face_conditions_and_bound() {
    // K_z(t, t) = 1 and K_τ(t, t) = 0 are the face conditions; rounding of O(1 + t) terms
    for k in 0..2000 {
        let t = 1e-6 * 1.01f64.powi(k);
        let kk = Kernels::at(t, t, 0.3);
        assert!(
            (kk.z - 1.0).abs() < 8.0 * f64::EPSILON * (1.0 + t),
            "t={t} {}",
            kk.z
        );
        assert!(
            kk.tau.abs() < 8.0 * f64::EPSILON * (1.0 + t),
            "t={t} {}",
            kk.tau
        );
        assert!(midplane(t) <= midplane_bound(t) && midplane(t) >= 0.0);
        assert!((midplane(t) - Kernels::at(t, 0.0, 0.3).z).abs() < 1e-15);
        // the overflow-free form agrees with the textbook form where that is safe
        if t < 20.0 {
            let k0 = 2.0 * (t.sinh() + t * t.cosh()) / ((2.0 * t).sinh() + 2.0 * t);
            assert!((midplane(t) - k0).abs() < 1e-13, "t={t}");
        }
    }
    assert!(Kernels::at(1e4, 5e3, 0.3).z.is_finite() && midplane(1e6) == 0.0);
}

#[test]
fn total_force_is_carried_by_the_midplane() {
    // 2π ∫ σ_z(r, 0) r dr = −F = −P π (B² − A²) (uniform and triangular loads); σ_z decays like e^(−2.1 r/D) beyond the load,
    // so [0, B + 30D] with 20-point Gauss panels of width D/4 holds everything above 1e-20
    let loads = [
        (FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(), 0.1),
        (FaceLoad::uniform(0.1, 0.13, 1.0).unwrap(), 0.2),
        (
            FaceLoad::uniform(0.1, 0.16, 1.0).unwrap(),
            0.1333333333333333,
        ),
        (
            FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA).unwrap(),
            0.1,
        ),
        (
            FaceLoad::triangular(0.1, 0.22, 1.0, Peak::AtB).unwrap(),
            0.2,
        ),
    ];
    for (load, d) in loads {
        let (a, b) = (load.inner(), load.outer());
        let s = Slab::new(d, Material::unit(0.3).unwrap(), load).unwrap();
        let r_end = b + 30.0 * d;
        let rule = MidplaneRule::new(&s, r_end, 1e-15).unwrap();
        let g = gauss_legendre(20);
        let n = (r_end / (0.25 * d)).ceil() as usize;
        let h = r_end / n as f64;
        let mut f = 0.0;
        for k in 0..n {
            for &(x, w) in g.iter() {
                let r = (k as f64 + 0.5 + 0.5 * x) * h;
                f += 0.5 * h * w * rule.eval(r).value * r;
            }
        }
        // F/(2π) from the load's closed-form moments (load.rs), not from p̄
        let exact = -s.load().total_force() / (2.0 * std::f64::consts::PI);
        assert!(
            (f - exact).abs() < 1e-9 * exact.abs(),
            "{a} {b} {d}: {f} vs {exact}"
        );
    }
}

/// Value at δ = 0 of the polynomial through (δ_i, v_i) (Neville's algorithm).
fn extrapolate_to_zero(d: &[f64], v: &[f64]) -> f64 {
    let mut p = v.to_vec();
    for k in 1..d.len() {
        for i in 0..d.len() - k {
            p[i] = (d[i + k] * p[i] - d[i] * p[i + 1]) / (d[i + k] - d[i]);
        }
    }
    p[0]
}

#[test]
fn face_conditions_hold_in_the_limit_from_inside() {
    // Approach the face z = D − δ with the interior route (no face subtraction) and
    // extrapolate the cubic through δ = 0.25, 0.5, 1, 2 (×1e-3) to δ = 0: the remainder is
    // about Πδ_i·|fourth derivative|/24 ≈ 1e-9 for a field varying on the scale of the nearest
    // load edge (≥ 0.04 here). σ_z → −p(r) and τ_rz → 0 to 1e-8 away from the edges.
    let s = slab(0.1, 0.31, 0.1);
    let p = QuadParams {
        rel_tol: 1e-13,
        ..Default::default()
    };
    let deltas = [0.25e-3, 0.5e-3, 1e-3, 2e-3];
    let limit = |v: &[f64]| extrapolate_to_zero(&deltas, v);
    for &r in &[0.0, 0.15, 0.2, 0.5] {
        let want = if (0.1..=0.31).contains(&r) { -1.0 } else { 0.0 };
        let st: Vec<_> = deltas.iter().map(|dz| s.stress(r, 0.1 - dz, &p)).collect();
        let sz = limit(&st.iter().map(|x| x.sigma_z.value).collect::<Vec<_>>());
        let tau = limit(&st.iter().map(|x| x.tau_rz.value).collect::<Vec<_>>());
        let sr = limit(&st.iter().map(|x| x.sigma_r.value).collect::<Vec<_>>());
        assert!((sz - want).abs() < 1e-8, "r={r}: σ_z → {sz}");
        assert!(tau.abs() < 1e-8, "r={r}: τ → {tau}");
        // the face route (analytic half-space terms + decaying remainders) gives the same σ_r
        let f = s.stress(r, 0.1, &p);
        assert!(
            (f.sigma_r.value - sr).abs() < 1e-8,
            "r={r}: σ_r {} vs {sr}",
            f.sigma_r.value
        );
    }
}

#[test]
fn thick_slab_tends_to_boussinesq_on_the_axis() {
    // Uniform disk (radius a, pressure p) on a half-space, on the axis at depth s
    // (Timoshenko & Goodier § 138): σ_z = −p[1 − s³/(a²+s²)^{3/2}],
    // σ_r = −(p/2)[(1+2ν) − 2(1+ν)s/√(a²+s²) + s³/(a²+s²)^{3/2}]; an annulus is the
    // difference of two disks. The far face adds O((a/D)²): the error must fall with slope ≈ −2.
    let nu = 0.3;
    let (a, b) = (0.1, 0.31);
    let disk = |rad: f64, s: f64| {
        let q = (rad * rad + s * s).sqrt();
        let c = s.powi(3) / q.powi(3);
        (
            -(1.0 - c),
            -0.5 * ((1.0 + 2.0 * nu) - 2.0 * (1.0 + nu) * s / q + c),
        )
    };
    let p = QuadParams::default();
    let mut errs = Vec::new();
    let ds = [3.0, 10.0, 30.0];
    for &d in &ds {
        let sl = slab(a, b, d);
        let mut worst: f64 = 0.0;
        for &depth in &[0.05, 0.2, 0.4] {
            let st = sl.stress(0.0, d - depth, &p);
            let (zb, rb) = disk(b, depth);
            let (za, ra) = disk(a, depth);
            worst = worst.max((st.sigma_z.value - (zb - za)).abs());
            worst = worst.max((st.sigma_r.value - (rb - ra)).abs());
            assert!((st.sigma_r.value - st.sigma_theta.value).abs() < 1e-10);
        }
        errs.push(worst);
    }
    let slope = boltzone::numerics::convergence::order_between(ds[2], errs[2], ds[0], errs[0]);
    assert!((slope + 2.0).abs() < 0.2, "errors {errs:?}, slope {slope}");
    assert!(errs[2] < 1e-4);
}

#[test]
fn wide_uniform_load_compresses_the_midplane_by_p() {
    // load on r ≤ B with B/D → ∞: σ_z(0, 0) → −P; the deficit is the far edge's influence,
    // exponentially small in B/D
    let mut last = 1.0;
    for &bd in &[2.0, 5.0, 10.0, 20.0] {
        let s = Slab::new(
            1.0,
            Material::unit(0.3).unwrap(),
            FaceLoad::uniform(0.0, bd, 1.0).unwrap(),
        )
        .unwrap();
        let e = s.sigma_z(0.0, 0.0, &QuadParams::default());
        let dev = (e.value + 1.0).abs();
        assert!(dev < last, "B/D = {bd}: {dev}");
        last = dev;
    }
    assert!(last < 1e-12, "{last}");
}

#[test]
fn interior_field_is_in_equilibrium() {
    // ∂σ_r/∂r + (σ_r − σ_θ)/r + ∂τ/∂z = 0 and ∂τ/∂r + τ/r + ∂σ_z/∂z = 0 by central
    // differences of step h: the residual must be pure O(h²) truncation, so it falls by 4 per
    // halving of h (observed slope 2 ± 0.2) and is small at the finest h.
    let s = slab(0.1, 0.31, 0.1);
    let p = QuadParams {
        rel_tol: 1e-14,
        ..Default::default()
    };
    for &(r, z) in &[(0.2, 0.05), (0.35, 0.08), (0.5, 0.02)] {
        let c = s.stress(r, z, &p);
        let residual = |h: f64| {
            let (rp, rm) = (s.stress(r + h, z, &p), s.stress(r - h, z, &p));
            let (zp, zm) = (s.stress(r, z + h, &p), s.stress(r, z - h, &p));
            let eq_r = (rp.sigma_r.value - rm.sigma_r.value) / (2.0 * h)
                + (c.sigma_r.value - c.sigma_theta.value) / r
                + (zp.tau_rz.value - zm.tau_rz.value) / (2.0 * h);
            let eq_z = (rp.tau_rz.value - rm.tau_rz.value) / (2.0 * h)
                + c.tau_rz.value / r
                + (zp.sigma_z.value - zm.sigma_z.value) / (2.0 * h);
            eq_r.abs() + eq_z.abs()
        };
        let (e1, e3) = (residual(4e-3), residual(1e-3));
        let slope = boltzone::numerics::convergence::order_between(4e-3, e1, 1e-3, e3);
        assert!(
            (slope - 2.0).abs() < 0.2,
            "({r},{z}): residuals {e1:e} {e3:e}"
        );
        // terms are O(P/D) = 10; the residual at h = D/100 is 1e-3 of that
        assert!(e3 < 1e-2, "({r},{z}): {e3:e}");
    }
}

#[test]
fn displacement_is_compatible_with_strain() {
    // ε_θ = u/r = (σ_θ − ν(σ_r + σ_z))/E and ε_z = ∂w/∂z = (σ_z − ν(σ_r + σ_θ))/E (E = 1):
    // the displacement kernels K_m, K_w against the stress kernels
    let s = slab(0.1, 0.31, 0.1);
    let p = QuadParams {
        rel_tol: 1e-13,
        ..Default::default()
    };
    for &(r, z) in &[(0.2, 0.02), (0.4, 0.05), (0.15, 0.09)] {
        let st = s.stress(r, z, &p);
        let u = s.displacement(r, z, &p).u.value;
        let eps = st.sigma_theta.value - 0.3 * (st.sigma_r.value + st.sigma_z.value);
        assert!((u / r - eps).abs() < 1e-10, "({r},{z}): {} vs {eps}", u / r);
        // ε_z = ∂w/∂z by central differences: O(h²) truncation, ≈ 1e-8 relative for h = 1e-4
        let h = 1e-4;
        let w = |z: f64| s.displacement(r, z, &p).w.value;
        let dw = (w(z + h) - w(z - h)) / (2.0 * h);
        let eps_z = st.sigma_z.value - 0.3 * (st.sigma_r.value + st.sigma_theta.value);
        assert!(
            (dw - eps_z).abs() < 1e-6 * eps_z.abs().max(1.0),
            "({r},{z}): {dw} vs {eps_z}"
        );
    }
}

#[test]
fn fast_midplane_rule_and_curve_match_direct_quadrature() {
    for load in [
        FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
        FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA).unwrap(),
    ] {
        let s = Slab::new(0.1, Material::unit(0.3).unwrap(), load).unwrap();
        let rule = MidplaneRule::new(&s, 1.5, 1e-13).unwrap();
        let curve = MidplaneCurve::new(&s, 0.0, 1.5, 1e-12).unwrap();
        for k in 0..40 {
            let r = 1.5 * k as f64 / 39.0;
            let d = s.sigma_z(
                r,
                0.0,
                &QuadParams {
                    rel_tol: 1e-14,
                    ..Default::default()
                },
            );
            let f = rule.eval(r);
            let c = curve.eval(r);
            assert!((d.value - f.value).abs() <= d.error + f.error, "r={r}");
            assert!(
                (d.value - c.value).abs() <= d.error + c.error && c.error < 1e-11,
                "r={r}"
            );
        }
    }
}

#[test]
fn load_transform_obeys_its_bounds_and_small_argument_limit() {
    // |p̄(ξ)| ≤ min(M, C₁/ξ) (used to truncate the midplane rule) on a fine grid, and
    // p̄(ξ) = ∫ p ρ dρ − ξ²∫ p ρ³ dρ/4 + O(ξ⁴) (J₀ series) at small ξ
    for load in [
        FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
        FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA).unwrap(),
        FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtB).unwrap(),
        FaceLoad::tabulated(&[0.0, 0.2, 0.5], &[2.0, 1.0, 0.0]).unwrap(),
    ] {
        let s = Slab::new(0.1, Material::unit(0.3).unwrap(), load.clone()).unwrap();
        let t = s.transform();
        let (m, c1) = (t.abs_moment(), t.decay_constant());
        for k in 1..20000 {
            let xi = 0.01 * k as f64;
            let v = t.eval(xi).abs();
            assert!(
                v <= m * (1.0 + 1e-12) && v <= c1 / xi * (1.0 + 1e-12),
                "ξ={xi}"
            );
        }
        // moments ∫ p ρ^{1,3} dρ by a fine midpoint rule (independent of both routes)
        let (a, b) = (load.inner(), load.outer());
        let n = 200_000;
        let h = (b - a) / n as f64;
        let (mut m1, mut m3) = (0.0, 0.0);
        for i in 0..n {
            let r = a + (i as f64 + 0.5) * h;
            let p = load.pressure_at(r);
            m1 += p * r * h;
            m3 += p * r * r * r * h;
        }
        let xi = 1e-3;
        let series = m1 - xi * xi * m3 / 4.0;
        assert!(
            (t.eval(xi) - series).abs() < 1e-9 * m1,
            "{} vs {series}",
            t.eval(xi)
        );
    }
}

#[test]
fn field_error_estimates_cover_the_actual_error() {
    // default tolerance (1e-12) and a looser one against a reference with 20-point panels at
    // 1e-14: every component's actual error is within its estimate, on the face, inside,
    // across the load's edges and far out
    let s = Slab::new(
        0.1,
        Material::unit(0.3).unwrap(),
        FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtB).unwrap(),
    )
    .unwrap();
    let reference = QuadParams {
        rel_tol: 1e-14,
        order: 20,
        ..Default::default()
    };
    let mut failures = Vec::new();
    for params in [
        QuadParams::default(),
        QuadParams {
            rel_tol: 1e-7,
            ..Default::default()
        },
    ] {
        for &r in &[0.0, 0.05, 0.1, 0.2, 0.31, 0.4, 1.0, 3.0] {
            for &z in &[0.0, 0.03, 0.07, 0.095, 0.1] {
                let (a, b) = (s.stress(r, z, &params), s.stress(r, z, &reference));
                let (c, d) = (
                    s.displacement(r, z, &params),
                    s.displacement(r, z, &reference),
                );
                let pairs = [
                    ("σ_r", a.sigma_r, b.sigma_r),
                    ("σ_θ", a.sigma_theta, b.sigma_theta),
                    ("σ_z", a.sigma_z, b.sigma_z),
                    ("τ", a.tau_rz, b.tau_rz),
                    ("u", c.u, d.u),
                    ("w", c.w, d.w),
                ];
                for (name, x, y) in pairs {
                    if (x.value - y.value).abs() > x.error + y.error {
                        failures.push(format!(
                            "{name} ({r},{z}) tol {:e}: {:e} ± {:.1e} vs {:e} ± {:.1e}",
                            params.rel_tol, x.value, x.error, y.value, y.error
                        ));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn surface_integral_matches_the_boussinesq_disk_deflection() {
    // W(r) = ∫ p̄ J₀ dξ for a uniform disk (radius a): (2pa/π)E(r²/a²) for r ≤ a and
    // (2pa/π)(r/a)[E(a²/r²) − (1 − a²/r²)K(a²/r²)] beyond (Timoshenko & Goodier § 138);
    // elliptic integrals (parameter m) from mpmath 1.3 at 30 digits.
    let t =
        boltzone::hankel::transform::LoadTransform::new(&FaceLoad::uniform(0.0, 1.0, 1.0).unwrap());
    let pi = std::f64::consts::PI;
    let cases = [
        (0.0, 1.0),
        (0.5, 2.0 / pi * 1.467_462_209_339_427), // E(0.25)
        (0.9, 2.0 / pi * 1.1716970527816141),    // E(0.81)
        (1.0, 2.0 / pi),                         // E(1) = 1
        (2.0, 0.258_657_904_611_341_7),          // r/a = 2
    ];
    for (r, want) in cases {
        let e = t.surface_integral(r, 1e-14);
        assert!(
            (e.value - want).abs() <= e.error.max(4.0 * f64::EPSILON),
            "r={r}: {e:?} vs {want}"
        );
        assert!(e.error < 1e-12, "r={r}: {e:?}");
    }
}

#[test]
fn ring_loads_superpose_to_the_annulus() {
    // ∫_A^B p(ρ₀) (ring-load field at ρ₀) dρ₀ = the annular-load field: Gauss–Legendre in ρ₀
    // (panels of D/2 at an interior point ≥ D/2 from the faces: the ring field is analytic in
    // ρ₀ there) against the Slab's direct transform
    let (a, b, d) = (0.1, 0.31, 0.1);
    let m = Material::unit(0.3).unwrap();
    let s = Slab::new(d, m, FaceLoad::triangular(a, b, 1.0, Peak::AtA).unwrap()).unwrap();
    let p = QuadParams {
        rel_tol: 1e-13,
        ..Default::default()
    };
    let g = gauss_legendre(20);
    for &(r, z) in &[(0.2, 0.04), (0.5, 0.0), (0.05, -0.03)] {
        let n = ((b - a) / (0.5 * d)).ceil() as usize;
        let h = (b - a) / n as f64;
        let mut acc = [0.0; 6];
        for k in 0..n {
            for &(x, w) in g.iter() {
                let rho = a + (k as f64 + 0.5 + 0.5 * x) * h;
                let (st, u) = boltzone::hankel::ring_load(d, m, rho, r, z, &p);
                let f = 0.5 * h * w * s.load().pressure_at(rho);
                let v = [
                    st.sigma_r.value,
                    st.sigma_theta.value,
                    st.sigma_z.value,
                    st.tau_rz.value,
                    u.u.value,
                    u.w.value,
                ];
                for i in 0..6 {
                    acc[i] += f * v[i];
                }
            }
        }
        let (st, u) = (s.stress(r, z, &p), s.displacement(r, z, &p));
        let want = [
            st.sigma_r.value,
            st.sigma_theta.value,
            st.sigma_z.value,
            st.tau_rz.value,
            u.u.value,
            u.w.value,
        ];
        for i in 0..6 {
            assert!(
                (acc[i] - want[i]).abs() < 1e-10,
                "({r},{z}) component {i}: {} vs {}",
                acc[i],
                want[i]
            );
        }
    }
}
