//! The figures, the teaching page's server and its browser test (issue 13).
//!
//! - `gallery`: `boltzone figures --only …`: every curve's sign change brackets its R_o, the
//!   report's points are the `reference/` tables' values (read here from the CSV files), the
//!   single-plate R_o of the figures agree with the independent Hankel route, the load variants
//!   carry the same bolt force, the files and the gallery are complete, bad flags exit 2;
//! - `serve`: the JSON API's contract (`two --json`'s numbers, in inches and bit for bit in mm),
//!   the page's embedded opening answer, HTTP 400 naming the parameter, and the server surviving
//!   every request;
//! - `load` (ignored: run with `--ignored --nocapture`): 2,000 requests over ~20 s, 8 at once:
//!   no error, latency percentiles, the server's memory before and after;
//! - `browser`: Debian's chromium drives the page at 400 and 1280 px (playwright-core: layout,
//!   first frame, slider, units) and paints it plainly headless (first paint); Node checks the
//!   tick chooser (each skipped with a note where chromium, node or the Node packages are
//!   missing, required when `BOLTZONE_BROWSER=1`).

#[path = "../common/mod.rs"]
mod common;

mod browser;
mod deflection;
mod gallery;
mod load;
mod markers;
mod server;
mod units;
