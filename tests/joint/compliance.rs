//! δ_P and k_P: the exact limits with their observed rates, the models against each other, the
//! orderings and the honesty of the error estimates (module docs of
//! `boltzone::contact::compliance`).

use boltzone::contact::compliance::{member_compliance, ComplianceParams, Head};
use boltzone::contact::two_plate::{InterfaceModel, TwoPlateParams};
use boltzone::fem::single_compliance::single_plate_compliance;
use boltzone::hankel::slab_compliance::{half_space_integral, slab_compliance};
use boltzone::numerics::convergence::order_between;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate, SinglePlate};
use std::f64::consts::PI;

const NU: f64 = 0.3;

fn steel() -> Material {
    Material::new(1.0, NU).unwrap()
}

/// k_P (1 − ν²)/(E B) of the Hankel slab 2D thick under a disk load of radius 1.
fn slab_k(d: f64) -> f64 {
    let v = slab_compliance(d, steel(), &FaceLoad::uniform(0.0, 1.0, 1.0).unwrap()).unwrap();
    assert!(v.converged, "{v:?}");
    (1.0 - NU * NU) / v.value
}

/// The hypergeometric series ₂F₁(1/2, −1/2; 2; x), summed until its terms vanish.
fn f21(x: f64) -> f64 {
    let (mut term, mut sum, mut n) = (1.0f64, 1.0f64, 0.0f64);
    while term.abs() > 1e-18 * sum {
        term *= (0.5 + n) * (-0.5 + n) / ((2.0 + n) * (n + 1.0)) * x;
        sum += term;
        n += 1.0;
    }
    sum
}

#[test]
fn half_space_closed_form_matches_the_weber_schafheitlin_series() {
    // ∫ (B J1(ξB) − A J1(ξA))²/ξ² dξ = (4/3π)(A³ + B³) − A²B ₂F₁(1/2, −1/2; 2; A²/B²): the same
    // integral from the hypergeometric form, independent of the elliptic integrals.
    for &(a, b) in &[
        (0.0f64, 1.0f64),
        (0.1, 0.31),
        (0.3, 1.0),
        (0.7, 1.0),
        (2.0, 3.0),
    ] {
        let series =
            4.0 / (3.0 * PI) * (a.powi(3) + b.powi(3)) - a * a * b * f21((a / b) * (a / b));
        let closed = half_space_integral(a, b);
        // both in round-off of a few terms of order B³
        assert!(
            (closed - series).abs() < 1e-14 * b.powi(3),
            "{a} {b}: {closed} vs {series}"
        );
    }
}

#[test]
fn thick_slab_tends_to_two_half_spaces_at_rate_one() {
    // k_P (1 − ν²)/(E B) → 3π²/32 (module docs: two half-spaces in series); a layer's
    // correction to the half-space compliance is ∝ B/D, so the error halves as D doubles.
    let limit = 3.0 * PI * PI / 32.0;
    let errs: Vec<(f64, f64)> = [8.0, 16.0, 32.0, 64.0]
        .iter()
        .map(|&d| (1.0 / d, (slab_k(d) / limit - 1.0).abs()))
        .collect();
    for w in errs.windows(2) {
        let rate = order_between(w[0].0, w[0].1, w[1].0, w[1].1);
        // the next term is O((B/D)²): at D ≥ 8B it moves the rate by well under 0.1
        assert!((rate - 1.0).abs() < 0.1, "rate {rate}: {errs:?}");
    }
    assert!(errs[3].1 < 2e-2, "{errs:?}");
}

#[test]
fn thin_slab_tends_to_the_sleeve_at_rate_one() {
    // k_P → πE B²/(2D(1 − ν²)) for A = 0, C = ∞ (module docs, the sleeve); the edge layer of
    // width ~D at r = B adds a relative O(D/B).
    let errs: Vec<(f64, f64)> = [0.04, 0.02, 0.01, 0.005]
        .iter()
        .map(|&d| {
            let sleeve = PI / (2.0 * d * (1.0 - NU * NU)) * (1.0 - NU * NU);
            (d, (slab_k(d) / sleeve - 1.0).abs())
        })
        .collect();
    for w in errs.windows(2) {
        let rate = order_between(w[0].0, w[0].1, w[1].0, w[1].1);
        assert!((rate - 1.0).abs() < 0.1, "rate {rate}: {errs:?}");
    }
    assert!(errs[3].1 < 2e-2, "{errs:?}");
}

fn joint(a: f64, b: f64, d: f64, c: Option<f64>) -> Joint {
    let j = Joint::symmetric(a, b, d, steel()).unwrap();
    match c {
        Some(c) => j.with_outer_radius(OuterRadius::Finite(c)).unwrap(),
        None => j,
    }
}

pub fn two_plate(
    j: &Joint,
    head: Head,
    tol: f64,
) -> boltzone::contact::compliance::MemberCompliance {
    let p = ComplianceParams {
        head,
        tolerance: tol,
        contact: TwoPlateParams {
            max_levels: 12,
            ..Default::default()
        },
    };
    let m = member_compliance(j, &p).unwrap();
    assert!(m.converged(), "{head:?} {:?} {:?}", m.compliance, m.levels);
    m
}

#[test]
fn thin_plates_tend_to_the_sleeve_for_both_heads() {
    // k_P → πE(B² − A²)/(2D(1 − ν²(C² − B²)/(C² − A²))) (module docs), for a pressure and a
    // rigid head alike, with an error of relative order D/(B − A).
    let (a, b, c) = (1.0, 3.0, 5.0);
    let sleeve = |d: f64| {
        PI * (b * b - a * a) / (2.0 * d * (1.0 - NU * NU * (c * c - b * b) / (c * c - a * a)))
    };
    for head in [Head::Pressure, Head::Rigid] {
        let errs: Vec<(f64, f64)> = [0.2, 0.1, 0.05]
            .iter()
            .map(|&d| {
                let k = two_plate(&joint(a, b, d, Some(c)), head, 1e-4)
                    .stiffness
                    .value;
                (d, (k / sleeve(d) - 1.0).abs())
            })
            .collect();
        for w in errs.windows(2) {
            let rate = order_between(w[0].0, w[0].1, w[1].0, w[1].1);
            // O((D/(B − A))²) next: at D ≤ 0.1 (B − A) it moves the rate by < 0.2
            assert!((rate - 1.0).abs() < 0.2, "{head:?} rate {rate}: {errs:?}");
        }
        assert!(errs[2].1 < 0.05, "{head:?} {errs:?}");
    }
}

#[test]
fn thick_plates_tend_to_two_half_spaces_for_both_heads() {
    // A = 0, C = ∞, D ≫ B: k_P (1 − ν²)/(E B) → 3π²/32 (pressure) and 1 (rigid), error ∝ B/D.
    for (head, limit) in [(Head::Pressure, 3.0 * PI * PI / 32.0), (Head::Rigid, 1.0)] {
        let errs: Vec<(f64, f64)> = [4.0, 8.0]
            .iter()
            .map(|&d| {
                let k = two_plate(&joint(0.0, 1.0, d, None), head, 1e-3)
                    .stiffness
                    .value;
                (1.0 / d, (k * (1.0 - NU * NU) / limit - 1.0).abs())
            })
            .collect();
        let rate = order_between(errs[0].0, errs[0].1, errs[1].0, errs[1].1);
        assert!((rate - 1.0).abs() < 0.25, "{head:?} rate {rate}: {errs:?}");
        assert!(errs[1].1 < 0.1, "{head:?} {errs:?}");
    }
}

#[test]
fn single_plate_fe_agrees_with_the_hankel_slab() {
    // no hole, infinite plate: the FE (cut at B + 30 D, where the rim adds no w) and the Hankel
    // slab share no code; they agree within the sum of their estimates.
    for &(b, d) in &[(1.0, 0.5), (1.0, 2.0), (3.0, 0.4)] {
        let load = FaceLoad::uniform(0.0, b, 1.0).unwrap();
        let plate = SinglePlate::new(0.0, OuterRadius::Infinite, d, steel(), load.clone()).unwrap();
        let fe = single_plate_compliance(&plate, Head::Pressure, 1e-4).unwrap();
        println!("{b} {d}: {:?}", fe.levels);
        let hk = slab_compliance(d, steel(), &load).unwrap();
        assert!(fe.compliance.converged, "{:?}", fe.levels);
        let diff = (fe.compliance.value - hk.value).abs();
        println!(
            "rel diff {:.3e} est {:.3e}",
            diff / hk.value,
            fe.compliance.error / hk.value
        );
        assert!(
            diff <= fe.compliance.error + hk.error,
            "B {b} D {d}: FE {:?} Hankel {hk:?}",
            fe.compliance
        );
    }
}

#[test]
fn symmetric_model_equals_both_plates_meshed_for_every_interface() {
    // δ_P is a difference of the two faces' displacements: the one-plate symmetric model and the
    // two meshed plates, welded, frictionless or with friction μ = 0, give the same number.
    let j = joint(0.1, 0.31, 0.1, Some(1.54));
    let reference = two_plate(&j, Head::Pressure, 1e-4).compliance;
    for interface in [
        InterfaceModel::Welded,
        InterfaceModel::Frictionless,
        InterfaceModel::Friction { mu: 0.0 },
    ] {
        let p = ComplianceParams {
            tolerance: 1e-4,
            contact: TwoPlateParams {
                both_plates: true,
                interface,
                ..Default::default()
            },
            ..Default::default()
        };
        let m = member_compliance(&j, &p).unwrap();
        let diff = (m.compliance.value - reference.value).abs();
        assert!(
            diff <= m.compliance.error + reference.error,
            "{interface:?}: {:?} vs {reference:?}",
            m.compliance
        );
    }
}

/// A random joint of the design range: A/D ∈ [0.2, 5], B/A ∈ [1.2, 4], C/B ∈ [1.5, 8] or ∞.
pub fn random_joint(rng: &mut boltzone::numerics::random::SplitMix64) -> Joint {
    let d = 1.0;
    let a = rng.log_uniform(0.2, 5.0) * d;
    let b = rng.log_uniform(1.2, 4.0) * a;
    let nu = 0.2 + 0.2 * rng.unit();
    let m = Material::new(1.0, nu).unwrap();
    let c = if rng.chance(0.2) {
        OuterRadius::Infinite
    } else {
        OuterRadius::Finite(rng.log_uniform(1.5, 8.0) * b)
    };
    Joint::new(
        a,
        c,
        Plate::new(d, m).unwrap(),
        Plate::new(d, m).unwrap(),
        FaceLoad::uniform(a, b, 1.0).unwrap(),
    )
    .unwrap()
}

/// What [`check_random_joints`] measured.
#[derive(Debug, Default)]
pub struct Honesty {
    /// Estimates checked against a tighter run.
    pub checked: usize,
    /// The largest |estimate's value − tighter value| / estimate's error.
    pub worst: f64,
    /// Tighter runs whose own error was not below the checked estimate's (the check is then
    /// against the sum of the two bars only).
    pub loose_references: usize,
}

/// The tighter run of `j` for `head` at `tol`: up to 14 levels.
fn tighter(j: &Joint, head: Head, tol: f64) -> boltzone::contact::compliance::MemberCompliance {
    member_compliance(
        j,
        &ComplianceParams {
            head,
            tolerance: tol,
            contact: TwoPlateParams {
                max_levels: 14,
                ..Default::default()
            },
        },
    )
    .unwrap()
}

/// The orderings and the estimate's honesty on `n` random joints from `seed`, at `tol`
/// against a run 100× tighter (for the rigid head too when `rigid_tight`): each estimate's
/// value within its error plus the tighter run's of the tighter value.
pub fn check_random_joints(seed: u64, n: usize, tol: f64, rigid_tight: bool) -> Honesty {
    let mut rng = boltzone::numerics::random::SplitMix64::new(seed);
    let mut h = Honesty::default();
    let start = std::time::Instant::now();
    for i in 0..n {
        let j = random_joint(&mut rng);
        let ku = two_plate(&j, Head::Pressure, tol);
        let kr = two_plate(&j, Head::Rigid, tol);
        // a rigid head imposes the same approach everywhere under it: less complementary
        // energy than the uniform pressure of the same force (Thomson–Tait), so stiffer
        let (u, r) = (ku.stiffness, kr.stiffness);
        assert!(
            u.value - u.error <= r.value + r.error,
            "{j:?}: uniform {u:?} rigid {r:?}"
        );
        // welding the interface everywhere (the single plate) can only stiffen the joint; near
        // full contact the two are equal, so the ordering is asked within the two estimates
        let s = j.single_plate_substitute().unwrap();
        let single = single_plate_compliance(&s, Head::Pressure, tol)
            .unwrap()
            .compliance;
        assert!(
            ku.compliance.value + ku.compliance.error >= single.value - single.error,
            "{j:?}: two-plate δ {:?} single δ {single:?}",
            ku.compliance
        );
        let mut line = format!(
            "joint {i} (A {:.3}, B {:.3}, C {:?}, ν {:.3}):",
            j.hole_radius(),
            j.load().outer(),
            j.outer_radius(),
            j.upper().material().poisson_ratio()
        );
        for (head, m) in [(Head::Pressure, &ku), (Head::Rigid, &kr)] {
            if head == Head::Rigid && !rigid_tight {
                continue;
            }
            let tight = tighter(&j, head, tol / 100.0);
            let actual = (m.compliance.value - tight.compliance.value).abs();
            let ratio = actual / m.compliance.error;
            h.checked += 1;
            h.worst = h.worst.max(ratio);
            h.loose_references += usize::from(tight.compliance.error >= m.compliance.error);
            line += &format!(
                " {head:?} {:.2e} of {:.2e} ({:.2}; tighter ±{:.1e}, {} levels, {:.1} s)",
                actual / m.compliance.value,
                m.compliance.error / m.compliance.value,
                ratio,
                tight.compliance.error / tight.compliance.value,
                tight.levels.len(),
                tight.seconds
            );
            assert!(
                actual <= m.compliance.error + tight.compliance.error,
                "{j:?} {head:?}: {:?} vs tighter {:?}",
                m.compliance,
                tight.compliance
            );
        }
        println!("{line} [{:.0} s]", start.elapsed().as_secs_f64());
    }
    h
}

#[test]
fn orderings_and_honest_estimates_on_random_joints() {
    // (the rigid head's 100× tighter runs take seconds each: in the ignored study)
    let h = check_random_joints(33, 6, 2e-3, false);
    println!("{h:?}");
}
