//! Time against achieved accuracy of the single plate's R_o with the hole (Hankel route), for
//! Table 1's twelve geometries: the default route (slab traction on the hole as a Chebyshev
//! profile in z, `SlabSampling::Profile`) beside the direct per-height route it replaced
//! (`SlabSampling::Direct`), both against a tight reference.
//!
//! **Problem.** Single plate 2D thick, hole radius A = 0.1, uniform pressure on A ≤ r ≤ B on
//! both faces, ν = 0.3, infinite outer radius; A/D ∈ {1, 0.75, 0.5}, B/A ∈ {3.1, 2.2, 1.6, 1.3}.
//! R_o is the first upward zero of the midplane σ_z beyond B.
//!
//! **Reference.** The same model with N = 2·`n_ref` Papkovich–Fadle modes fixed and the slab's
//! hole traction to 1e-10 P (about the tightest the quadrature confirms next to the face); its
//! own uncertainty is the change from N = `n_ref` to 2·`n_ref` (the hole residual falls like
//! N^(−1.74), R_o's error faster). "actual" is |R_o − reference|.
//!
//! **What to expect.** N doubles from 4 until R_o's own error estimate is below 1e-6 R_o: six
//! rows stop at N = 8 and six (the narrower loads) at N = 16, in 4.0–8.3 ms (idle machine,
//! 2026-11-25), of which the slab's traction profile is 1–3 ms and the corner enrichment's
//! tractions at the new heights about as much again. The self-check: every actual error within
//! its estimate plus the reference's uncertainty, and the two routes' R_o equal within their
//! slab-data errors.
//!
//! Times are wall-clock, the minimum and median of `reps` runs (the machine is shared: state
//! its load beside them).
//!
//! Run: `cargo run --release --example 14_hole_speed [rows] [n_ref] [reps]` (default 12 rows,
//! n_ref = 128, 15 repetitions).
//!
//! Builds on: example 05 (the hole correction, timed).

use boltzone::hankel::hole::{single_plate_separation, HoleInfo, HoleParams, SlabSampling};
use boltzone::hankel::{SeparationInfo, SeparationParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use std::time::Instant;

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        return run(2, 16, 1);
    }
    let mut args = std::env::args().skip(1);
    let rows: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(12);
    let n_ref: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(128);
    let reps: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(15);
    run(rows, n_ref, reps)
}

/// One route timed: (min ms, median ms, R_o, hole info).
struct Timed {
    min: f64,
    median: f64,
    sep: SeparationInfo,
    hole: HoleInfo,
}

fn timed(plate: &SinglePlate, params: &HoleParams, reps: usize) -> anyhow::Result<Timed> {
    let mut ms = Vec::with_capacity(reps);
    let mut last = None;
    for _ in 0..reps.max(1) {
        let t = Instant::now();
        let out = single_plate_separation(plate, &SeparationParams::default(), params)?;
        ms.push(1e3 * t.elapsed().as_secs_f64());
        last = Some(out);
    }
    ms.sort_by(f64::total_cmp);
    let (sep, hole) = last.expect("at least one run");
    Ok(Timed {
        min: ms[0],
        median: ms[ms.len() / 2],
        sep,
        hole,
    })
}

/// The table for the first `rows` rows of Table 1, reference N = 2·`n_ref`, `reps` timings.
pub fn run(rows: usize, n_ref: usize, reps: usize) -> anyhow::Result<()> {
    let a = 0.1;
    println!(
        "R_o/A of the single plate with a hole, Hankel route (A = {a}, ν = 0.3, C = ∞); errors ÷A, \
         times in ms (min/median of {reps})"
    );
    println!(
        "{:>5} {:>4} | {:>13} {:>8} | {:>8} {:>8} {:>3} {:>6} {:>13} | {:>8} {:>13} | {:>7}",
        "A/D",
        "B/A",
        "reference",
        "± ref",
        "estim.",
        "actual",
        "N",
        "nodes",
        "ms profile",
        "actual",
        "ms direct",
        "speedup"
    );
    let (mut total_profile, mut total_direct) = (0.0, 0.0);
    for row in boltzone::reference::table1().into_iter().take(rows) {
        let plate = SinglePlate::new(
            a,
            OuterRadius::Infinite,
            a / row.a_over_d,
            Material::unit(0.3)?,
            FaceLoad::uniform(a, a * row.b_over_a, 1.0)?,
        )?;
        let reference = |n: usize| {
            let params = HoleParams {
                terms: Some(n),
                slab_tolerance: 1e-10,
                ..HoleParams::default()
            };
            single_plate_separation(&plate, &SeparationParams::default(), &params)
        };
        let (r_fine, _) = reference(2 * n_ref)?;
        let (r_coarse, _) = reference(n_ref)?;
        let r_ref = r_fine.r_o;
        // (a fixed-N run's own estimate is the residual bound max residual·P/slope, far above
        // its actual error: the change under doubling N is the honest measure here)
        let ref_unc = (r_fine.r_o - r_coarse.r_o).abs();
        let profile = timed(&plate, &HoleParams::default(), reps)?;
        let direct_params = HoleParams {
            slab_sampling: SlabSampling::Direct,
            ..HoleParams::default()
        };
        let direct = timed(&plate, &direct_params, reps)?;
        let actual = (profile.sep.r_o - r_ref).abs();
        let actual_direct = (direct.sep.r_o - r_ref).abs();
        total_profile += profile.min;
        total_direct += direct.min;
        println!(
            "{:>5} {:>4} | {:>13.10} {:>8.1e} | {:>8.1e} {:>8.1e} {:>3} {:>6} {:>6.2}/{:<6.2} | {:>8.1e} {:>6.2}/{:<6.2} | {:>6.1}x",
            row.a_over_d,
            row.b_over_a,
            r_ref / a,
            ref_unc / a,
            profile.sep.r_o_error / a,
            actual / a,
            profile.hole.terms,
            profile.hole.slab_evaluations,
            profile.min,
            profile.median,
            actual_direct / a,
            direct.min,
            direct.median,
            direct.min / profile.min
        );
        anyhow::ensure!(
            actual <= profile.sep.r_o_error + ref_unc,
            "A/D {} B/A {}: actual error {actual:e} beyond estimate {:e} + reference {ref_unc:e}",
            row.a_over_d,
            row.b_over_a,
            profile.sep.r_o_error
        );
        // The two routes differ only in the slab data: their R_o agree within the data errors.
        let data = (profile.hole.slab_error + direct.hole.slab_error) / profile.sep.slope.abs();
        let diff = (profile.sep.r_o - direct.sep.r_o).abs();
        anyhow::ensure!(
            diff <= data + 1e-9 * r_ref,
            "routes differ by {diff:e} (data errors {data:e})"
        );
    }
    println!(
        "sum of minimum times: profile {total_profile:.1} ms, direct {total_direct:.1} ms ({:.1}x)",
        total_direct / total_profile
    );
    Ok(())
}
