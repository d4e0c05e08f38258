//! Runs every example at its quick size (`BOLTZONE_QUICK=1`: each example's `main` then ignores
//! its arguments and runs a small set), so none can go stale. Each example checks itself
//! against an independent reference and fails (an error or a panic) when a check fails; a few
//! tests below call an example's `run` directly to check what it returns or writes.

use std::sync::Once;

/// Sets `BOLTZONE_QUICK=1` once, before any example reads it. Every test of this binary that
/// reads the environment reads only this variable, and only after this call.
fn quick() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| std::env::set_var("BOLTZONE_QUICK", "1"));
}

#[allow(dead_code)]
#[path = "../../examples/01_slab_work_precision.rs"]
mod ex01;
#[allow(dead_code)]
#[path = "../../examples/02_lame_convergence.rs"]
mod ex02;
#[allow(dead_code)]
#[path = "../../examples/03_single_plate_table1.rs"]
mod ex03;
#[allow(dead_code)]
#[path = "../../examples/04_two_plate_tables.rs"]
mod ex04;
#[allow(dead_code)]
#[path = "../../examples/05_hole_correction_convergence.rs"]
mod ex05;
#[allow(dead_code)]
#[path = "../../examples/06_receding_contact.rs"]
mod ex06;
#[allow(dead_code)]
#[path = "../../examples/07_teach_45_degree_rule.rs"]
mod ex07;
#[allow(dead_code)]
#[path = "../../examples/08_fem_scaling.rs"]
mod ex08;
#[allow(dead_code)]
#[path = "../../examples/09_rigid_nut.rs"]
mod ex09;
#[allow(dead_code)]
#[path = "../../examples/10_single_report_mesh.rs"]
mod ex10;
#[allow(dead_code)]
#[path = "../../examples/11_two_plate_variants.rs"]
mod ex11;
#[allow(dead_code)]
#[path = "../../examples/12_two_plate_report_mesh.rs"]
mod ex12;
#[allow(dead_code)]
#[path = "../../examples/13_map_speed.rs"]
mod ex13;
mod ex13_map;
#[allow(dead_code)]
#[path = "../../examples/14_hole_speed.rs"]
mod ex14;
#[allow(dead_code)]
#[path = "../../examples/15_lap_joint_heat.rs"]
mod ex15;
#[allow(dead_code)]
#[path = "../../examples/16_error_bars.rs"]
mod ex16;
#[allow(dead_code)]
#[path = "../../examples/17_scene_plan.rs"]
mod ex17;
#[allow(dead_code)]
#[path = "../../examples/18_heat_speed.rs"]
mod ex18;

#[test]
fn ex01_slab_work_precision() {
    quick();
    ex01::main().unwrap();
}

#[test]
fn ex02_lame_convergence() {
    quick();
    ex02::main().unwrap();
}

#[test]
fn ex03_single_plate_table1() {
    // quick: 5 levels reach 0.05 % on the first two rows by the estimate (on 4 it still
    // carries a sixteenth of the coarsest change, ~0.07 %)
    quick();
    ex03::main().unwrap();
}

#[test]
fn ex04_two_plate_tables() {
    quick();
    ex04::main();
}

#[test]
fn ex05_hole_correction_convergence() {
    // quick: N up to 16 (the modes-only rate fit then has two points, N = 8 and 16; the
    // enriched one N = 4…16 above the data's 1e-8 floor), Table 1's first two rows
    quick();
    ex05::main().unwrap();
}

#[test]
fn ex06_receding_contact() {
    quick();
    ex06::main();
}

#[test]
fn ex07_teaches_the_45_degree_rule() {
    // the example checks itself (equilibrium of both models, complementarity, the curve's zero
    // against R_o, the ordering of the radii); here also what it returns and the figures
    let dir = std::env::temp_dir().join(format!("boltzone_ex07_test_{}", std::process::id()));
    let s = ex07::run(&dir).unwrap();
    assert!(s.two < s.single && s.single < s.cone45);
    let png = std::fs::read(&s.files[1]).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let svg = std::fs::read_to_string(&s.files[0]).unwrap();
    assert!(svg.contains("<svg") && svg.contains("45° rule"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn ex08_fem_scaling() {
    quick();
    ex08::main().unwrap();
}

#[test]
fn ex09_rigid_nut() {
    quick();
    ex09::main().unwrap();
}

#[test]
fn ex10_single_report_mesh() {
    quick();
    ex10::main().unwrap();
}

#[test]
fn ex11_two_plate_variants() {
    quick();
    ex11::main();
}

#[test]
fn ex12_two_plate_report_mesh() {
    quick();
    ex12::main();
}

#[test]
fn ex13_map_error_estimates_cover_the_actual_errors() {
    // Example 13 fails itself if an estimate exceeds the tolerance or an actual error (against
    // a run converged 50 times tighter) exceeds its estimate plus the reference's estimate.
    // The quick set: the four corners of the map's range and Table 1's narrowest load (A/D 1,
    // B/A 1.3, where an extrapolating estimate once went wrong).
    let runs = ex13::run(&ex13::QUICK_POINTS, 1e-3).unwrap();
    assert_eq!(runs.len(), ex13::QUICK_POINTS.len());
    for r in &runs {
        for m in [r.single, r.two] {
            assert!(m.estimate <= 1e-3 && m.actual <= m.estimate + m.reference_estimate);
            assert!(m.levels >= 3);
        }
    }
}

#[test]
fn ex14_hole_speed() {
    // quick: Table 1's first two rows, reference N = 32 (from 16), one timing each
    quick();
    ex14::main().unwrap();
}

#[test]
fn ex15_lap_joint_heat() {
    quick();
    ex15::main();
}

#[test]
fn ex16_error_bars() {
    quick();
    ex16::main().unwrap();
}

#[test]
fn ex17_scene_plan() {
    quick();
    ex17::main().unwrap();
}

#[test]
fn ex18_heat_speed() {
    quick();
    ex18::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/19_two_plate_hankel.rs"]
mod ex19;

#[test]
fn ex19_two_plate_hankel() {
    // quick: Table 1's first row; the example fails itself if the FE at its default tolerance
    // and the Hankel route disagree beyond both estimates
    quick();
    let rows = ex19::run(1, false).unwrap();
    assert_eq!(rows.len(), 1);
    assert!(rows[0].hankel.info.r_o_error < 1e-8 * rows[0].hankel.r_o);
    // and with the report's rim C = 1.54 in against the FE meshed to C (fails itself likewise)
    ex19::rim_table(1, false).unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/20_thermal_contact.rs"]
mod ex20;

#[test]
fn ex20_thermal_contact() {
    quick();
    ex20::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/21_friction.rs"]
mod ex21;

#[test]
fn ex21_friction() {
    quick();
    ex21::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/22_fe_edge.rs"]
mod ex22;

#[test]
fn ex22_fe_edge() {
    quick();
    ex22::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/23_fe_table1_fitted.rs"]
mod ex23;

#[test]
fn ex23_fe_table1_fitted() {
    quick();
    ex23::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/24_hole_decay.rs"]
mod ex24;

#[test]
fn ex24_hole_decay() {
    quick();
    ex24::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/25_build_tables.rs"]
mod ex25;

#[test]
fn ex25_build_tables() {
    // quick: the shipped tables printed and each checked against one fresh solve
    quick();
    ex25::main().unwrap();
}

#[allow(dead_code)]
#[path = "../../examples/26_member_stiffness_grid.rs"]
mod ex26;

#[test]
fn ex26_member_stiffness_grid() {
    // quick: 3 × 3 at 2e-3, the figure written to a temporary file and removed
    quick();
    ex26::main().unwrap();
}

#[path = "../../examples/27_build_near_table.rs"]
mod ex27;

#[test]
fn ex27_build_near_table() {
    // quick: the shipped near table's provenance and Table 1's row against one fresh solve
    quick();
    ex27::main().unwrap();
}

#[path = "../../examples/29_fe_fitted_study.rs"]
mod ex29;

#[test]
fn ex29_fe_fitted_study() {
    // quick: one joint of each interface kind at 1e-5 against the exact routes
    quick();
    ex29::main().unwrap();
}

#[path = "../../examples/30_single_plate_rim.rs"]
mod ex30;

#[test]
fn ex30_single_plate_rim() {
    // quick: the slope survey's corners and four plates, six rimmed plates against the route
    quick();
    ex30::main().unwrap();
}

#[path = "../../examples/31_two_plate_rim_law.rs"]
mod ex31;

#[test]
fn ex31_two_plate_rim_law() {
    // quick: the rim table against two fresh rimmed solves, and the law on one geometry at 1e-6
    quick();
    ex31::main().unwrap();
}
