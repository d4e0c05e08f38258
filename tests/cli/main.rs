//! The command line's contract as a whole: exit codes, messages that name the flag, no panic,
//! bounded time and memory, no NaN, infinity or null in any output (the per-command behaviour is
//! tested in each area's `cli` module).

mod fuzz;
mod out_of_reach;
mod readme;
mod regressions;
mod rim_no_hole;
mod sanity;
mod thin_plates;
mod tour;
