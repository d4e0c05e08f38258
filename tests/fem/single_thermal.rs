//! The single plate with temperatures (`fem::single_thermal`, issue 12 item 5) against exact
//! statements of thermoelasticity that share no code with the solver:
//! - a uniform temperature (α constant): the free plate expands by u = α ΔT r, w = α ΔT z
//!   without stress, so on the same mesh the displacements differ from the isothermal ones by
//!   exactly that and the stresses not at all, and R_o is the isothermal one to rounding;
//! - a temperature linear in the depth below the midplane (mirror-symmetric, as in a joint of
//!   two equal plates): the midplane holds the plate flat, and away from every edge the thermal
//!   part of the stress is σ_r = σ_θ = E α (T̄ − T)/(1 − ν), σ_z = τ_rz = 0 (T̄ the mean over
//!   the thickness), the disturbances of the hole, the load edge and the rim decaying like
//!   e^(−2.106 x/D) (first root of sin 2λ + 2λ = 0 for a strip 2D thick); the thermal roller
//!   reactions carry no net force.

use boltzone::fem::plate_temperature::PlateTemperature;
use boltzone::fem::single::{level_spacings, solve, solve_half_plate_with, FaceCondition};
use boltzone::fem::single::{HalfPlate, SingleParams};
use boltzone::fem::single_thermal::{solve_with_temperature, SingleTemperature};
use boltzone::fem::{internal_forces, Spacing};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

const ALPHA: f64 = 13e-6;
const E: f64 = 1e7;
const NU: f64 = 0.3;
const D: f64 = 0.1;

/// A = 0.1, B = 0.22, D = 0.1 (Table 1's A/D = 1, B/A = 2.2), P = 1000, rim at `c`.
fn plate(c: f64) -> SinglePlate {
    let load = FaceLoad::uniform(0.1, 0.22, 1000.0).unwrap();
    let m = Material::new(E, NU).unwrap();
    SinglePlate::new(0.1, OuterRadius::Finite(c), D, m, load).unwrap()
}

fn temperature(p: &SinglePlate, t: PlateTemperature) -> SingleTemperature {
    SingleTemperature::constant(p, 70.0, t, ALPHA).unwrap()
}

/// The half plate solved on level `level`'s mesh with and without the temperature `t`.
fn pair(p: &SinglePlate, level: u32, t: &SingleTemperature) -> (HalfPlate, HalfPlate) {
    let (r, z) = level_spacings(p, &SingleParams::default(), level, None).unwrap();
    pair_on(p, &r, &z, t)
}

/// The half plate solved on the mesh `r` × `z` with and without the temperature `t`.
fn pair_on(
    p: &SinglePlate,
    r: &Spacing,
    z: &Spacing,
    t: &SingleTemperature,
) -> (HalfPlate, HalfPlate) {
    let run = |t| solve_half_plate_with(p, &SingleParams::default(), r, z, t).unwrap();
    (run(None), run(Some(t)))
}

/// The thermal part of the solution: displacement difference of the two solves.
fn thermal_part(iso: &HalfPlate, hot: &HalfPlate) -> Vec<[f64; 2]> {
    iso.u
        .iter()
        .zip(&hot.u)
        .map(|(a, b)| [b[0] - a[0], b[1] - a[1]])
        .collect()
}

#[test]
fn uniform_temperature_expands_the_plate_freely_and_keeps_r_o() {
    let p = plate(1.54);
    let dt = 100.0;
    let t = temperature(&p, PlateTemperature::Uniform(70.0 + dt));
    let (iso, hot) = pair(&p, 2, &t);
    let du = thermal_part(&iso, &hot);
    let umax = ALPHA * dt * 1.54;
    for (x, d) in hot.mesh.nodes().iter().zip(&du) {
        let err = (d[0] - ALPHA * dt * x[0])
            .abs()
            .max((d[1] - ALPHA * dt * x[1]).abs());
        // round-off of the solve relative to the free expansion (cond(K) ε)
        assert!(err < 1e-10 * umax, "node {x:?}: {d:?}");
    }
    let th = hot.thermal.as_ref().unwrap();
    let s = th.gauss_stresses(&hot.mesh, &hot.materials, &du).unwrap();
    let held = E * ALPHA * dt / (1.0 - NU);
    let smax = s
        .iter()
        .flat_map(|p| p.stress.to_array())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    println!(
        "uniform ΔT: thermal stress max {:e} of E α ΔT/(1 − ν)",
        smax / held
    );
    assert!(smax < 1e-9 * held, "{smax:e}");
    // R_o through the whole refinement study: the isothermal one to rounding
    let params = SingleParams {
        tolerance: 1e-3,
        ..SingleParams::default()
    };
    let t0 = std::time::Instant::now();
    let s = solve_with_temperature(&p, &params, &t).unwrap();
    let secs = t0.elapsed().as_secs_f64();
    let i = solve(&p, &params).unwrap();
    println!(
        "R_o: isothermal {:.9}, ΔT = 100: {:.9} ({secs:.2} s)",
        i.r_o, s.r_o
    );
    assert!(
        (s.r_o - i.r_o).abs() < 1e-9 * i.r_o,
        "{} vs {}",
        s.r_o,
        i.r_o
    );
    assert_eq!(s.info.levels.len(), i.info.levels.len());
}

#[test]
fn mirrored_gradient_is_held_flat_with_the_plate_stress_of_the_closed_form() {
    // a wide rim: the interior 0.95 ≤ r ≤ 2 lies ≥ 7.3 D from the load edge and 10 D from the rim
    let p = plate(3.0);
    let (ti, to) = (170.0, 70.0); // midplane (interface) hotter than the faces
    let t = temperature(
        &p,
        PlateTemperature::Linear {
            interface: ti,
            outer: to,
        },
    );
    // a uniform mesh h = D/4 that resolves the edge layers (the level meshes' interior elements
    // are 4D long: their error there, 1.2e-3, is discretisation). Measured interior error
    // against E α ΔT/(1 − ν): h = D/2 7.6e-7, D/4 5.7e-8, D/8 5.9e-9 (4, 4, 8 elements through D)
    let r = Spacing::uniform(0.1, 3.0, 116).unwrap();
    let z = Spacing::uniform(0.0, D, 4).unwrap();
    let (iso, hot) = pair_on(&p, &r, &z, &t);
    let du = thermal_part(&iso, &hot);
    let th = hot.thermal.as_ref().unwrap();
    let pts = th.gauss_stresses(&hot.mesh, &hot.materials, &du).unwrap();
    let mean = 0.5 * (ti + to);
    let scale = E * ALPHA * (ti - to) / (1.0 - NU);
    let (lo, hi) = (0.95, 2.0);
    let x = (lo - 0.22f64).min(3.0 - hi);
    // the edge disturbances' decay over the distance x (constant 1 relative to E α ΔT/(1 − ν))
    let bound = (-2.106 * x / D).exp();
    let mut worst = 0.0f64;
    for q in pts.iter().filter(|q| q.r >= lo && q.r <= hi) {
        let tz = ti + (to - ti) * q.z / D;
        let plate_stress = E * ALPHA * (mean - tz) / (1.0 - NU);
        let s = q.stress;
        for (g, x) in [
            (s.r, plate_stress),
            (s.theta, plate_stress),
            (s.z, 0.0),
            (s.rz, 0.0),
        ] {
            worst = worst.max((g - x).abs() / scale);
        }
    }
    println!(
        "mirrored gradient: interior error {worst:e} of E α ΔT/(1 − ν), decay bound {bound:e}"
    );
    assert!(worst < bound, "{worst:e} vs {bound:e}");
    // the thermal part of the roller reactions is self-equilibrated: no net axial force
    let f = internal_forces(&hot.mesh, &hot.materials, &du).unwrap();
    let fth = th.loads(&hot.mesh, &hot.materials).unwrap();
    let mid = hot.mesh.bottom(0);
    let net: f64 = mid.iter().map(|&n| f[n][1] - fth.forces()[n][1]).sum();
    let gross: f64 = mid
        .iter()
        .map(|&n| (f[n][1] - fth.forces()[n][1]).abs())
        .sum();
    println!("thermal midplane reactions: net {net:e}, gross {gross:e}");
    assert!(net.abs() < 1e-10 * gross, "{net:e} of {gross:e}");
}

#[test]
fn a_rigid_nut_with_temperatures_is_refused() {
    let p = plate(1.54);
    let params = SingleParams {
        loading: FaceCondition::UniformDisplacement,
        ..SingleParams::default()
    };
    let t = temperature(&p, PlateTemperature::Uniform(80.0));
    let err = solve_with_temperature(&p, &params, &t)
        .unwrap_err()
        .to_string();
    assert!(err.contains("face loading"), "{err}");
}
