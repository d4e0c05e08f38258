//! The two-plate model with temperatures (`contact::thermal`, issue 12 item 5) against exact
//! statements of thermoelasticity that share no code with the solver:
//! - T = T_ref everywhere: no thermal force at all, the isothermal solution bit for bit;
//! - a uniform temperature (the same α in both plates): each plate expands freely, u = α ΔT r,
//!   w = α ΔT z, stress-free; on a frictionless interface this changes neither the gap nor the
//!   pressure, so R_o and p(r) are the isothermal ones to rounding — whatever the two plates'
//!   temperatures, even different ones;
//! - the same gradient dT/dz through both plates (a steady heat flow through equal plates): both
//!   bend stress-free to the same curvature α dT/dz, the gap between them is unchanged, and so
//!   are R_o and p(r) (frictionless);
//! - a gradient mirrored about the interface bends the two rims toward each other (outer faces
//!   hotter: R_o grows) or apart (interface hotter: R_o shrinks).

use boltzone::contact::thermal::{solve_with_temperature, JointTemperature, PlateTemperature};
use boltzone::contact::two_plate::{solve, TwoPlateParams, TwoPlateSolution};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};

/// Aluminium plates (psi, in, °F): A = 0.1, B = 0.31, D = 0.1, C = 1, P = 1000 psi.
fn joint() -> Joint {
    let m = Material::new(10.0e6, 0.33).unwrap();
    let p = Plate::new(0.1, m).unwrap();
    Joint::new(
        0.1,
        OuterRadius::Finite(1.0),
        p,
        p,
        FaceLoad::uniform(0.1, 0.31, 1000.0).unwrap(),
    )
    .unwrap()
}

const ALPHA: f64 = 13e-6;

fn params() -> TwoPlateParams {
    TwoPlateParams {
        tolerance: 2e-3,
        both_plates: true, // the thermal model meshes both plates: compare like with like
        ..Default::default()
    }
}

fn with(upper: PlateTemperature, lower: PlateTemperature) -> TwoPlateSolution {
    let t = JointTemperature::constant(&joint(), 70.0, [upper, lower], [ALPHA; 2]).unwrap();
    solve_with_temperature(&joint(), &params(), &t).unwrap()
}

/// Largest pressure difference relative to the largest pressure, at `b`'s nodes (the finest
/// meshes are graded at each run's own R_o estimates, equal only to rounding).
fn pressure_change(a: &TwoPlateSolution, b: &TwoPlateSolution) -> f64 {
    let pmax = b.pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    b.radius
        .iter()
        .zip(&b.pressure)
        .fold(0.0f64, |m, (&r, y)| m.max((a.pressure_at(r) - y).abs()))
        / pmax
}

/// Rounding bounds. The free thermal displacement (α ΔT C ≈ 2e-3 in for ΔT = 150 °F) is ~200
/// times the bolt-load displacements (~1e-5 in) whose differences make the gap and p: the
/// solve's relative round-off (≤ 1.4e-10 measured on a floating plate in tests/fem/thermal.rs)
/// can reach ~3e-8 of p. Measured: Δp/p_max ≤ 1.1e-8, ΔR_o/R_o ≤ 5.3e-11.
const P_ROUNDING: f64 = 3e-8;
const R_O_ROUNDING: f64 = 1e-9;

#[test]
fn no_temperature_change_is_the_isothermal_solution_bit_for_bit() {
    let iso = solve(&joint(), &params()).unwrap();
    let s = with(
        PlateTemperature::Uniform(70.0),
        PlateTemperature::Uniform(70.0),
    );
    assert_eq!(s.r_o, iso.r_o);
    assert_eq!(s.pressure, iso.pressure);
    assert_eq!(s.gap, iso.gap);
}

#[test]
fn uniform_temperatures_leave_a_frictionless_joint_unchanged() {
    // E α ΔT = 13 000 psi for ΔT = 100 °F, 13 times the bearing pressure
    let iso = solve(&joint(), &params()).unwrap();
    for (t1, t2) in [(170.0, 170.0), (170.0, 20.0)] {
        let s = with(PlateTemperature::Uniform(t1), PlateTemperature::Uniform(t2));
        let (dr, dp) = ((s.r_o - iso.r_o).abs() / iso.r_o, pressure_change(&s, &iso));
        println!("T = ({t1}, {t2}): ΔR_o/R_o = {dr:e}, Δp/p_max = {dp:e}");
        assert!(
            dr < R_O_ROUNDING && dp < P_ROUNDING,
            "({t1}, {t2}): {dr:e}, {dp:e}"
        );
        assert!(s.converged);
    }
}

#[test]
fn equal_gradients_through_both_plates_change_nothing() {
    // heat flowing down through the stack: upper 80 → 75 °F, lower 72 → 67 °F (a jump at the
    // interface, the same dT/dz = 50 °F/in in both plates)
    let iso = solve(&joint(), &params()).unwrap();
    let s = with(
        PlateTemperature::Linear {
            interface: 75.0,
            outer: 80.0,
        },
        PlateTemperature::Linear {
            interface: 72.0,
            outer: 67.0,
        },
    );
    let (dr, dp) = ((s.r_o - iso.r_o).abs() / iso.r_o, pressure_change(&s, &iso));
    println!("equal gradients: ΔR_o/R_o = {dr:e}, Δp/p_max = {dp:e}");
    assert!(dr < R_O_ROUNDING && dp < P_ROUNDING, "{dr:e}, {dp:e}");
}

#[test]
fn mirrored_gradients_move_r_o_the_way_the_rims_bend() {
    let iso = solve(&joint(), &params()).unwrap();
    let mirrored = |interface: f64, outer: f64| {
        let p = PlateTemperature::Linear { interface, outer };
        with(p.clone(), p)
    };
    // outer faces 0.2 °F hotter: each plate's loaded face grows more, the rims bend toward
    // the interface, the contact zone grows; the interface hotter: the rims lift, it shrinks
    let (hot_out, hot_in) = (mirrored(70.0, 70.2), mirrored(70.2, 70.0));
    println!(
        "R_o: isothermal {:.5}, outer faces hotter {:.5}, interface hotter {:.5}",
        iso.r_o, hot_out.r_o, hot_in.r_o
    );
    let err = iso.r_o_error + hot_out.r_o_error.max(hot_in.r_o_error);
    assert!(
        hot_out.r_o > iso.r_o + err,
        "{} vs {}",
        hot_out.r_o,
        iso.r_o
    );
    assert!(hot_in.r_o < iso.r_o - err, "{} vs {}", hot_in.r_o, iso.r_o);
    // the contact force still balances the bolt (thermal forces are self-equilibrated)
    let total = joint().load().total_force();
    for s in [&hot_out, &hot_in] {
        let f: f64 = s.force.iter().sum();
        assert!((f - total).abs() < 1e-8 * total, "{f} vs {total}");
    }
}

#[test]
fn a_conduction_field_equals_the_linear_description_it_reproduces() {
    // Heat through the stack (upper outer face 80 °F, lower outer face 67 °F, interface
    // conductance h = 20 k/D): T is linear in each plate with a jump at the interface, which the
    // conduction FE reproduces exactly; its grid (bilinear, exact on a linear field) must give the
    // joint of the matching `Linear` temperatures.
    use boltzone::contact::thermal::TemperatureGrid;
    use boltzone::fem::{ElementKind, Mesh, PlateSpec, Spacing};
    use boltzone::heat::conduction::solve_conduction;
    let r = Spacing::uniform(0.1, 1.0, 6).unwrap();
    let plates = [
        PlateSpec {
            z: Spacing::uniform(-0.1, 0.0, 3).unwrap(),
            material: 0,
        },
        PlateSpec {
            z: Spacing::uniform(0.0, 0.1, 3).unwrap(),
            material: 1,
        },
    ];
    let mesh = Mesh::structured(ElementKind::Q4, &r, &plates).unwrap();
    let fixed: Vec<(usize, f64)> = mesh
        .top(1)
        .into_iter()
        .map(|n| (n, 80.0))
        .chain(mesh.bottom(0).into_iter().map(|n| (n, 67.0)))
        .collect();
    let heat = solve_conduction(&mesh, &[1.0, 1.0], &|_| 200.0, &fixed).unwrap();
    let t = &heat.temperature;
    // series resistances D/k, 1/h, D/k = 0.1, 0.005, 0.1: the interface faces
    let q = 13.0 / 0.205;
    let (t_up, t_lo) = (80.0 - 0.1 * q, 67.0 + 0.1 * q);
    assert!(
        (t[mesh.bottom(1)[2]] - t_up).abs() < 1e-10,
        "{}",
        t[mesh.bottom(1)[2]]
    );
    let grid =
        |p, top| PlateTemperature::Field(TemperatureGrid::from_mesh(&mesh, p, t, top).unwrap());
    let from_heat = with(grid(1, false), grid(0, true));
    let linear = with(
        PlateTemperature::Linear {
            interface: t_up,
            outer: 80.0,
        },
        PlateTemperature::Linear {
            interface: t_lo,
            outer: 67.0,
        },
    );
    let (dr, dp) = (
        (from_heat.r_o - linear.r_o).abs() / linear.r_o,
        pressure_change(&from_heat, &linear),
    );
    println!("conduction field vs linear: ΔR_o/R_o = {dr:e}, Δp/p_max = {dp:e}");
    assert!(dr < R_O_ROUNDING && dp < P_ROUNDING, "{dr:e}, {dp:e}");
}
