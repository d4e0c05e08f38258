//! The member-stiffness rules against their published worked examples and their own integrals.

use boltzone::numerics::quadrature::{gauss_legendre, panel};
use boltzone::rules::shigley::{frustum, members, two_equal_members};
use boltzone::rules::vdi2230_stiffness::{resilience, Case};
use boltzone::rules::wileman::{member_stiffness, Material};
use std::f64::consts::PI;

/// `x` printed to `digits` significant digits equals `printed`.
fn prints_as(x: f64, printed: f64, digits: i32) -> bool {
    let scale = 10f64.powi(printed.abs().log10().floor() as i32 - digits + 1);
    ((x / scale).round() - printed / scale).abs() < 1e-6
}

#[test]
fn shigley_frusta_reproduce_the_books_solutions() {
    // Budynas & Nisbett, Shigley's MED 9th ed., solutions manual, ch. 8, p. 213 (Problem 8-22):
    // M12, d_w = 18 mm, steel 20 mm over cast iron; k in MN/m (E in GPa, lengths in mm).
    let k1 = frustum(207.0, 12.0, 18.0, 20.0).unwrap();
    let k2 = frustum(100.0, 12.0, 41.09, 2.5).unwrap();
    let k3 = frustum(100.0, 12.0, 18.0, 22.5).unwrap();
    assert!(prints_as(k1, 4470.0, 4) && prints_as(k2, 52230.0, 4) && prints_as(k3, 2074.0, 4));
    assert!(prints_as(1.0 / (1.0 / k1 + 1.0 / k2 + 1.0 / k3), 1379.0, 4));
    // p. 221: M10, d_w = 15 mm, steel 20 mm over cast iron (E = 96 GPa).
    let k1 = frustum(207.0, 10.0, 15.0, 20.0).unwrap();
    let k2 = frustum(96.0, 10.0, 38.09, 2.5).unwrap();
    let k3 = frustum(96.0, 10.0, 15.0, 22.5).unwrap();
    assert!(prints_as(k1, 3503.0, 4) && prints_as(k2, 44044.0, 5) && prints_as(k3, 1567.0, 4));
    assert!(prints_as(1.0 / (1.0 / k1 + 1.0 / k2 + 1.0 / k3), 1057.0, 4));
    // p. 215: 1/2 in bolt, four frusta (Mlbf/in, E in Mpsi).
    let f = [
        frustum(30.0, 0.5, 0.75, 0.5).unwrap(),
        frustum(14.5, 0.5, 1.327, 0.11).unwrap(),
        frustum(14.5, 0.5, 0.86, 0.515).unwrap(),
        frustum(30.0, 0.5, 0.75, 0.095).unwrap(),
    ];
    for (k, printed) in f.iter().zip([33.30, 173.8, 21.47, 97.27]) {
        assert!(prints_as(*k, printed, 4), "{k} vs {printed}");
    }
    assert!(prints_as(
        1.0 / f.iter().map(|k| 1.0 / k).sum::<f64>(),
        10.79,
        4
    ));
}

#[test]
fn shigley_example_8_2_two_steel_members() {
    // Example 8-2 (9th ed., p. 430-431): 1/2 in bolt, grip 0.5 + 0.75 + 0.095 = 1.345 in, both
    // members steel (30 Mpsi): (b) Eq. 8-22 gives 14.64 Mlbf/in, (c) Eq. 8-23 14.92 Mlbf/in.
    let l = 0.5 + 0.75 + 0.095;
    assert!(prints_as(
        two_equal_members(30.0, 0.5, l).unwrap(),
        14.64,
        4
    ));
    assert!(prints_as(
        member_stiffness(Material::Steel, 30.0, 0.5, l).unwrap(),
        14.92,
        4
    ));
    // the general stack procedure on one material with d_w = 1.5 d is Eq. 8-22, up to the
    // printed constants: Eq. 8-20's 1.155 against Eq. 8-22's 2 × 0.5774 = 1.1548 (1.7e-4)
    let stack = members(&[(0.595, 30.0), (0.75, 30.0)], 0.5, 0.75).unwrap();
    let eq22 = two_equal_members(30.0, 0.5, l).unwrap();
    assert!((stack / eq22 - 1.0).abs() < 1.7e-4, "{stack} vs {eq22}");
}

/// δ_P of VDI's cone with sleeve by quadrature: ∫ dz/(E π (r(z)² − d_h²/4)) over the clamp
/// length, r(z) = min(d_W/2 + z' tan φ, D_A/2) with z' the distance to the nearer bearing face.
fn vdi_by_quadrature(dw: f64, dh: f64, lk: f64, da: f64, e: f64, tan_phi: f64) -> f64 {
    let rule = gauss_legendre(20);
    let mut f = |z: f64| {
        let zz = z.min(lk - z);
        let r = (0.5 * dw + zz * tan_phi).min(0.5 * da);
        1.0 / (e * PI * (r * r - 0.25 * dh * dh))
    };
    // panels fine enough and with a break at every kink (the sleeve's start, the middle)
    let mut knots = vec![0.0, 0.5 * lk, lk];
    let zs = (0.5 * (da - dw) / tan_phi).max(0.0);
    if zs < 0.5 * lk {
        knots.extend([zs, lk - zs]);
    }
    knots.sort_by(f64::total_cmp);
    let mut s = 0.0;
    for w in knots.windows(2) {
        let n = 64;
        for k in 0..n {
            let a = w[0] + (w[1] - w[0]) * k as f64 / n as f64;
            let b = w[0] + (w[1] - w[0]) * (k + 1) as f64 / n as f64;
            s += panel(&rule, a, b, &mut f).0;
        }
    }
    s
}

#[test]
fn vdi2230_closed_forms_equal_the_cone_integral_in_all_three_cases() {
    let (dw, dh, lk, e) = (16.0, 11.0, 20.0, 210e3);
    for (da, case) in [
        (60.0, Case::Cone),
        (24.0, Case::ConeAndSleeve),
        (15.0, Case::Sleeve),
    ] {
        let r = resilience(dw, dh, lk, da, e).unwrap();
        assert_eq!(r.case, case, "D_A = {da}");
        let q = vdi_by_quadrature(dw, dh, lk, da, e, r.tan_phi);
        // smooth integrand on each panel: Gauss 20 on 64 panels is exact to round-off
        assert!(
            (r.compliance / q - 1.0).abs() < 1e-12,
            "{case:?}: {} vs {q}",
            r.compliance
        );
    }
    // continuity at D_A,Gr and at d_W
    let gr = resilience(dw, dh, lk, 60.0, e).unwrap().limiting_diameter;
    for x in [gr, dw] {
        let below = resilience(dw, dh, lk, x * (1.0 - 1e-9), e)
            .unwrap()
            .compliance;
        let above = resilience(dw, dh, lk, x * (1.0 + 1e-9), e)
            .unwrap()
            .compliance;
        assert!(
            (below / above - 1.0).abs() < 1e-6,
            "at {x}: {below} vs {above}"
        );
    }
}
