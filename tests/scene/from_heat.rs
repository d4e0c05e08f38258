//! `[temperature] from_heat = true` (issue 12 item 5) and its library call
//! `boltzone::heat::coupled`: equal face temperatures against the uniform field and the
//! isothermal joint; the conduction's energy balance and its heat flow against the interface
//! conductance G of `heat::joint` (computed separately) in the limit of conducting plates; the
//! example scene against the library call bit for bit; located errors and exit 2.

use crate::heat::error_of;
use crate::{example, scratch};
use boltzone::contact::two_plate::{self, TwoPlateParams};
use boltzone::fem::thermal::ThermalMaterial;
use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
use boltzone::heat::coupled::{conduct, solve_from_heat, HeatCoupling};
use boltzone::heat::joint::{joint_conductance, JointParams};
use boltzone::heat::units::{Conductivity, Length, Pressure};
use boltzone::scene::Scene;
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::f64::consts::PI;
use std::process::Command;

const IN: f64 = 0.0254;
const PSI: f64 = 4.4482216152605 / (IN * IN);
/// W/K per Btu/(hr·°F), from the IT Btu, the hour and the Fahrenheit degree.
const BTU_HR_F: f64 = 1055.05585262 / 3600.0 / (5.0 / 9.0);

/// The Chapter V aluminium pair of `examples/scenes/from_heat.toml`, by hand in SI units.
fn chapter5_joint() -> (Joint, Material) {
    let al = Material::new(1.0e7 * PSI, 0.33).unwrap();
    let (a, b) = (0.1 * IN, 0.13 * IN);
    let p = 1000.0 * 4.4482216152605 / (PI * (b * b - a * a));
    let plate = Plate::new(0.1 * IN, al).unwrap();
    let joint = Joint::new(
        a,
        OuterRadius::Finite(1.54 * IN),
        plate,
        plate,
        FaceLoad::uniform(a, b, p).unwrap(),
    )
    .unwrap();
    (joint, al)
}

/// Eq. (1.1) with the scene's surfaces; conductivity `k` in Btu/(hr·ft·°F).
fn coupling(al: Material, k: f64, faces: [f64; 2], tolerance: f64) -> HeatCoupling {
    let k_si = k * BTU_HR_F / 0.3048;
    let surfaces = Surfaces::new(
        [Conductivity::from_si(k_si); 2],
        [Length::from_si(50e-6 * IN); 2],
        [0.07071067811865475; 2],
        Pressure::from_si(150_000.0 * PSI),
    )
    .unwrap();
    let m = ThermalMaterial::constant(al, 13e-6).unwrap();
    HeatCoupling {
        contact: ContactConductance::new(Correlation::Cmy1969, surfaces).unwrap(),
        conductivity: [k_si; 2],
        faces,
        reference: 70.0,
        materials: [m.clone(), m],
        axial: 8,
        tolerance,
        max_passes: 20,
    }
}

fn coarse() -> TwoPlateParams {
    TwoPlateParams {
        tolerance: 1e-2,
        ..Default::default()
    }
}

#[test]
fn equal_faces_give_a_uniform_field_and_the_isothermal_joint() {
    let (joint, al) = chapter5_joint();
    let iso = two_plate::solve(&joint, &coarse()).unwrap();
    // faces at 150 °F (not the reference): the conduction field is 150 everywhere
    let c = conduct(&joint, &iso, &coupling(al, 100.0, [150.0; 2], 1e-3)).unwrap();
    let worst = c
        .solution
        .temperature
        .iter()
        .map(|t| (t - 150.0).abs())
        .fold(0.0, f64::max);
    println!(
        "equal faces: max |T − 150| = {worst:e} °F, Q = {:e} W",
        c.heat_in
    );
    assert!(worst <= 1e-12 * 150.0, "{worst:e}");
    // faces at the stress-free temperature: the isothermal R_o
    let s = solve_from_heat(&joint, &coarse(), &coupling(al, 100.0, [70.0; 2], 1e-3)).unwrap();
    let dr = (s.solution.r_o / iso.r_o - 1.0).abs();
    println!(
        "faces = reference: ΔR_o/R_o = {dr:e} after {} pass(es)",
        s.passes
    );
    assert!(dr < 1e-10 && s.passes == 1, "{dr:e}, {} passes", s.passes);
}

#[test]
fn heat_in_equals_heat_out_and_tends_to_g_delta_t() {
    // The conduction's reactions must balance (no source inside), and Q/ΔT is the series
    // resistance 1/G + R_plates: with the plates' conductivity k multiplied by 10, R_plates falls
    // as 1/k, so 1 − Q/(G ΔT) falls tenfold per step (rate 1 in k) towards the interface's own
    // conductance G = Σ h_c A of `heat::joint` (nodal rule on the same interface nodes).
    let (joint, al) = chapter5_joint();
    let iso = two_plate::solve(&joint, &coarse()).unwrap();
    let base = coupling(al, 100.0, [170.0, 70.0], 1e-3);
    let mut params = JointParams::new(base.contact);
    params.length_unit = Length::from_si(1.0); // the joint is in SI units
    params.pressure_unit = Pressure::from_si(1.0);
    let g = joint_conductance(&iso, &params).unwrap().total.si();
    let dt = 100.0;
    let mut e = Vec::new();
    for scale in [1.0, 1e1, 1e2, 1e3, 1e4] {
        // the plates' conductivity only: h_c(p) of the surfaces stays that of k = 100
        let mut heat = base.clone();
        heat.conductivity = base.conductivity.map(|k| k * scale);
        let c = conduct(&joint, &iso, &heat).unwrap();
        let balance = (c.heat_in - c.heat_out).abs() / c.heat_in;
        // the reactions' rounding grows with k/h (the matrix's conditioning): checked up to
        // 100 000 Btu/(hr·ft·°F), far past any metal, and printed beyond
        assert!(
            scale > 1e3 || balance < 1e-10,
            "k × {scale}: in {} out {} W",
            c.heat_in,
            c.heat_out
        );
        e.push(1.0 - c.heat_in / (g * dt));
        println!(
            "k × {scale}: Q = {:.6e} W, G ΔT = {:.6e} W, 1 − Q/(G ΔT) = {:e}, |in − out|/in = {balance:e}",
            c.heat_in,
            g * dt,
            e[e.len() - 1]
        );
    }
    // k → ∞: Q/ΔT → Σ h_i w_i, the interface's lumped conductance, with w_i = ∫ N_i 2πr dr of
    // the hat functions on the interface nodes in closed form
    let r = &iso.radius;
    let mut lumped = 0.0;
    for i in 0..r.len() {
        let mut w = 0.0;
        if i > 0 {
            w += (r[i] - r[i - 1]) * (r[i - 1] + 2.0 * r[i]) / 6.0;
        }
        if i + 1 < r.len() {
            w += (r[i + 1] - r[i]) * (2.0 * r[i] + r[i + 1]) / 6.0;
        }
        let p = iso.pressure[i];
        if p > 0.0 && r[i] <= iso.r_o {
            let h = base.contact.coefficient(Pressure::from_si(p)).unwrap().si();
            lumped += h * 2.0 * PI * w;
        }
    }
    let limit = 1.0 - lumped / g;
    let rates: Vec<f64> = e
        .windows(2)
        .map(|w| ((w[0] - limit) / (w[1] - limit)).log10())
        .collect();
    println!(
        "k → ∞ limit 1 − Σ h_i w_i / G = {limit:e} (the lumped interface against heat::joint's \
         tributary rule); observed rates of e − limit in k: {rates:?}"
    );
    assert!(e.windows(2).all(|w| w[1] < w[0] && w[1] > limit), "{e:?}");
    let last = rates[rates.len() - 1];
    assert!((last - 1.0).abs() < 0.02, "rate {last}");
    assert!(limit.abs() < 2e-3, "{limit:e}");
}

#[test]
fn scene_equals_the_library_call_bit_for_bit() {
    let (joint, al) = chapter5_joint();
    let params = TwoPlateParams {
        tolerance: 2e-3,
        ..Default::default()
    };
    let mut heat = coupling(al, 100.0, [570.0, 70.0], 2e-3);
    heat.materials[1] = ThermalMaterial::constant(al, 6.5e-6).unwrap();
    let lib = solve_from_heat(&joint, &params, &heat).unwrap();
    let s = boltzone::solve(&Scene::parse(&example("from_heat")).unwrap()).unwrap();
    let iso = two_plate::solve(&joint, &params).unwrap();
    println!(
        "from_heat scene: R_o = {} in (isothermal {} in), {} passes, Q = {} Btu/hr, ΔR_o/R_o last pass {:e}",
        s.r_o,
        iso.r_o / IN,
        lib.passes,
        s.heat_flow.unwrap(),
        lib.r_o_change
    );
    assert_eq!(s.r_o.to_bits(), (lib.solution.r_o / IN).to_bits());
    assert_eq!(s.heat_passes, Some(lib.passes));
    // the Btu factor of the scene and of this test differ by rounding only
    let q = s.heat_flow.unwrap() * BTU_HR_F;
    assert!(
        (q / lib.heat_flow - 1.0).abs() < 1e-14,
        "{q} vs {} W",
        lib.heat_flow
    );
    assert_eq!(s.heat_flow_unit, Some("Btu/hr"));
    assert!(s.converged && lib.solution.converged && lib.passes > 1);
    assert!(lib.r_o_change <= 2e-3 && (s.r_o * IN / iso.r_o - 1.0).abs() > 1e-2);
    // the command: the JSON keys and the printed line with its unit
    let path =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/from_heat.toml");
    let dir = scratch("from_heat_scene");
    let run = |json: bool| {
        let mut args = vec!["solve", path.to_str().unwrap()];
        args.extend(json.then_some("--json"));
        let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        out
    };
    let v = crate::common::json_of(&run(true));
    assert_eq!(v["heat_passes"].as_u64(), Some(lib.passes as u64));
    assert_eq!(v["heat_flow"].as_f64(), s.heat_flow);
    assert_eq!(v["heat_flow_unit"], "Btu/hr");
    let text = String::from_utf8(run(false).stdout).unwrap();
    assert!(
        text.contains("heat flow through the joint") && text.contains("Btu/hr"),
        "{text}"
    );
}

#[test]
fn the_field_of_the_last_pass_leaves_r_o_bit_for_bit() {
    let text = example("from_heat").replace("r_o = true\n", "r_o = true\nfield = \"f.vtu\"\n");
    let plain = boltzone::solve(&Scene::parse(&example("from_heat")).unwrap()).unwrap();
    let with = boltzone::solve(&Scene::parse(&text).unwrap()).unwrap();
    assert_eq!(with.r_o.to_bits(), plain.r_o.to_bits());
    assert_eq!(with.heat_passes, plain.heat_passes);
    let grid = with.field.expect("a field");
    let t = grid
        .scalars
        .iter()
        .find(|(name, _)| name == "temperature")
        .map(|(_, v)| v)
        .expect("a temperature");
    // conduction: every temperature between the two faces' (maximum principle)
    let (lo, hi) = t
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    println!("field temperatures {lo} .. {hi} °F");
    assert!(
        lo >= 70.0 - 1e-9 && hi <= 570.0 + 1e-9 && hi - lo > 100.0,
        "{lo} .. {hi}"
    );
}

#[test]
fn a_symmetric_pair_gets_an_antisymmetric_field_that_leaves_r_o_unchanged() {
    // Equal plates and conductivities: T − T_mean is antisymmetric about the interface
    // (T_upper(r, s) + T_lower(r, s) = 170 + 70 at every depth s below it). The uniform part
    // T_mean − T_ref expands both plates freely; the antisymmetric part bends the mirrored plates
    // by equal and opposite amounts, so the gap — and for a frictionless interface R_o — is that
    // of the isothermal joint.
    let (joint, al) = chapter5_joint();
    let iso = two_plate::solve(&joint, &coarse()).unwrap();
    let c = conduct(&joint, &iso, &coupling(al, 100.0, [170.0, 70.0], 1e-3)).unwrap();
    let [up, lo] = c.plates().unwrap();
    let d = 0.1 * IN;
    let mut worst: f64 = 0.0;
    for &r in &iso.radius {
        for j in 0..=8 {
            let s = d * j as f64 / 8.0;
            worst = worst.max((up.at(r, s, d) + lo.at(r, s, d) - 240.0).abs());
        }
    }
    let s = solve_from_heat(&joint, &coarse(), &coupling(al, 100.0, [170.0, 70.0], 1e-3)).unwrap();
    let dr = (s.solution.r_o / iso.r_o - 1.0).abs();
    println!("symmetric pair: max |T_u + T_l − 240| = {worst:e} °F, ΔR_o/R_o = {dr:e}");
    assert!(worst < 1e-10 && dr < 1e-10, "{worst:e} °F, {dr:e}");
}

#[test]
fn a_fixed_point_not_reached_is_flagged_not_converged() {
    // One pass allowed and a tolerance below the first pass's change: flagged, not hidden.
    let (joint, al) = chapter5_joint();
    let mut heat = coupling(al, 100.0, [170.0, 70.0], 1e-14);
    heat.max_passes = 1;
    let s = solve_from_heat(&joint, &coarse(), &heat).unwrap();
    println!("one pass: ΔR_o/R_o = {:e}", s.r_o_change);
    assert!(s.passes == 1 && s.r_o_change > 1e-14 && !s.solution.converged);
}

#[test]
fn bad_from_heat_tables_exit_2_naming_key_and_line() {
    let scene = example("from_heat");
    let heat_at = scene.find("[heat]").unwrap();
    let no_heat = format!(
        "{}{}",
        &scene[..heat_at],
        &scene[scene.find("[temperature]").unwrap()..]
    );
    let line = |text: &str, key: &str| 1 + text.lines().position(|l| l.starts_with(key)).unwrap();
    let cases = [
        (
            scene.replace("from_heat = true\n", ""),
            "temperature.faces: [570.0, 70.0]",
            "faces",
        ),
        (
            scene.replace("from_heat = true\n", "from_heat = true\nplates = [90.0]\n"),
            "temperature.plates",
            "plates",
        ),
        (
            scene.replace(
                "from_heat = true\n",
                "from_heat = true\ngradient = [[1.0, 2.0]]\n",
            ),
            "temperature.gradient",
            "gradient",
        ),
        (no_heat.clone(), "temperature.from_heat: true", "from_heat"),
        (
            scene.replace("faces = [570.0, 70.0]\n", ""),
            "temperature.from_heat: true",
            "from_heat",
        ),
    ];
    for (text, start, key) in &cases {
        let (m, at) = error_of(text);
        assert!(
            m.starts_with(start) && at == line(text, key),
            "{m} (line {at}, want {}) for {start}",
            line(text, key)
        );
    }
    // through the command: exit 2, the message names the key and the line
    let dir = scratch("from_heat_errors");
    let path = dir.join("no_heat.toml");
    std::fs::write(&path, &no_heat).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", path.to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    let want = format!("line {}", line(&no_heat, "from_heat"));
    assert!(
        err.contains("temperature.from_heat") && err.contains(&want),
        "{err}"
    );
}
