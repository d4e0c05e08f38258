//! `single --method hankel --curve FILE`: the midplane normal stress σ_z(r, 0) of the single
//! plate 2D thick with its hole made traction-free, by the semi-analytic route
//! ([`boltzone::hankel::hole`]): the slab under the extended load (a Hankel-transform integral on
//! one node set for all radii, [`boltzone::hankel::midplane::MidplaneRule`]) plus the fitted
//! hole correction (modes and corner enrichment, [`HolePlate::correction_midplane`]), with the
//! number of modes the R_o search converged with. Compression negative; P = 1 psi (stresses scale
//! with P). Same CSV layout as the FE curve (`r [in]`, `sigma_z [psi]`, [`super::output`]).
//!
//! Error bound of each value: the slab quadrature's estimate plus the hole fit's largest residual
//! traction × P (a traction error δt on the hole's face changes σ_z by at most max|δt|, see
//! [`boltzone::hankel::hole`]); its maximum over the curve is in the file's notes.
//!
//! # Accuracy
//!
//! `tests/io/curve_hankel.rs` compares the curve with the FE curve of the same plate within both
//! error bars.
//!
//! # Cost
//!
//! One hole fit at the final N and one quadrature rule (a fraction of the R_o search; measured in
//! that test).

use boltzone::hankel::hole::{HoleInfo, HoleParams, HolePlate};
use boltzone::hankel::midplane::MidplaneRule;
use boltzone::{OuterRadius, SinglePlate};

/// Radii of the curve: from A to min(C, B + 8 D) (D the half thickness), `n` equal steps.
pub fn radii(plate: &SinglePlate, n: usize) -> Vec<f64> {
    let (a, d, b) = (
        plate.hole_radius(),
        plate.half_thickness(),
        plate.load().outer(),
    );
    let end = match plate.outer_radius() {
        OuterRadius::Finite(c) => c.min(b + 8.0 * d),
        OuterRadius::Infinite => b + 8.0 * d,
    };
    (0..=n)
        .map(|i| a + (end - a) * i as f64 / n as f64)
        .collect()
}

/// σ_z(r, 0) at `r` with its error bound (module docs), for the plate fitted with `info.terms`
/// modes; and the largest bound.
pub fn midplane_curve(
    plate: &SinglePlate,
    params: &HoleParams,
    info: &HoleInfo,
    r: &[f64],
) -> anyhow::Result<(Vec<[f64; 2]>, f64)> {
    // as the R_o search: a rim beyond B + 30 D is an infinite plate to every digit
    let far = boltzone::fem::single::FAR_RIM * plate.half_thickness() + plate.load().outer();
    let outer = match plate.outer_radius() {
        OuterRadius::Finite(c) if c > far => OuterRadius::Infinite,
        o => o,
    };
    let (a, d, mat) = (
        plate.hole_radius(),
        plate.half_thickness(),
        plate.material(),
    );
    let plate = &SinglePlate::new(a, outer, d, mat, plate.load().clone())?;
    let holed = HolePlate::with_terms(plate, params, info.terms)?;
    let p = plate.load().mean_pressure().abs();
    let r_max = r.iter().copied().fold(plate.hole_radius(), f64::max);
    let rule = MidplaneRule::new(holed.slab(), r_max, 1e-9 * p)?;
    let residual = holed.info().residual_max.max(holed.info().rim_residual_max) * p;
    let mut worst: f64 = 0.0;
    let values = r
        .iter()
        .map(|&x| {
            let slab = rule.eval(x);
            let err = slab.error + residual;
            worst = worst.max(err);
            [slab.value + holed.correction_midplane(x), err]
        })
        .collect();
    Ok((values, worst))
}
