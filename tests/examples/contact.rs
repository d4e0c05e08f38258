//! Runs example 04 (Tables 1 and 2 by the two-plate model) at its quick tolerance: the example
//! checks itself (convergence, equilibrium, agreement with the report within its resolution).

#[path = "../examples/04_two_plate_tables.rs"]
mod ex04;

#[test]
fn example_04_two_plate_tables_quick() {
    // Safe: this test binary runs no other test that reads the environment.
    std::env::set_var("BOLTZONE_QUICK", "1");
    ex04::main();
}

#[path = "../examples/11_two_plate_variants.rs"]
mod ex15;

#[test]
fn example_15_two_plate_variants_quick() {
    std::env::set_var("BOLTZONE_QUICK", "1");
    ex15::main();
}

#[path = "../examples/12_two_plate_report_mesh.rs"]
mod ex16;

#[test]
fn example_16_report_mesh_quick() {
    std::env::set_var("BOLTZONE_QUICK", "1");
    ex16::main();
}
