//! Runs example 19 (Chapter V's lap joint) on coarse networks: the example checks itself (energy
//! balance, the network's contact conductance against the nodal integral, the order of the
//! heat flows, the ring pressures against the report's table).

#[path = "../examples/19_lap_joint_heat.rs"]
mod ex19;

#[test]
fn example_19_lap_joint_heat_quick() {
    // Safe: this test binary runs no other test that reads the environment.
    std::env::set_var("BOLTZONE_QUICK", "1");
    ex19::main();
}
