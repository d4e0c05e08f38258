//! Integration tests of `boltzone::fem`: elements and assembly, the Lamé cylinder, the single
//! plate against the Hankel routes (no hole, and with the hole), and the `single` command.

mod cli;
#[path = "../common/mod.rs"]
mod common;
mod elements;
mod full_contact;
mod hankel_agreement;
mod hole_agreement;
mod lame;
mod single;
mod single_thermal;
mod system;
mod thermal;
mod tight_tolerance;
