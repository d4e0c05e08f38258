//! Shared by the heat tests: the crate's seeded generator under the name the tests use.

pub use boltzone::numerics::random::SplitMix64 as Rng;
