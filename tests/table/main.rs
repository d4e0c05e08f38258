//! Integration tests of `boltzone::table`: the far tables against fresh solves not used to
//! build them, the extrapolation's bar, the holed routes where the hole is far, and (ignored)
//! the decay study behind the handover bound.

#[path = "../common/mod.rs"]
mod common;
mod decay;
mod far;
mod near;
mod rim;
mod two_plates;
