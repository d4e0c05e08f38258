//! Integration tests of `boltzone::heat`: contact-conductance correlations and units, the
//! Appendix D network and its card decks, the joint conductance from the interface pressure,
//! the lap-joint network and the conduction finite elements.

mod conduction;
mod correlation;
mod deck;
mod joint;
mod lap;
mod network;
mod network_fixtures;
mod zone;
