//! Integration tests of `boltzone::hankel`: the slab (kernels, transform, fields, R_o), the
//! hole correction (`hole_*`) and the receding contact (`receding_*`), each against closed forms,
//! independent derivations or a second method; and the `slab` and `single --method hankel`
//! commands.

mod cli;
#[path = "../common/mod.rs"]
mod common;
mod grid_study;
mod hole_cli;
mod hole_corner;
mod hole_correction;
mod hole_eigen;
mod hole_fast;
mod hole_profile;
mod hole_reach_survey;
mod pair_cli;
mod reach;
mod receding_contact;
mod receding_kernels;
mod receding_pair;
mod rim_moment_fields;
mod separation;
mod shear_kernels;
mod slab;
mod small_hole_residual;
mod transform;
mod two_plate_curve_equilibrium;
mod two_plate_hole;
mod two_plate_hole_fast;
mod two_plate_hole_handover;
mod two_plate_hole_newton;
mod two_plate_hole_pressure;
mod two_plate_hole_reach;
mod two_plate_hole_reach_survey;
mod two_plate_hole_tier8;
mod two_plate_hole_tiers;
mod two_plate_rim;
mod two_plate_rim_decay;
mod two_plate_rim_hankel;
mod two_plate_rim_holed;
mod two_plate_rim_survey;
mod two_plate_rim_wide;
