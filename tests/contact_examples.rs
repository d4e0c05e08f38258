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
