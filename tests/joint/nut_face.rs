//! Head and nut of their own (issue 33, item 5): the nut's bearing face A..B₂ differs from the
//! head's A..B₁ (`Joint::with_nut_load`). Checked: B₂ = B₁ is today's symmetric joint; the
//! interface carries the preload; swapping head and nut gives the same k_P and the same
//! interface (the mirrored joint); thick plates tend to two half-spaces in series, each under
//! its own face, at rate one; the routes that press both faces alike refuse by key; the
//! front ends (`two --b2`, `load.nut_outer_radius`) agree bit for bit.

// k_P's study at a tolerance (up to 12 levels), asserted converged
use super::builders::{own_faces, two_line};
use super::compliance::two_plate as stiffness;
use crate::common::{boltzone, json_of};
use boltzone::contact::compliance::{member_compliance, ComplianceParams, Head};
use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::joint::Asymmetry;
use boltzone::numerics::convergence::order_between;
use boltzone::route::two_plate::{self, Key, Question};
use boltzone::route::Method;
use boltzone::rules::{shigley, vdi2230_stiffness};
use boltzone::{FaceLoad, Joint, Material, OuterRadius};
use std::f64::consts::PI;

const NU: f64 = 0.3;

fn steel() -> Material {
    Material::new(1.0, NU).unwrap()
}

/// Two equal plates D thick, the head's unit pressure on A..B₁, the nut's face A..B₂ carrying
/// the same force.
fn nut_joint(a: f64, b1: f64, b2: f64, d: f64, c: Option<f64>) -> Joint {
    own_faces(a, b1, b2, d, c, steel())
}

#[test]
fn equal_faces_are_todays_symmetric_joint() {
    let j = Joint::symmetric(0.1, 0.31, 0.1, steel())
        .unwrap()
        .with_outer_radius(OuterRadius::Finite(1.54))
        .unwrap();
    // B₂ = B₁: the same joint, so the same (symmetric) path, bit for bit
    let same = j.clone().with_nut_load(j.load().clone()).unwrap();
    assert_eq!(same, j);
    assert!(same.is_symmetric() && !same.has_own_nut_load());
    let sym = stiffness(&j, Head::Pressure, 1e-4);
    assert!(sym.contact.info.model.starts_with("symmetric"));
    // B₂ a hair from B₁: both plates meshed (the path of unequal faces), the same k_P within
    // the two bars (the physical change, ~1e-7 relative, is far below them)
    let near = nut_joint(0.1, 0.31, 0.31 * (1.0 + 1e-7), 0.1, Some(1.54));
    assert_eq!(near.asymmetry(), Some(Asymmetry::NutFace));
    let two = stiffness(&near, Head::Pressure, 1e-4);
    assert_eq!(two.contact.info.model, "frictionless");
    let diff = (two.stiffness.value - sym.stiffness.value).abs();
    println!(
        "k_P symmetric {:?}, both plates {:?}: diff {diff:.3e} ({:.2} of the bars)",
        sym.stiffness,
        two.stiffness,
        diff / (sym.stiffness.error + two.stiffness.error)
    );
    assert!(diff <= sym.stiffness.error + two.stiffness.error);
    let dr = (two.contact.r_o - sym.contact.r_o).abs();
    assert!(
        dr <= two.contact.r_o_error + sym.contact.r_o_error,
        "R_o {} vs {}",
        two.contact.r_o,
        sym.contact.r_o
    );
}

#[test]
fn the_interface_carries_the_preload() {
    // equilibrium of each plate: the interface forces sum to the bolt force, whichever face is
    // wider (the nodal forces are totals around the circle)
    for b2 in [0.22, 0.45] {
        let j = nut_joint(0.1, 0.31, b2, 0.1, Some(1.54));
        let f = j.load().total_force();
        assert!((j.nut_load().total_force() / f - 1.0).abs() < 1e-15);
        let s = solve(&j, &TwoPlateParams::default()).unwrap();
        assert!(s.converged, "B2 {b2}: {s:?}");
        let sum: f64 = s.force.iter().sum();
        println!(
            "B2 {b2}: interface {sum:.15e}, bolt {f:.15e}, R_o {}",
            s.r_o
        );
        assert!((sum / f - 1.0).abs() < 1e-9, "B2 {b2}: {sum} vs {f}");
        // (the pressure vanishes beyond R_o)
        assert!(s
            .radius
            .iter()
            .zip(&s.pressure)
            .all(|(r, p)| *r <= s.r_o + 1e-9 || *p == 0.0));
    }
}

#[test]
fn swapping_head_and_nut_mirrors_the_joint() {
    // equal plates: the joint with (B₁, B₂) is the mirror image of the one with (B₂, B₁), so
    // k_P, R_o and the interface pressure are the same (δ_P is symmetric in the two faces)
    let (a, b1, b2, d, c) = (0.1, 0.31, 0.45, 0.1, 1.54);
    let j12 = nut_joint(a, b1, b2, d, Some(c));
    let wide = j12.nut_load().clone();
    let j21 = Joint::new(
        a,
        OuterRadius::Finite(c),
        j12.upper(),
        j12.lower(),
        wide.clone(),
    )
    .unwrap()
    .with_nut_load(j12.load().clone())
    .unwrap();
    assert_eq!((j21.load(), j21.nut_load()), (&wide, j12.load()));
    for head in [Head::Pressure, Head::Rigid] {
        let (m12, m21) = (stiffness(&j12, head, 1e-4), stiffness(&j21, head, 1e-4));
        let dk = (m12.stiffness.value - m21.stiffness.value).abs();
        println!(
            "{head:?}: k_P {:?} vs {:?}, |diff|/k {:.2e}",
            m12.stiffness,
            m21.stiffness,
            dk / m12.stiffness.value
        );
        assert!(dk <= m12.stiffness.error + m21.stiffness.error);
        if head == Head::Pressure {
            let (s12, s21) = (&m12.contact, &m21.contact);
            let dr = (s12.r_o - s21.r_o).abs();
            println!("R_o {} vs {}: {dr:.2e}", s12.r_o, s21.r_o);
            assert!(dr <= s12.r_o_error + s21.r_o_error);
            // the interface pressure of one, read at the other's nodes (the meshes differ
            // only where R_o's estimate placed its grading)
            let pmax = s12.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
            let worst = s21
                .radius
                .iter()
                .zip(&s21.pressure)
                .filter(|(r, _)| (**r - s12.r_o).abs() > 4.0 * s12.r_o_error.max(1e-3))
                .map(|(r, p)| (s12.pressure_at(*r) - p).abs())
                .fold(0.0f64, f64::max);
            println!(
                "interface pressure: max |diff| {:.2e} of max p",
                worst / pmax
            );
            assert!(worst < 1e-2 * pmax, "{worst} of {pmax}");
        }
    }
}

#[test]
fn thick_plates_tend_to_two_half_spaces_each_under_its_own_face() {
    // A = 0, C = ∞, D ≫ B: each face indents its own half-space, in series:
    // δ_P = (1 − ν²)/E · c (1/B₁ + 1/B₂), c = 16/(3π²) for a uniform pressure (mean
    // displacement under a disk, Johnson §3.4) and 1/2 for a rigid punch (Boussinesq); the
    // error falls like B/D.
    let (b1, b2) = (1.0, 1.5);
    for (head, c) in [(Head::Pressure, 16.0 / (3.0 * PI * PI)), (Head::Rigid, 0.5)] {
        let limit = 1.0 / (c * (1.0 / b1 + 1.0 / b2));
        let errs: Vec<(f64, f64)> = [6.0, 12.0]
            .iter()
            .map(|&d| {
                let k = stiffness(&nut_joint(0.0, b1, b2, d, None), head, 1e-3)
                    .stiffness
                    .value;
                (1.0 / d, (k * (1.0 - NU * NU) / limit - 1.0).abs())
            })
            .collect();
        let rate = order_between(errs[0].0, errs[0].1, errs[1].0, errs[1].1);
        println!("{head:?}: errors {errs:?}, rate {rate:.3}");
        assert!((rate - 1.0).abs() < 0.25, "{head:?} rate {rate}: {errs:?}");
        assert!(errs[1].1 < 0.1, "{head:?} {errs:?}");
    }
}

/// The stack's bending limit of δ_P for thin plates whose faces differ (B₁ ≠ B₂, pressures p₁
/// on A..B₁ and p₂ on A..B₂ of the same force F): the two equal plates, frictionless and in
/// contact, bend together as one Kirchhoff plate of rigidity 2·E D³/(12(1 − ν²)) under the
/// self-equilibrated load q = p₁χ(A..B₁) − p₂χ(A..B₂), free at A and C. Returns (δ_P from the
/// bending energy, 2U/F²; δ_P from the work of q, ∫ q w dA/F²): two formulas that agree only
/// if the slope solves the plate's equations.
///
/// With φ = w′ and V(r) = ∫_A^r q ρ dρ (V(A) = V(C) = 0): the shear Q_r(A) = 0 gives
/// (∇²w)′ = V/(D_b r), so ∇²w = (rφ)′/r = G + c₁ with G = ∫_A^r V/(D_b s) ds and
/// φ = (H + c₁(r² − A²)/2 + c₂)/r, H = ∫_A^r ρ G dρ; M_r ∝ φ′ + νφ/r = 0 at A and C fixes c₁,
/// c₂. U = π D_b ∫ (φ′² + 2ν φ φ′/r + φ²/r²) r dr; the work ∫ q w 2πr dr = −2π ∫ V φ dr.
fn kirchhoff_stack(a: f64, b1: f64, b2: f64, c: f64, d: f64, nu: f64) -> (f64, f64) {
    let f = PI * (b1 * b1 - a * a); // p₁ = 1
    let p2 = f / (PI * (b2 * b2 - a * a));
    let v = |r: f64| 0.5 * ((r.min(b1).powi(2) - a * a) - p2 * (r.min(b2).powi(2) - a * a));
    let rigidity = 2.0 / (12.0 * (1.0 - nu * nu)) * d.powi(3); // E = 1
                                                               // cumulative trapezoids on a fine grid with nodes at A, B₁, B₂, C (V is smooth between)
    let mut knots = [a, b1, b2, c];
    knots.sort_by(f64::total_cmp);
    let per = 40_000;
    let mut r = vec![a];
    for w in knots.windows(2) {
        r.extend((1..=per).map(|i| w[0] + (w[1] - w[0]) * i as f64 / per as f64));
    }
    let cumulative = |g: &dyn Fn(usize) -> f64| {
        let mut s = vec![0.0];
        for i in 1..r.len() {
            s.push(s[i - 1] + 0.5 * (r[i] - r[i - 1]) * (g(i) + g(i - 1)));
        }
        s
    };
    let g = cumulative(&|i| v(r[i]) / (rigidity * r[i]));
    let h = cumulative(&|i| r[i] * g[i]);
    let n = r.len() - 1;
    // c₁ = (1 − ν)c₂/A² (free at A); free at C: G + c₁ − (1 − ν)φ/r = 0
    let k = (1.0 - nu) / (a * a);
    let c2 = -(g[n] - (1.0 - nu) * h[n] / (c * c))
        / (k - (1.0 - nu) / (c * c) * (k * (c * c - a * a) / 2.0 + 1.0));
    let c1 = k * c2;
    let phi: Vec<f64> = (0..=n)
        .map(|i| (h[i] + c1 * (r[i] * r[i] - a * a) / 2.0 + c2) / r[i])
        .collect();
    let dphi = |i: usize| g[i] + c1 - phi[i] / r[i];
    let energy = cumulative(&|i| {
        let (p, dp, x) = (phi[i], dphi(i), r[i]);
        (dp * dp + 2.0 * nu * p * dp / x + p * p / (x * x)) * x
    })[n]
        * PI
        * rigidity;
    let work = -2.0 * PI * cumulative(&|i| v(r[i]) * phi[i])[n];
    (2.0 * energy / (f * f), work / (f * f))
}

#[test]
fn thin_plates_with_their_own_faces_bend_or_tend_to_the_narrower_sleeve() {
    // D ≪ B − A with B₁ < B₂ (module docs of contact::compliance):
    // - rigid head and nut: the stack is squeezed between them over A..B₁ only (the nut's
    //   face beyond B₁ presses an unloaded plate, which would have to bend to take load: a
    //   stiffness O(D³)), so k_P → the sleeve of B = min(B₁, B₂), error O(D/(B₁ − A)) from the
    //   edge layer, as with equal faces;
    // - pressures: the faces' loads do not balance through the thickness, their difference
    //   bends the stack (compliance O(1/D³) against the sleeve's O(D)): k_P → the Kirchhoff
    //   limit of `kirchhoff_stack`, relative error O((D/L)²) (transverse shear).
    let (a, c) = (1.0, 5.0);
    let sleeve = |b: f64, d: f64| {
        PI * (b * b - a * a) / (2.0 * d * (1.0 - NU * NU * (c * c - b * b) / (c * c - a * a)))
    };
    let (b1, b2) = (3.0, 4.0);
    let rigid: Vec<(f64, f64)> = [0.2, 0.1, 0.05]
        .iter()
        .map(|&d| {
            let m = stiffness(&nut_joint(a, b1, b2, d, Some(c)), Head::Rigid, 1e-3);
            println!("  rigid D {d}: {:?} {:.1} s", m.stiffness, m.seconds);
            (d, (m.stiffness.value / sleeve(b1, d) - 1.0).abs())
        })
        .collect();
    println!("rigid: errors {rigid:?}");
    assert!(rigid[2].1 < 0.02, "{rigid:?}");
    for w in rigid.windows(2) {
        let rate = order_between(w[0].0, w[0].1, w[1].0, w[1].1);
        println!("  rate {rate:.3}");
        // as for equal faces: O((D/(B − A))²) next moves the rate by < 0.2 at D ≤ 0.1 (B − A)
        assert!((rate - 1.0).abs() < 0.2, "rigid rate {rate}: {rigid:?}");
    }
    let (b1, b2) = (2.0, 3.0);
    let pressure: Vec<(f64, f64)> = [0.2, 0.1, 0.05]
        .iter()
        .map(|&d| {
            let (by_energy, by_work) = kirchhoff_stack(a, b1, b2, c, d, NU);
            assert!(
                (by_energy / by_work - 1.0).abs() < 1e-8,
                "{by_energy} vs {by_work}"
            );
            let m = stiffness(&nut_joint(a, b1, b2, d, Some(c)), Head::Pressure, 1e-3);
            println!("  pressure D {d}: {:?} {:.1} s", m.stiffness, m.seconds);
            (d, (m.stiffness.value * by_energy - 1.0).abs())
        })
        .collect();
    println!("pressure: errors {pressure:?}");
    for w in pressure.windows(2) {
        let rate = order_between(w[0].0, w[0].1, w[1].0, w[1].1);
        println!("  rate {rate:.3}");
        // the leading correction is O((D/L)²): the errors fall at least that fast
        assert!(rate > 1.8, "pressure rate {rate}: {pressure:?}");
    }
    assert!(pressure[2].1 < 1e-3, "{pressure:?}");
}

#[test]
fn routes_that_press_both_faces_alike_refuse_by_key() {
    let j = nut_joint(0.1, 0.31, 0.4, 0.1, None);
    assert!(j.single_plate_substitute().is_none());
    assert_eq!(j.asymmetry(), Some(Asymmetry::NutFace));
    let mut q = Question::new(&j, 1e-6);
    q.method = Method::Hankel;
    assert_eq!(two_plate::plan(&q).unwrap_err().key, Key::NutOuterRadius);
    assert_eq!(
        two_plate::table_answer(&q).unwrap_err().key,
        Key::NutOuterRadius
    );
    // auto goes to the finite elements, at any tolerance
    q.method = Method::Auto;
    for tol in [1e-6, 5e-3] {
        q.tolerance = tol;
        assert_eq!(two_plate::plan(&q).unwrap().method, Method::Fem, "{tol}");
    }
    // the nut's force must be the head's
    let j0 = Joint::symmetric(0.1, 0.31, 0.1, steel()).unwrap();
    let e = j0
        .with_nut_load(FaceLoad::uniform(0.1, 0.4, 1.0).unwrap())
        .unwrap_err();
    assert!(e.to_string().contains("nut load"), "{e}");
}

#[test]
fn the_rules_take_each_side_its_own_diameter() {
    let (dh, lk, da, e) = (11.0, 20.0, 40.0, 210e3);
    let one = |dw: f64| vdi2230_stiffness::resilience(dw, dh, lk, da, e).unwrap();
    let sides = |dw: [f64; 2]| vdi2230_stiffness::resilience_sides(dw, dh, lk, da, e).unwrap();
    assert_eq!(sides([16.0, 16.0]), one(16.0));
    assert_eq!(
        sides([16.0, 14.6]).compliance,
        sides([14.6, 16.0]).compliance
    );
    // each body half of its own symmetric one, by the cone integral itself: ∫ dz/(E π (r² −
    // d_h²/4)) from each face to the middle (case Cone here: D_A ≥ D_A,Gr on both sides)
    let half_cone = |dw: f64| {
        let r = one(dw);
        assert_eq!(r.case, vdi2230_stiffness::Case::Cone);
        let n = 20_000;
        let h = 0.5 * lk / n as f64;
        (0..n)
            .map(|i| {
                let z = (i as f64 + 0.5) * h;
                let rad = 0.5 * dw + z * r.tan_phi;
                h / (e * PI * (rad * rad - 0.25 * dh * dh))
            })
            .sum::<f64>()
    };
    let by_quadrature = half_cone(16.0) + half_cone(14.6);
    let rel = (sides([16.0, 14.6]).compliance / by_quadrature - 1.0).abs();
    assert!(rel < 1e-8, "{rel}");
    let stack = [(10.0, e), (10.0, e)];
    let k = |dw: [f64; 2]| shigley::members_sides(&stack, 10.0, dw).unwrap();
    assert_eq!(
        k([16.0, 16.0]),
        shigley::members(&stack, 10.0, 16.0).unwrap()
    );
    assert!((k([16.0, 14.6]) / k([14.6, 16.0]) - 1.0).abs() < 1e-15);
    // the series of the two sides: 1/k = (1/k(d1) + 1/k(d2))/2 for equal members
    let series = 2.0 / (1.0 / k([16.0, 16.0]) + 1.0 / k([14.6, 14.6]));
    assert!((k([16.0, 14.6]) / series - 1.0).abs() < 1e-14);
}

/// `two` on the plates (D, C, E) in `units` with the joint's flags `joint`, asking k_P by the
/// finite elements as JSON.
fn fe_line<'a>(units: &'a str, plates: [&'a str; 3], joint: &[&'a str]) -> Vec<&'a str> {
    let mut line = two_line(units, plates, joint);
    line.extend(["--stiffness", "--method", "fem", "--json"]);
    line
}

/// The M10-sized joint of the `two` lines, in mm-MPa-N.
fn two() -> Vec<&'static str> {
    let joint = ["--a", "5.5", "--b", "8", "--force", "20e3"];
    fe_line("mm-MPa-N", ["10", "20", "205e3"], &joint)
}

#[test]
fn two_b2_is_the_library_joint_and_b2_equal_to_b_changes_nothing() {
    let plain = json_of(&boltzone(&two()));
    let mut same = two();
    same.extend(["--b2", "8"]);
    let same = json_of(&boltzone(&same));
    for key in [
        "r_o",
        "r_o_error",
        "member_stiffness",
        "rules_member_stiffness",
    ] {
        assert_eq!(plain[key], same[key], "{key}");
    }
    let mut own = two();
    own.extend(["--b2", "9.5"]);
    let own = json_of(&boltzone(&own));
    let steel = Material::new(205e3, 0.3).unwrap();
    let j = own_faces(5.5, 8.0, 9.5, 10.0, Some(20.0), steel);
    let m = member_compliance(&j, &ComplianceParams::default()).unwrap();
    let k = own["member_stiffness"]["value"].as_f64().unwrap();
    // the CLI's force and the library's unit pressure: the linear problem agrees to rounding
    assert!(
        (k / m.stiffness.value - 1.0).abs() < 1e-9,
        "{k} vs {:?}",
        m.stiffness
    );
    // a wider nut face stiffens the joint
    assert!(k > plain["member_stiffness"]["value"].as_f64().unwrap());
    // bearing pressures are not asked without a bolt; the rules take 2B and 2B2
    let vdi = own["rules_member_stiffness"]["vdi2230"]["stiffness"]
        .as_f64()
        .unwrap();
    let want = vdi2230_stiffness::resilience_sides([16.0, 19.0], 11.0, 20.0, 40.0, 205e3)
        .unwrap()
        .stiffness;
    assert_eq!(vdi, want);
}

#[test]
fn scene_nut_outer_radius_is_two_b2() {
    // (in m-Pa-N, as the scene solves in SI: the same bits reach the solver)
    let scene = "units = \"m-Pa-N\"\nmethod = \"fem\"\n[hole]\nradius = 0.0055\n[load]\n\
                 outer_radius = 0.008\nnut_outer_radius = 0.0095\nforce = 20e3\n[[plates]]\n\
                 thickness = 0.01\nmaterial = { E = 205e9, nu = 0.3 }\n[joint]\n\
                 outer_radius = 0.02\n[outputs]\nstiffness = true\n";
    let dir = std::env::temp_dir().join(format!("boltzone-nut-face-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("nut.toml");
    std::fs::write(&path, scene).unwrap();
    let s = json_of(&boltzone(&["solve", path.to_str().unwrap(), "--json"]));
    let joint = [
        "--a", "0.0055", "--b", "0.008", "--b2", "0.0095", "--force", "20e3",
    ];
    let t = json_of(&boltzone(&fe_line(
        "m-Pa-N",
        ["0.01", "0.02", "205e9"],
        &joint,
    )));
    for key in [
        "r_o",
        "member_stiffness",
        "member_compliance",
        "rules_member_stiffness",
    ] {
        assert_eq!(s[key], t[key], "{key}");
    }
    // bad values named by key and by flag
    let bad = scene.replace("nut_outer_radius = 0.0095", "nut_outer_radius = 0.005");
    std::fs::write(&path, bad).unwrap();
    let out = boltzone(&["solve", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("load.nut_outer_radius"));
    let single = scene.replace("method = \"fem\"", "model = \"single-plate\"");
    std::fs::write(&path, single).unwrap();
    let out = boltzone(&["solve", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("load.nut_outer_radius"));
    std::fs::remove_dir_all(&dir).ok();
    for (extra, flag) in [
        (&["--b2", "5"][..], "--b2"),
        (&["--b2", "25"], "--c"),
        (&["--b2", "9.5", "--method", "hankel"], "--b2"),
    ] {
        let mut line: Vec<&str> = two().into_iter().filter(|a| *a != "fem").collect();
        line.retain(|a| *a != "--method");
        line.extend(extra);
        let out = boltzone(&line);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        assert!(err.contains(flag), "{extra:?}: {err}");
    }
}
