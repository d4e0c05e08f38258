//! Integration tests of the bolted-joint engineer's quantities: the member compliance δ_P and
//! stiffness k_P (two-plate FE, single-plate FE, Hankel slab) and their exact limits.

#[path = "../common/mod.rs"]
mod common;

mod bolt;
mod builders;
mod catalogue;
mod compliance;
mod compliance_study;
mod diagram;
mod front_ends;
mod nut_face;
mod rules;
