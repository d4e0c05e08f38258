//! Checks of command-line values before any work starts, so that a bad value is reported with
//! its flag (`--d2 = -1: …`) rather than by a solver's internals, and exits 2.
//!
//! # Accuracy
//!
//! No numerics: `tests/cli/regressions.rs` (`every_bad_value_is_named_by_its_flag`,
//! `output_paths_are_checked_before_any_work_and_nothing_is_left_behind`) and the argument fuzz of
//! `tests/cli/fuzz.rs`.
//!
//! # Cost
//!
//! None: checks run before any work.

use super::exit::{num, usage};
use std::path::Path;

pub use boltzone::route::reach::{B_OVER_D_SINGLE, B_OVER_D_SLAB, B_OVER_D_TWO, NU_MAX_FEM};

/// `value` if finite and > 0; the message names the flag and the `field` (report notation).
pub fn positive(flag: &str, field: &str, value: f64) -> anyhow::Result<f64> {
    let v = num(value);
    if !value.is_finite() {
        return usage(flag, &v, &format!("{field} = {v} is not a finite number"));
    }
    if value <= 0.0 {
        return usage(flag, &v, &format!("{field} = {v} must be positive"));
    }
    Ok(value)
}

/// `value` if finite and ≥ 0; the message names the flag and the `field`.
pub fn non_negative(flag: &str, field: &str, value: f64) -> anyhow::Result<f64> {
    let v = num(value);
    if !value.is_finite() {
        return usage(flag, &v, &format!("{field} = {v} is not a finite number"));
    }
    if value < 0.0 {
        return usage(flag, &v, &format!("{field} = {v} must not be negative"));
    }
    Ok(value)
}

/// A relative tolerance: finite, in [f64::EPSILON, 0.5] (f64 resolves R_o no finer than
/// its epsilon, 2.2e-16; a tolerance below it asks nothing a route could meet).
pub fn tolerance(flag: &str, value: f64) -> anyhow::Result<f64> {
    if !((f64::EPSILON..=0.5).contains(&value)) {
        return usage(
            flag,
            num(value),
            "a relative tolerance on R_o must lie in [2.2e-16, 0.5] (f64 resolves R_o no \
             finer than 2.2e-16; e.g. 5e-4 = 0.05 %)",
        );
    }
    Ok(value)
}

/// Poisson's ratio: in (−1, `max`].
pub fn poisson(flag: &str, value: f64, max: f64) -> anyhow::Result<f64> {
    if !(value > -1.0 && value <= max) {
        let reason = if max < 0.5 {
            format!(
                "Poisson's ratio nu = {} must lie in (-1, {max}] for the finite-element routes \
                 (nearer 0.5 the elements lock)",
                num(value)
            )
        } else {
            format!(
                "Poisson's ratio nu = {} must lie in the open interval (-1, 0.5)",
                num(value)
            )
        };
        return usage(flag, num(value), &reason);
    }
    if max >= 0.5 && value >= 0.5 {
        return usage(
            flag,
            num(value),
            &format!(
                "Poisson's ratio nu = {} must lie in the open interval (-1, 0.5)",
                num(value)
            ),
        );
    }
    Ok(value)
}

/// The bearing face: hole radius A ≥ 0 (`--a`), B > A (`--b`).
pub fn annulus(a: f64, b: f64) -> anyhow::Result<()> {
    non_negative("--a", "hole radius A", a)?;
    positive("--b", "bearing-face outer radius B", b)?;
    if b <= a {
        return usage(
            "--b",
            num(b),
            &format!(
                "the bearing face's outer radius B = {} must exceed the hole radius A = {}",
                num(b),
                num(a)
            ),
        );
    }
    Ok(())
}

/// An outer radius C > B (`flag`).
pub fn outer_radius(flag: &str, c: f64, b: f64) -> anyhow::Result<f64> {
    positive(flag, "plate outer radius C", c)?;
    if c <= b {
        return usage(
            flag,
            num(c),
            &format!(
                "the plate's outer radius C = {} must exceed the bearing face's B = {}",
                num(c),
                num(b)
            ),
        );
    }
    Ok(c)
}

/// Checks that `path` can be written whole before any work starts: a file name (not a
/// directory), in an existing directory that accepts a new file (probed by creating and
/// removing an empty temporary file there).
pub fn output_path(flag: &str, path: &Path) -> anyhow::Result<()> {
    let shown = path.display();
    if path.as_os_str().is_empty() {
        return usage(flag, "''", "an output file name is required");
    }
    if path.is_dir() {
        return usage(flag, shown, "is a directory, not a file name");
    }
    let Some(name) = path.file_name() else {
        return usage(flag, shown, "has no file name");
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return usage(
            flag,
            shown,
            &format!("the directory '{}' does not exist", dir.display()),
        );
    }
    let probe = dir.join(format!(
        ".{}.probe{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    match std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
    {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => usage(
            flag,
            shown,
            &format!("cannot create a file in '{}': {e}", dir.display()),
        ),
    }
}

/// The supported domain of the joint's shape ([`boltzone::route::reach`]), in thicknesses of the
/// (thinner) plate D: a hole A = 0 or 1e-3 ≤ A/D ≤ 1e3, a bearing face at least 1e-6·B wider than the hole, reaching
/// at least 1e-3 thicknesses (B = 1e-320 left the FE's contact window unsized: three exit-1
/// runs of the 10⁴ fuzz, 25 Nov 2026) and at most `b_over_d_max` thicknesses wide
/// ([`B_OVER_D_SLAB`], [`B_OVER_D_SINGLE`], [`B_OVER_D_TWO`]).
/// Outside it the solvers' meshes or quadratures cannot be sized within bounded memory and time,
/// so such input is refused rather than left to run out of either.
pub fn domain(a: f64, b: f64, d: f64, b_over_d_max: f64) -> anyhow::Result<()> {
    if !boltzone::route::reach::hole_in_reach(a, d) {
        return usage(
            "--a",
            num(a),
            &format!("the hole radius must be 0 or within 1e-3..1e3 plate thicknesses (A/D = {:.3e} with D = {})", a / d, num(d)),
        );
    }
    if b / d < 1e-3 {
        return usage(
            "--b",
            num(b),
            &format!(
                "the bearing face must reach at least 1e-3 plate thicknesses, as a hole does \
                 (B/D = {:.3e} with D = {})",
                b / d,
                num(d)
            ),
        );
    }
    if b / d > b_over_d_max {
        return usage(
            "--b",
            num(b),
            &format!(
                "this model reaches bearing faces of at most {b_over_d_max:e} plate thicknesses \
                 (B/D = {:.3e} with D = {})",
                b / d,
                num(d)
            ),
        );
    }
    if b - a < 1e-6 * b {
        return usage(
            "--b",
            num(b),
            &format!("the bearing face must be wider than 1e-6·B beyond the hole A = {a}"),
        );
    }
    Ok(())
}

/// A ratio of the lower plate to the upper one within [1/`limit`, `limit`].
pub fn ratio(flag: &str, value: f64, upper: f64, limit: f64, what: &str) -> anyhow::Result<()> {
    let q = value / upper;
    if !(q >= 1.0 / limit && q <= limit) {
        return usage(
            flag,
            num(value),
            &format!("the lower plate's {what} must lie within 1/{limit:e}..{limit:e} times the upper plate's ({upper})"),
        );
    }
    Ok(())
}
