//! Joint conductance from the interface pressure (src/heat/joint.rs).
//! References: equilibrium (2π∫p r dr = F, so a law linear in p integrates to c (m/σ) k F/H
//! exactly); a convergence study over the contact solver's tolerance; closed forms of the gap
//! integral.

use boltzone::contact::two_plate::{solve, TwoPlateParams, TwoPlateSolution};
use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
use boltzone::heat::joint::{gap_integral, joint_conductance, rings, GasGap, JointParams};
use boltzone::heat::units::{Conductivity, Length, Pressure};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Peak, Plate};
use std::f64::consts::PI;

fn surfaces() -> Surfaces {
    Surfaces::new(
        [
            Conductivity::btu_per_hr_ft_f(100.0),
            Conductivity::btu_per_hr_ft_f(60.0),
        ],
        [Length::micro_inches(50.0), Length::micro_inches(30.0)],
        [0.08, 0.06],
        Pressure::psi(150_000.0),
    )
    .unwrap()
}

fn aluminium() -> Material {
    Material::new(1.0e7, 0.33).unwrap()
}

/// Chapter V's pair: A = D = 0.1 in, 2B = 0.26 in, 46,500 psi, C = 1.54 in.
fn chapter5_joint() -> Joint {
    let plate = Plate::new(0.1, aluminium()).unwrap();
    let load = FaceLoad::uniform(0.1, 0.13, 46_500.0).unwrap();
    Joint::new(0.1, OuterRadius::Finite(1.54), plate, plate, load).unwrap()
}

fn solved(joint: &Joint, tolerance: f64) -> TwoPlateSolution {
    solve(
        joint,
        &TwoPlateParams {
            tolerance,
            ..Default::default()
        },
    )
    .unwrap()
}

#[test]
fn exponent_one_integrates_to_the_bolt_force() {
    let (a, b) = (0.1, 0.13);
    let plate = |d| Plate::new(d, aluminium()).unwrap();
    let loads = [
        FaceLoad::uniform(a, b, 46_500.0).unwrap(),
        FaceLoad::triangular(a, b, 46_500.0, Peak::AtA).unwrap(),
        FaceLoad::triangular(a, b, 46_500.0, Peak::AtB).unwrap(),
    ];
    let mut joints: Vec<Joint> = loads
        .iter()
        .map(|l| {
            Joint::new(
                a,
                OuterRadius::Finite(1.54),
                plate(0.1),
                plate(0.1),
                l.clone(),
            )
            .unwrap()
        })
        .collect();
    // Table 2 case 5's unequal pair, 0.124 on 0.257 in.
    joints.push(
        Joint::new(
            a,
            OuterRadius::Finite(1.54),
            plate(0.124),
            plate(0.257),
            loads[0].clone(),
        )
        .unwrap(),
    );
    let s = surfaces();
    let c = 1.3;
    let law = ContactConductance::new(
        Correlation::PowerLaw {
            coefficient: c,
            exponent: 1.0,
        },
        s,
    )
    .unwrap();
    let params = JointParams::new(law);
    for (k, joint) in joints.iter().enumerate() {
        let sol = solved(joint, 2e-2);
        let g = joint_conductance(&sol, &params).unwrap();
        let force =
            Pressure::psi(joint.load().total_force()).si() * Length::inches(1.0).si().powi(2);
        let expect =
            c * s.slope() / s.roughness().si() * s.conductivity().si() * force / s.hardness().si();
        // Only rounding: the nodal forces sum to F to the LCP's residual.
        assert!(
            (g.contact.si() / expect - 1.0).abs() < 1e-9,
            "joint {k}: {} vs {expect}",
            g.contact.si()
        );
        assert!(g.contact_area > 0.0 && g.contact_nodes > 2);
        // The contact area lies between the annulus A..R_o and the nodes' supports beyond it.
        let annulus = PI * (sol.r_o.powi(2) - a * a) * 0.0254f64.powi(2);
        assert!(
            (g.contact_area / annulus - 1.0).abs() < 0.1,
            "joint {k}: area {} vs {annulus}",
            g.contact_area
        );
    }
}

#[test]
fn conductance_converges_with_the_contact_mesh() {
    let joint = chapter5_joint();
    // Level L of the contact solver halves the element size L - 1 times at A, B and R_o.
    let sols: Vec<TwoPlateSolution> = (2..=8)
        .map(|levels| {
            let p = TwoPlateParams {
                tolerance: 1e-12,
                min_levels: levels,
                max_levels: levels,
                ..Default::default()
            };
            solve(&joint, &p).unwrap()
        })
        .collect();
    for n in [0.985, 0.5] {
        let law = if n == 0.985 {
            Correlation::Cmy1969
        } else {
            Correlation::PowerLaw {
                coefficient: 1.0,
                exponent: n,
            }
        };
        let params = JointParams::new(ContactConductance::new(law, surfaces()).unwrap());
        let g: Vec<f64> = sols
            .iter()
            .map(|s| joint_conductance(s, &params).unwrap().contact.si())
            .collect();
        let d: Vec<f64> = g.windows(2).map(|w| (w[1] - w[0]).abs() / w[1]).collect();
        eprintln!("n = {n}: G_c {g:?}\n  successive relative changes {d:?}");
        if n == 0.985 {
            // Eq. (1.1) is nearly linear: from level 4 on, G_c moves by less than 2e-6 (measured
            // 1.5e-7 to 1.1e-6), far inside the solver's R_o tolerance of 5e-4.
            assert!(d[2..].iter().all(|&x| x < 2e-6), "{d:?}");
        } else {
            // The nodal rule's error sits in the last element before R_o, of size h, where
            // p ~ (R_o - r)^(1/2): there p^n deviates from its mean by ~h^(n/2), over an area ~h:
            // predicted rate 1 + n/2 = 1.25 in h (measured 1.28 over the last two halvings).
            let rate = (d[3] / d[5]).log2() / 2.0;
            assert!((rate - 1.25).abs() < 0.25, "rate {rate}, changes {d:?}");
        }
    }
}

#[test]
fn gap_integral_against_closed_forms() {
    // Constant gap g0: ∫ 2πr/(g0 + M) dr = π(r1² - r0²)/(g0 + M), wherever it starts.
    let r = [0.0, 0.5, 1.0, 2.0];
    let g = [0.3; 4];
    let got = gap_integral(&r, &g, 0.7, 0.1);
    assert!((got - PI * (4.0 - 0.49) / 0.4).abs() < 1e-13);
    // A linear gap g = r from 0, M = 1e-3 (near the edge t = sL/c is huge): ∫0^1 2πr/(r + M) dr
    // = 2π (1 - M ln((1+M)/M)).
    let m = 1e-3;
    let r = [0.0, 0.25, 1.0];
    let got = gap_integral(&r, &r, 0.0, m);
    let exact = 2.0 * PI * (1.0 - m * ((1.0 + m) / m).ln());
    assert!((got / exact - 1.0).abs() < 1e-14, "{got} vs {exact}");
    // Nearly constant slopes take the series branch: gap 1 + 1e-6 r.
    let gap = [1.0, 1.0 + 0.25e-6, 1.0 + 1e-6];
    let got = gap_integral(&r, &gap, 0.0, 0.0);
    // ∫ 2πr (1 - εr + ε²r² - ...) dr = π - 2πε/3 + πε²/2 to O(ε³).
    let e = 1e-6;
    assert!(
        (got - (PI - 2.0 * PI * e / 3.0 + PI * e * e / 2.0)).abs() < 1e-14,
        "{got}"
    );
}

#[test]
fn rings_average_the_pressure_and_gas_adds_beyond_r_o() {
    let joint = chapter5_joint();
    let sol = solved(&joint, 5e-3);
    let mut params =
        JointParams::new(ContactConductance::new(Correlation::Cmy1969, surfaces()).unwrap());
    // Rings covering the whole contact zone carry the bolt force (the linear interpolant of
    // the nodal pressures: a second-order rule, within 1 % on this mesh).
    let edges = [0.1, 0.13, 0.16, sol.r_o + 0.05];
    let rows = rings(&sol, &edges, &params).unwrap();
    let force: f64 = rows
        .iter()
        .map(|r| r.pressure * PI * (r.r_outer.powi(2) - r.r_inner.powi(2)))
        .sum();
    let f = joint.load().total_force();
    assert!((force / f - 1.0).abs() < 1e-2, "{force} vs {f}");
    assert!(rows[0].pressure > rows[1].pressure && rows[1].pressure > rows[2].pressure);
    assert!(rings(&sol, &[0.2, 0.1], &params)
        .unwrap_err()
        .to_string()
        .contains("ring 1"));
    // Gas: positive, finite, and below the bound of a zero gap over R_o..C, k/M · area.
    let k = Conductivity::from_si(0.026);
    let m = Length::micro_inches(10.0);
    params.gas = Some(GasGap {
        conductivity: k,
        rarefaction: m,
    });
    let g = joint_conductance(&sol, &params).unwrap();
    let bound = k.si() / m.si() * PI * (1.54f64.powi(2) - sol.r_o.powi(2)) * 0.0254f64.powi(2);
    assert!(
        g.gas.si() > 0.0 && g.gas.si() < bound,
        "{} vs {bound}",
        g.gas.si()
    );
    assert!((g.total.si() - g.contact.si() - g.gas.si()).abs() < 1e-12 * g.total.si());
}
