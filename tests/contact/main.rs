//! Integration tests of `boltzone::contact`: the LCP solvers, R_o below one element, the
//! two-plate model, its agreement with the semi-analytic receding contact, and the `two` command.

mod cli;
mod edge_fit;
mod exterior;
mod fitted_route;
mod friction;
mod friction_cli;
mod lcp;
mod near_rim;
mod receding_vs_fe;
mod separation;
mod thermal;
mod tighter_tolerance;
mod two_plate;
