//! Contact conductance correlations and units (src/heat/units.rs, src/heat/correlation.rs).
//! References: NIST SP 811 (2008) conversion factors; eq. (1.1) evaluated by hand in the report's
//! own units (ft, Btu/hr, psi: no SI on that path); identities between the laws.

use boltzone::heat::correlation::{
    effective_modulus, fluid_gap, gas_gap, radiation, ContactConductance, Correlation, Surfaces,
};
use boltzone::heat::units::*;

fn chapter5_surfaces(hardness: Pressure) -> Surfaces {
    Surfaces::new(
        [Conductivity::btu_per_hr_ft_f(100.0); 2],
        [Length::micro_inches(50.0); 2],
        [0.1 / 2f64.sqrt(); 2],
        hardness,
    )
    .unwrap()
}

#[test]
fn conversion_factors_match_nist_sp811() {
    // SP 811 Appendix B.9 values, 7 significant digits.
    let cases = [
        (Conductivity::btu_per_hr_ft_f(1.0).si(), 1.730_735),
        (Coefficient::btu_per_hr_ft2_f(1.0).si(), 5.678_263),
        (Pressure::psi(1.0).si(), 6.894_757e3),
        (Power::btu_per_hr(1.0).si(), 2.930_711e-1),
        (Length::micro_inches(1.0).si(), 2.54e-8),
        (Length::feet(1.0).si(), 0.3048),
    ];
    for (ours, nist) in cases {
        assert!((ours / nist - 1.0).abs() < 5e-7, "{ours} vs {nist}");
    }
    // The report: sigma = 5.9e-6 ft for two 50 µin surfaces.
    let s = chapter5_surfaces(Pressure::psi(150_000.0))
        .roughness()
        .to_feet();
    assert!((s - 5.9e-6).abs() < 0.01e-6, "{s}");
}

#[test]
fn round_trips_are_exact_to_rounding() {
    let x = 1234.5678;
    let pairs = [
        Length::inches(x).to_inches(),
        Length::feet(x).to_feet(),
        Length::micro_inches(x).to_micro_inches(),
        Pressure::psi(x).to_psi(),
        Conductivity::btu_per_hr_ft_f(x).to_btu_per_hr_ft_f(),
        Coefficient::btu_per_hr_ft2_f(x).to_btu_per_hr_ft2_f(),
        Conductance::btu_per_hr_f(x).to_btu_per_hr_f(),
        Resistance::f_hr_per_btu(x).to_f_hr_per_btu(),
        Power::btu_per_hr(x).to_btu_per_hr(),
        TemperatureDifference::fahrenheit_degrees(x).to_fahrenheit_degrees(),
    ];
    for y in pairs {
        // One multiplication and one division: at most 2 roundings.
        assert!((y - x).abs() <= 2.0 * f64::EPSILON * x, "{y}");
    }
    // Resistance and conductance are reciprocal in either unit system.
    let g = Conductance::btu_per_hr_f(2.0);
    let r = Resistance::from_si(1.0 / g.si());
    assert!((r.to_f_hr_per_btu() - 0.5).abs() < 1e-15);
}

#[test]
fn eq_1_1_against_the_report_units_by_hand() {
    // h = 1.45 (0.1 / sigma_ft) 100 (P/150000)^0.985 Btu/hr-ft2-F with sigma_ft = sqrt(2) 50e-6/12,
    // evaluated separately (Python, double precision) at the three Chapter V pressures.
    let by_hand = [
        (27_900.0, 469_390.716_712_479),
        (14_000.0, 237_985.485_727_773),
        (3_950.0, 68_432.514_032_219),
    ];
    let h = ContactConductance::new(
        Correlation::Cmy1969,
        chapter5_surfaces(Pressure::psi(150_000.0)),
    )
    .unwrap();
    for (p, want) in by_hand {
        let got = h
            .coefficient(Pressure::psi(p))
            .unwrap()
            .to_btu_per_hr_ft2_f();
        assert!((got / want - 1.0).abs() < 1e-12, "{p} psi: {got} vs {want}");
    }
    assert_eq!(h.coefficient(Pressure::psi(0.0)).unwrap().si(), 0.0);
}

#[test]
fn combination_rules_eq_1_2_to_1_4() {
    let s = Surfaces::new(
        [Conductivity::from_si(100.0), Conductivity::from_si(25.0)],
        [Length::from_si(3e-6), Length::from_si(4e-6)],
        [0.06, 0.08],
        Pressure::from_si(1e9),
    )
    .unwrap();
    assert!((s.conductivity().si() - 40.0).abs() < 1e-12); // 2*100*25/125
    assert!((s.roughness().si() - 5e-6).abs() < 1e-20); // 3-4-5
    assert!((s.slope() - 0.1).abs() < 1e-16);
}

#[test]
fn the_laws_coincide_where_their_parameters_do() {
    let hard = Pressure::psi(150_000.0);
    let s = chapter5_surfaces(hard);
    let pairs = [
        (Correlation::Cmy1969, 1.45, 0.985),
        (Correlation::Yovanovich1982, 1.25, 0.95),
    ];
    for (named, c, n) in pairs {
        let a = ContactConductance::new(named, s).unwrap();
        let b = ContactConductance::new(
            Correlation::PowerLaw {
                coefficient: c,
                exponent: n,
            },
            s,
        )
        .unwrap();
        for p in [10.0, 1e3, 5e4] {
            let (x, y) = (
                a.coefficient(Pressure::psi(p)).unwrap().si(),
                b.coefficient(Pressure::psi(p)).unwrap().si(),
            );
            assert!((x / y - 1.0).abs() < 1e-15);
        }
    }
    // Mikic elastic = power law 1.54, 0.94 with H replaced by m E'/sqrt(2).
    let e = effective_modulus([Pressure::psi(1e7); 2], [0.33; 2]).unwrap();
    assert!((e.to_psi() - 1e7 / (2.0 * (1.0 - 0.33 * 0.33))).abs() < 1e-6);
    let elastic = ContactConductance::new(Correlation::MikicElastic { modulus: e }, s).unwrap();
    let equivalent = chapter5_surfaces(Pressure::from_si(0.1 * e.si() / 2f64.sqrt()));
    let law = ContactConductance::new(
        Correlation::PowerLaw {
            coefficient: 1.54,
            exponent: 0.94,
        },
        equivalent,
    )
    .unwrap();
    let p = Pressure::psi(20_000.0);
    let (x, y) = (
        elastic.coefficient(p).unwrap().si(),
        law.coefficient(p).unwrap().si(),
    );
    assert!((x / y - 1.0).abs() < 1e-14, "{x} {y}");
}

#[test]
fn gap_fluid_and_radiation() {
    let k = Conductivity::from_si(0.026);
    let hf = fluid_gap(k, Length::micro_inches(100.0)).unwrap();
    assert!((hf.si() - 0.026 / 2.54e-6).abs() < 1e-9);
    let hg = gas_gap(k, Length::from_si(1e-5), Length::from_si(1e-5)).unwrap();
    assert!((hg.si() - 1300.0).abs() < 1e-9);
    // Black surfaces at 300 K: 4 sigma T^3 = 6.124004 W/m2K (by hand).
    let hr = radiation([1.0, 1.0], 300.0).unwrap();
    assert!((hr.si() - 6.124_004_372_52).abs() < 1e-9);
    // Two grey surfaces of 0.5: the factor 1/(1/e1 + 1/e2 - 1) = 1/3.
    assert!((radiation([0.5, 0.5], 300.0).unwrap().si() * 3.0 - hr.si()).abs() < 1e-12);
}

#[test]
fn bad_input_names_the_field_and_value() {
    let good = [Conductivity::from_si(1.0); 2];
    let r = [Length::from_si(1e-6); 2];
    let cases: Vec<(String, &str)> = vec![
        (
            Surfaces::new(
                [Conductivity::from_si(-3.0), good[0]],
                r,
                [0.1; 2],
                Pressure::from_si(1.0),
            )
            .unwrap_err()
            .to_string(),
            "conductivity k1 = -3",
        ),
        (
            Surfaces::new(
                good,
                [Length::from_si(0.0); 2],
                [0.1; 2],
                Pressure::from_si(1.0),
            )
            .unwrap_err()
            .to_string(),
            "combined roughness sigma = 0",
        ),
        (
            Surfaces::new(good, r, [0.1, f64::NAN], Pressure::from_si(1.0))
                .unwrap_err()
                .to_string(),
            "slope tan(theta2) = NaN",
        ),
        (
            Surfaces::new(good, r, [0.1; 2], Pressure::from_si(0.0))
                .unwrap_err()
                .to_string(),
            "hardness H = 0",
        ),
        (
            effective_modulus([Pressure::from_si(1.0); 2], [0.3, 0.7])
                .unwrap_err()
                .to_string(),
            "Poisson's ratio nu2 = 0.7",
        ),
        (
            radiation([1.2, 1.0], 300.0).unwrap_err().to_string(),
            "emissivity e1 = 1.2",
        ),
        (
            gas_gap(good[0], Length::from_si(0.0), Length::from_si(0.0))
                .unwrap_err()
                .to_string(),
            "g + M = 0",
        ),
    ];
    for (msg, want) in cases {
        assert!(msg.contains(want), "'{msg}' should contain '{want}'");
    }
    let s = Surfaces::new(good, r, [0.1; 2], Pressure::from_si(1.0)).unwrap();
    let e = ContactConductance::new(
        Correlation::PowerLaw {
            coefficient: 1.0,
            exponent: -1.0,
        },
        s,
    )
    .unwrap_err();
    assert!(e.to_string().contains("power-law exponent n = -1"));
    let h = ContactConductance::new(Correlation::Cmy1969, s).unwrap();
    let e = h.coefficient(Pressure::from_si(-5.0)).unwrap_err();
    assert!(e.to_string().contains("interface pressure P = -5"));
}
