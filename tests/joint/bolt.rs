//! The bolt: ISO thread areas against ISO 898-1's table, and the M10 joint end to end.

use boltzone::bolt::compliance::{bolt_resilience, load_factor};
use boltzone::bolt::preload::{
    bearing_pressure, preload_from_torque, preload_from_utilisation, PropertyClass,
};
use boltzone::bolt::thread::Thread;
use boltzone::contact::compliance::{member_compliance, ComplianceParams, Head};
use boltzone::rules::vdi2230_stiffness::resilience;
use boltzone::{Joint, Material, OuterRadius};

#[test]
fn stress_areas_match_iso_898_1() {
    // ISO 898-1:2013 Table 4 (coarse threads), A_s,nom in mm², printed to three digits
    let table = [
        ("M3", 5.03f64),
        ("M4", 8.78),
        ("M5", 14.2),
        ("M6", 20.1),
        ("M8", 36.6),
        ("M10", 58.0),
        ("M12", 84.3),
        ("M14", 115.0),
        ("M16", 157.0),
        ("M18", 192.0),
        ("M20", 245.0),
        ("M22", 303.0),
        ("M24", 353.0),
        ("M27", 459.0),
        ("M30", 561.0),
        ("M33", 694.0),
        ("M36", 817.0),
    ];
    stress_areas_match_to_three_digits(&table);
    assert!(Thread::metric_coarse("M11").is_err());
}

/// Each size's metric stress area against the printed value (mm², three significant digits).
pub fn stress_areas_match_to_three_digits(table: &[(&str, f64)]) {
    for &(size, printed) in table {
        let t = Thread::lookup(size).unwrap();
        assert_eq!(t.form, boltzone::bolt::thread::Form::Metric, "{size}");
        let a = t.stress_area();
        let scale = 10f64.powi(printed.log10().floor() as i32 - 2);
        assert_eq!(
            (a / scale).round(),
            (printed / scale).round(),
            "{size}: {a}"
        );
    }
}

#[test]
fn m10_joint_end_to_end() {
    // M10 8.8 through two 10 mm steel plates (outside diameter 40 mm), 40 N·m, μ_G = μ_K = 0.12;
    // bearing diameter d_W = 14.63 mm (ISO 4017 grade A d_w,min), hole 11 mm (ISO 273 medium).
    let t = Thread::metric_coarse("M10").unwrap();
    let (dw, dh, lk, da, e) = (14.63, 11.0, 20.0, 40.0, 205e3);
    let f = preload_from_torque(&t, 40e3, 0.12, 0.12, dw, dh).unwrap();
    // the torque the preload needs, summed term by term (thread pitch, flank, head friction)
    let m =
        f * 0.16 * 1.5 + f * 0.58 * (10.0 - 0.649519 * 1.5) * 0.12 + f * 0.25 * (dw + dh) * 0.12;
    assert!((m / 40e3 - 1.0).abs() < 1e-12);
    // below the preload that uses 90 % of R_p0.2 (40 N·m is under VDI's tabulated torque)
    let f_zul = preload_from_utilisation(&t, PropertyClass::C8_8, 0.9, 0.12).unwrap();
    assert!(f < f_zul, "{f} vs {f_zul}");
    let steel = Material::new(e, 0.3).unwrap();
    let joint = Joint::symmetric(0.5 * dh, 0.5 * dw, 10.0, steel)
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(0.5 * da))
        .unwrap();
    let exact = member_compliance(
        &joint,
        &ComplianceParams {
            head: Head::Pressure,
            tolerance: 5e-4,
            ..Default::default()
        },
    )
    .unwrap();
    assert!(exact.converged());
    let vdi = resilience(dw, dh, lk, da, e).unwrap();
    let ds = bolt_resilience(&t, lk, 0.0, e, e).unwrap();
    let phi = load_factor(ds, exact.compliance.value, 1.0).unwrap();
    let phi_vdi = load_factor(ds, vdi.compliance, 1.0).unwrap();
    println!(
        "M10: F_M {f:.0} N, k_P {:.4e} ± {:.1e} N/mm (VDI {:.4e}), δ_S {ds:.4e} mm/N, Φ_K {phi:.4} (VDI {phi_vdi:.4}), p {:.1} MPa",
        exact.stiffness.value, exact.stiffness.error, vdi.stiffness, bearing_pressure(f, dw, dh)
    );
    // the bolt is the softer spring and the members carry most of an external load's relief
    assert!(phi > 0.0 && phi < 0.5 && ds > exact.compliance.value);
}
