//! The holed route WITH a rim held to its estimates over random geometries (the survey,
//! ignored): the tiers for 1e-3 and 1e-6 against the tier for 1e-8 with 44 Chebyshev heights
//! (the heights converge slowly with a rim: `small_hole_residual.rs`), its own estimate added
//! to the bound. A/D 0.3–3, B/A 1.1–4 (B/D ≤ 8, the rim's reach), ν 0–0.45, C − B from 1.5 to
//! 10 D. The tiers' survey (`two_plate_hole_tiers.rs`) and the 1e-8 tier's
//! (`two_plate_hole_tier8.rs`) cover the infinite plate only; this one found what they could
//! not see.

use super::two_plate_hole_tiers::{survey_n, Rng};
use boltzone::hankel::receding::holed::{two_plate_hole, HoledContact, HoledParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// (A/D, B/A, ν, (C − B)/D) → R_o by `params`, A = 0.1.
fn run(g: (f64, f64, f64, f64), params: &HoledParams) -> HoledContact {
    let (a, (a_over_d, b_over_a, nu, gap)) = (0.1, g);
    let d = a / a_over_d;
    let b = b_over_a * a;
    let plate = SinglePlate::new(
        a,
        OuterRadius::Finite(b + gap * d),
        d,
        Material::new(3.0e7, nu).unwrap(),
        FaceLoad::uniform(a, b, 1.0).unwrap(),
    )
    .unwrap();
    two_plate_hole(&plate, params).unwrap()
}

/// Measured (25 Nov 2026, SURVEY_N = 16, 228 s on two cores): every run within the bar, the
/// largest error/(estimate + reference's) 0.14 at 1e-3 and 0.72 at 1e-6 (A/D 1.77, B/A 1.91,
/// C − B = 6.8D: error 8.6e-10 R_o, estimate 1.2e-9). Rims within ~3.5D of B carry the decay
/// bound's 1e-6 … 6e-4 R_o and are honestly not converged at 1e-6.
#[test]
#[ignore = "survey: about 20 s of CPU per geometry (SURVEY_N, default 16)"]
fn random_rims_are_within_their_estimates() {
    let n = survey_n(16);
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let reference_knobs = HoledParams {
        heights: 44,
        ..HoledParams::for_tolerance(1e-8)
    };
    let mut worst = [0.0f64; 2];
    let mut k = 0;
    while k < n {
        let (ad, ba, nu) = rng.geometry();
        if ad * ba > 8.0 {
            continue;
        }
        k += 1;
        // C − B from 1.5D to 10D, log-uniform (the rim's bound is D·e^(−4.21(C − R_o)/D))
        let gap = rng.uniform(1.5f64.ln(), 10f64.ln()).exp();
        let g = (ad, ba, nu, gap);
        let reference = run(g, &reference_knobs);
        let mut line = format!("A/D {ad:.3} B/A {ba:.3} nu {nu:.3} (C-B)/D {gap:.2}:");
        for (w, tol) in worst.iter_mut().zip([1e-3, 1e-6]) {
            let out = run(g, &HoledParams::for_tolerance(tol));
            let error = (out.r_o - reference.r_o).abs();
            let bar = out.info.r_o_error + reference.info.r_o_error;
            line += &format!(
                "  {tol:.0e}: error {:.1e} estimate {:.1e} (ref {:.1e})",
                error / out.r_o,
                out.info.r_o_error / out.r_o,
                reference.info.r_o_error / out.r_o
            );
            *w = w.max(error / bar);
            assert!(error <= bar, "{line}");
        }
        println!("{line}");
    }
    println!(
        "largest error/(estimate + reference's): {:.2} (1e-3), {:.2} (1e-6)",
        worst[0], worst[1]
    );
}
