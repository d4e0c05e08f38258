//! The lap-joint network (src/heat/lap.rs) against the closed form of a bonded overlap.
//!
//! With no hole and a uniform contact conductance h over the whole overlap, nothing varies across
//! the width and the joint is one-dimensional: two strips of conductance K = k W t each, coupled
//! by c = h W per unit length over the overlap l. The temperature difference between the strips
//! then obeys d'' = λ² d with λ² = 2c/K, and the overlap's resistance is
//! l/(2K) + coth(λl/2)/(Kλ), so R = (L − l)/K + l/(2K) + coth(λl/2)/(Kλ)
//! (limits: perfect bond (L − l/2)/K; weak contact (L − l)/K + 1/(c l) + l/(2K) − l/(6K)…).

use boltzone::contact::two_plate::{TwoPlateInfo, TwoPlateSolution};
use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
use boltzone::heat::joint::JointParams;
use boltzone::heat::lap::{LapError, LapJoint};
use boltzone::heat::units::{Conductivity, Length, Pressure, TemperatureDifference};

/// A uniform interface pressure p0 (psi) out to 100 in: every cell of the overlap in contact.
fn uniform_contact(p0: f64) -> TwoPlateSolution {
    TwoPlateSolution {
        r_o: 100.0,
        r_o_error: 0.0,
        converged: true,
        full_contact: true,
        overlap: 0.0,
        overlapping: false,
        report_rule: false,
        radius: vec![0.0, 100.0],
        force: vec![1.0, 1.0],
        pressure: vec![p0, p0],
        shear: vec![0.0; 2],
        gap: vec![0.0; 2],
        nut_deflection: 0.0,
        friction: None,
        info: TwoPlateInfo {
            model: "synthetic",
            levels: Vec::new(),
            observed_order: None,
            cut: None,
            compliance: Vec::new(),
            truncation_error: 0.0,
            seconds: 0.0,
        },
    }
}

fn bonded_lap(cells: usize) -> LapJoint {
    LapJoint {
        width: Length::inches(1.0),
        thickness: Length::inches(0.1),
        length: Length::inches(7.0),
        overlap: Length::inches(1.0),
        margin: Length::inches(0.5),
        hole_radius: Length::inches(0.0),
        conductivity: Conductivity::btu_per_hr_ft_f(100.0),
        drop: TemperatureDifference::fahrenheit_degrees(20.0),
        cells,
        samples: 1,
        through_thickness: false,
    }
}

fn params() -> JointParams {
    let s = Surfaces::new(
        [Conductivity::btu_per_hr_ft_f(100.0); 2],
        [Length::micro_inches(50.0); 2],
        [0.1; 2],
        Pressure::psi(150_000.0),
    )
    .unwrap();
    JointParams::new(
        ContactConductance::new(
            Correlation::PowerLaw {
                coefficient: 1.0,
                exponent: 1.0,
            },
            s,
        )
        .unwrap(),
    )
}

#[test]
fn bonded_overlap_against_its_closed_form_at_second_order() {
    // p0 chosen so that λl ≈ 2: neither limit.
    let p0 = 5.0;
    let params = params();
    let h = params.contact.coefficient(Pressure::psi(p0)).unwrap().si();
    let lap = bonded_lap(4);
    let (w, t, l, big_l) = (
        lap.width.si(),
        lap.thickness.si(),
        lap.overlap.si(),
        lap.length.si(),
    );
    let k = lap.conductivity.si() * w * t;
    let c = h * w;
    let lambda = (2.0 * c / k).sqrt();
    let r = (big_l - l) / k + l / (2.0 * k) + 1.0 / ((lambda * l / 2.0).tanh() * k * lambda);
    let exact = lap.drop.si() / r;
    eprintln!("lambda l = {:.3}, exact Q = {exact:.6} W", lambda * l);
    assert!(lambda * l > 1.0 && lambda * l < 4.0);
    let sol = uniform_contact(p0);
    let errors: Vec<f64> = [4, 8, 16, 32]
        .iter()
        .map(|&n| {
            let s = bonded_lap(n).solve(&sol, &params).unwrap();
            assert!((s.heat_flow.si() - s.cold_flow.si()).abs() < 1e-10 * exact);
            (s.heat_flow.si() / exact - 1.0).abs()
        })
        .collect();
    let rates: Vec<f64> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
    eprintln!("relative errors {errors:?}, rates {rates:?}");
    // Cell-centred finite volumes with the coupling lumped at the centres: second order.
    assert!(rates.iter().all(|&r| (r - 2.0).abs() < 0.1), "{rates:?}");
    assert!(errors[3] < 1e-4);
}

#[test]
fn chapter5_lap_and_bad_geometry() {
    let lap = LapJoint::chapter5();
    assert!((lap.solid_heat_flow().to_btu_per_hr() - 3.58).abs() < 1e-12);
    assert!((lap.width.to_inches() - 1.5036).abs() < 1e-4);
    let mut bad = lap;
    bad.margin = Length::inches(4.0);
    let e = bad.solve(&uniform_contact(1.0), &params()).unwrap_err();
    assert!(
        matches!(e, LapError::Input(_)) && e.to_string().contains("overlap/2 + margin"),
        "{e}"
    );
    let mut bad = lap;
    bad.cells = 1;
    let e = bad.solve(&uniform_contact(1.0), &params()).unwrap_err();
    assert!(e.to_string().contains("cells across the width = 1"), "{e}");
}
