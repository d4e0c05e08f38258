//! Runs example 06 (receding contact of a layer on a rigid base) on its quick set: the example
//! checks itself (error estimates, geometric convergence in the basis size, equilibrium).

#[path = "../examples/06_receding_contact.rs"]
mod ex06;

#[test]
fn example_06_receding_contact_quick() {
    // Safe: this test binary runs no other test that reads the environment.
    std::env::set_var("BOLTZONE_QUICK", "1");
    ex06::main();
}
