//! The refinement levels of the single-plate model ([`super::single`]): the graded meshes of
//! each level ([`level_spacings`]), the limits every study shares ([`MAX_LEVELS`],
//! [`FIXED_GRADING_TOLERANCE`], [`FASTEST_ESTIMATE_RATE`]) and the endless iterator over the
//! levels' crossings ([`crossing_levels`]) from which [`super::single::solve`] stops at a
//! tolerance.
//!
//! **Method.** Level l is a mesh graded in r and z with element size h_l = `coarse_size`·D/2^l
//! at the foci — the hole edge A, the load's knots, the load edge B and, from level 1 on, the
//! previous level's R_o (the rim C after a level in full contact) — growing away from them
//! (the rules and their measurements are in [`super::single`]'s docs; the grading ratios in
//! [`crate::fem::spacing::level_grading`]).
//!
//! # Accuracy
//!
//! Measured through the study of [`super::single`] (`tests/fem/single.rs`, example 13).
//!
//! # Cost
//!
//! Each level is one solve of [`super::single::solve_half_plate_with`]; the unknowns grow
//! 1.5–2.8× per level (example 13, `cargo bench --bench fem`).
//!
//! ```
//! use boltzone::fem::single::{crossing_levels, SingleParams};
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.22, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1,
//!                              Material::unit(0.3)?, load)?;
//! let params = SingleParams::default();
//! let levels: Vec<_> = crossing_levels(&plate, &params)?.take(3).collect::<Result<_, _>>()?;
//! assert!(levels[2].dofs > levels[0].dofs); // finer at the foci each level
//! assert!((levels[2].r_o / 0.1 - 3.3).abs() < 0.2); // Table 1 (1, 2.2): 3.3 ± its grid
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::FemError;
use super::midplane_crossing::midplane_of;
use super::single::{solve_half_plate_with, HalfPlate, Refinement, SingleParams};
use super::single_temperature::SingleTemperature;
use super::spacing::{level_grading_below, Spacing, GRADING_FIXED_DOWN_TO};
use crate::error::InputError;
use crate::joint::{OuterRadius, SinglePlate, FAR_RIM};

/// The radial spacing of level 0 for `plate` (knots at the load's knots): the radial part of
/// [`level_spacings`] at level 0.
pub fn coarse_radial_spacing(
    plate: &SinglePlate,
    params: &SingleParams,
) -> Result<Spacing, InputError> {
    Ok(level_spacings(plate, params, 0, None)?.0)
}

/// The radial and axial spacings of refinement level `level` (module docs). Graded: element
/// size `coarse_size`·D/2^level at A, the load's knots, B and `r_focus` (the previous level's
/// R_o), growing by `growth` radially up to 4D and by `axial_growth` away from z = 0 and z = D
/// up to D/2. Uniform: level 0's spacings (without `r_focus`) with every element split into
/// 2^level. An infinite plate ends at C = B + 30D.
pub fn level_spacings(
    plate: &SinglePlate,
    params: &SingleParams,
    level: u32,
    r_focus: Option<f64>,
) -> Result<(Spacing, Spacing), InputError> {
    crate::error::positive("coarse element size", params.coarse_size)?;
    let refinement = params.refinement.for_element(params.kind);
    if refinement == Refinement::Uniform && level > 0 {
        let (r, z) = level_spacings(plate, params, 0, None)?;
        let k = 1usize << level.min(20);
        return Ok((r.refined(k), z.refined(k)));
    }
    let d = plate.half_thickness();
    let (a, b) = (plate.hole_radius(), plate.load().outer());
    let c = match plate.outer_radius() {
        OuterRadius::Infinite => b + FAR_RIM * d,
        OuterRadius::Finite(c) => c.min(b + FAR_RIM * d),
    };
    let h = params.coarse_size * d / 2f64.powi(level as i32);
    let mut foci = vec![a, plate.load().inner(), b];
    // (after a level in full contact, R_o = C: the rim)
    foci.extend(r_focus.filter(|&r| r > a && r <= c));
    // the growth ratios, and the largest axial size, shrink on the finest levels
    // ([`level_grading`]) so that every part of the mesh is refined
    let fixed = if params.tolerance < FIXED_GRADING_TOLERANCE {
        FIXED_GRADING_TIGHT
    } else {
        GRADING_FIXED_DOWN_TO
    };
    let (growth, axial_growth, shrink) =
        level_grading_below(h, d, params.growth, params.axial_growth, fixed);
    let radial = Spacing::graded(a, c, plate.load().knots(), &foci, h, growth, 4.0 * d)?;
    let axial = match refinement {
        Refinement::Graded | Refinement::Auto => Spacing::graded(
            0.0,
            d,
            &[],
            &[0.0, d],
            h,
            axial_growth,
            (0.5 * d * shrink).max(h),
        )?,
        Refinement::Uniform => {
            Spacing::uniform(0.0, d, (1.0 / params.coarse_size).ceil() as usize)?
        }
    };
    Ok((radial, axial))
}

/// Most levels [`solve`](super::single::solve) refines to meet a tolerance for its callers that do not choose
/// (`single --levels`' default, the tables, scenes and figures): the finest has 2⁻⁷ of the
/// first's element size at the foci. [`SingleParams::default`]'s 5 are the fixed study of
/// [`single_plate_r_o`](super::single::single_plate_r_o).
pub const MAX_LEVELS: usize = 8;

/// The tightest `tolerance` whose levels keep the fixed grading down to h = D/64
/// ([`crate::fem::spacing::level_grading`]); tighter ones shrink it from h = D/8 on
/// ([`FIXED_GRADING_TIGHT`]). The fixed grading leaves a floor of 1.2e-6 to 2.4e-6 of R_o that
/// the level-to-level changes do not show: example 16 at `tolerance` 1e-5 found 15 of 355
/// converged runs over their estimate (up to 1.71×, most stopping at level 5, the last fixed
/// one); at 1e-4 none (at most 0.84 of it).
pub const FIXED_GRADING_TOLERANCE: f64 = 1e-4;

/// The shrink of the error estimate per level beyond which [`solve`](super::single::solve) decides that a tolerance
/// is out of reach and stops, not converged: twice the fastest seen (38×, from level 3 to 4;
/// 2–15× elsewhere, on 15 geometries of example 16 over 8 levels with either grading), so that
/// no reachable tolerance is given up. `table1 --tol 1e-320` solved every level of the finer
/// tight-tolerance grading: 9.7 s and 266 MB, over the fuzz's 30 s under load.
pub const FASTEST_ESTIMATE_RATE: f64 = 76.0;

/// Element size, in D, below which a study tighter than [`FIXED_GRADING_TOLERANCE`] shrinks
/// its grading: from level 3 on (h = D/16 with the default `coarse_size`).
pub const FIXED_GRADING_TIGHT: f64 = 1.0 / 8.0;

/// The discrete crossing R_o of one mesh level, and that mesh's size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelCrossing {
    /// First upward zero of the recovered midplane σ_z beyond B on this mesh; a finite rim C
    /// where σ_z stays compressive out to it (full contact).
    pub r_o: f64,
    /// In full contact, the least compression of the midplane beyond B, −max σ_z (in the load's
    /// units): how far this mesh is from opening near the rim; None where σ_z turned tensile.
    pub full_contact_margin: Option<f64>,
    /// Nodes of the mesh.
    pub nodes: usize,
    /// Equations of the mesh.
    pub dofs: usize,
}

/// The crossings of the refinement levels of the module docs (level l: element size
/// `coarse_size`·D/2^l at the foci, graded toward the previous level's R_o): an endless
/// iterator, so callers choose how many levels and when to stop ([`single_plate_r_o`](super::single::single_plate_r_o) takes
/// `params.levels`; the comparison module stops at a tolerance).
pub struct CrossingLevels<'a> {
    plate: &'a SinglePlate,
    params: &'a SingleParams,
    previous: Option<f64>,
    level: u32,
    /// Keep each level's solved half plate (for a field or curve output).
    pub(super) keep: bool,
    pub(super) last: Option<HalfPlate>,
    pub(super) temperature: Option<&'a SingleTemperature>,
}

/// Refinement levels of the single-plate model (see [`CrossingLevels`]).
pub fn crossing_levels<'a>(
    plate: &'a SinglePlate,
    params: &'a SingleParams,
) -> Result<CrossingLevels<'a>, FemError> {
    level_spacings(plate, params, 0, None)?; // checks the parameters once
    Ok(CrossingLevels {
        plate,
        params,
        previous: None,
        level: 0,
        keep: false,
        last: None,
        temperature: None,
    })
}

impl Iterator for CrossingLevels<'_> {
    type Item = Result<LevelCrossing, FemError>;

    fn next(&mut self) -> Option<Self::Item> {
        let p = self.params;
        let solved = level_spacings(self.plate, p, self.level, self.previous)
            .map_err(FemError::from)
            .and_then(|(radial, axial)| {
                solve_half_plate_with(self.plate, p, &radial, &axial, self.temperature)
            })
            .and_then(|h| {
                let m = midplane_of(self.plate, &h);
                if self.keep {
                    self.last = Some(h);
                }
                m
            });
        self.level += 1;
        let level = solved.and_then(|m| {
            let b = self.plate.load().outer();
            let (r_o, full_contact_margin) =
                match (m.first_tensile_crossing(b), self.plate.outer_radius()) {
                    (Some(r_o), _) => (r_o, None),
                    // compressive out to a finite rim: full contact, R_o = C (an answer)
                    (None, OuterRadius::Finite(c)) => {
                        let peak =
                            m.r.iter()
                                .zip(&m.sigma_z)
                                .filter(|(r, _)| **r >= b)
                                .fold(f64::NEG_INFINITY, |p, (_, s)| p.max(*s));
                        (c, Some(-peak))
                    }
                    (None, OuterRadius::Infinite) => {
                        return Err(FemError::Solver(
                            "the midplane stress never turns tensile inside the plate".into(),
                        ))
                    }
                };
            Ok(LevelCrossing {
                r_o,
                full_contact_margin,
                nodes: m.nodes,
                dofs: m.dofs,
            })
        });
        self.previous = level.as_ref().ok().map(|l| l.r_o);
        Some(level)
    }
}
