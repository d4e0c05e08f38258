//! Table 1 on the report's own terms: the 1970 element (four constant-strain triangles, Cst4),
//! the report's spacings (0.015 in radially, ≈ 0.03 in axially; Chapter II) and its criterion
//! (the element-average σ_z of the elements along the midplane, printed at element centres,
//! z = h_z/2 above the midplane). R_o is taken as the inner edge and as the centre of the first
//! element beyond B whose σ_z is tensile, beside the report's single-plate column and our
//! converged midplane value (Q9, level-change estimate, example 03).
//!
//! This separates the two reasons our converged R_o differs from 1970: the coarse element and
//! its one-interval resolution, and σ_z taken half an element above the midplane.
//!
//! Self-check (exit code 1): the converged column agrees with the Hankel route with the hole
//! and the same rim (`boltzone::hankel::hole`, an independent method) within the two error
//! estimates. `BOLTZONE_QUICK=1` runs Table 1's first row (the test suite does).
//!
//! Run: `cargo run --release --example 10_single_report_mesh [rows]` (default 12).
//!
//! Builds on: example 03 (the converged column).

use boltzone::fem::single::{single_plate_r_o, solve_half_plate, FaceCondition, SingleParams};
use boltzone::fem::{centre_stresses, ElementKind, SolveParams, Spacing};
use boltzone::hankel::hole::{single_plate_separation, HoleParams};
use boltzone::hankel::SeparationParams;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

pub fn main() -> anyhow::Result<()> {
    if std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1") {
        return run(1);
    }
    let rows: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse())
        .transpose()?
        .unwrap_or(12);
    run(rows)
}

/// The comparison for the first `rows` rows of Table 1.
pub fn run(rows: usize) -> anyhow::Result<()> {
    let (a, c) = (0.1, 1.54);
    println!(
        "{:>6} {:>5} | {:>7} {:>7} | {:>7} | {:>9}",
        "A/D", "B/A", "edge", "centre", "report", "converged"
    );
    for row in boltzone::reference::table1().into_iter().take(rows) {
        let load = FaceLoad::uniform(a, row.b(), 1.0)?;
        let plate = SinglePlate::new(
            a,
            OuterRadius::Finite(c),
            row.d(),
            Material::unit(0.3)?,
            load,
        )?;
        let radial = Spacing::uniform(a, c, ((c - a) / 0.015).round() as usize)?;
        let nz = (row.d() / 0.03).round() as usize;
        let axial = Spacing::uniform(0.0, row.d(), nz)?;
        let h = solve_half_plate(
            &plate,
            FaceCondition::Pressure,
            ElementKind::Cst4,
            &radial,
            &axial,
            &SolveParams::default(),
        )?;
        let mut first_row: Vec<(f64, f64)> = centre_stresses(&h.mesh, &[plate.material()], &h.u)?
            .into_iter()
            .filter(|p| p.z < row.d() / nz as f64)
            .map(|p| (p.r, p.stress.z))
            .collect();
        first_row.sort_by(|x, y| x.0.total_cmp(&y.0));
        let tensile = first_row
            .iter()
            .find(|(r, s)| *r > row.b() && *s > 0.0)
            .ok_or_else(|| anyhow::anyhow!("no tensile element"))?;
        let (converged, info) = single_plate_r_o(&plate, &SingleParams::default())?;
        // the converged column against the Hankel route with the hole and the same rim
        let (hankel, _) =
            single_plate_separation(&plate, &SeparationParams::default(), &HoleParams::default())?;
        let gap = (converged - hankel.r_o).abs();
        if gap > info.error_estimate + hankel.r_o_error {
            anyhow::bail!(
                "A/D {} B/A {}: FE R_o {converged} and Hankel {} differ by {gap:e}, more than their estimates",
                row.a_over_d,
                row.b_over_a,
                hankel.r_o
            );
        }
        println!(
            "{:>6} {:>5} | {:>7.3} {:>7.3} | {:>7.3} | {:>9.3}",
            row.a_over_d,
            row.b_over_a,
            (tensile.0 - 0.0075) / a,
            tensile.0 / a,
            row.single,
            converged / a
        );
    }
    Ok(())
}
