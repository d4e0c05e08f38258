//! Runs the FE examples on small sizes so they cannot go stale (their full runs are studies).

#[allow(dead_code)]
#[path = "../examples/02_lame_convergence.rs"]
mod ex02;
#[allow(dead_code)]
#[path = "../examples/03_single_plate_table1.rs"]
mod ex03;

#[test]
fn lame_convergence_example_runs() {
    ex02::run(16).unwrap();
}

#[test]
fn table1_example_runs_on_two_rows() {
    // 5 levels reach 0.05 % on the first rows by the estimate (on 4 it still carries a
    // sixteenth of the coarsest change, ~0.07 %)
    ex03::run(5, 2, 0.05).unwrap();
}

#[allow(dead_code)]
#[path = "../examples/09_rigid_nut.rs"]
mod ex11;

#[test]
fn rigid_nut_example_runs() {
    ex11::run(3).unwrap();
}

#[allow(dead_code)]
#[path = "../examples/10_single_report_mesh.rs"]
mod ex12;

#[test]
fn report_mesh_example_runs() {
    ex12::run(1).unwrap();
}
