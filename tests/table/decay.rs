//! The decay study behind the far table's handover bound (example 24 prints it whole).

#[allow(dead_code)]
#[path = "../../examples/24_hole_decay.rs"]
mod ex22;

use boltzone::table::decay::{fit_decay, HANDOVER_RATE};
use boltzone::table::far::{HANDOVER_K_SINGLE, HANDOVER_K_TWO};

/// (B − A)/D = 0.5 … 8 in steps of 0.5: x from ≈ 1 to ≈ 8.5, where Δ reaches the routes' floor.
fn widths() -> Vec<f64> {
    (1..=16).map(|k| 0.5 * k as f64).collect()
}

#[test]
#[ignore = "study: about 10 minutes of CPU (the two-plate route at 1e-8 out to B/D = 12)"]
fn the_hole_decays_at_least_at_the_round_trip_rate_within_the_handover_bound() {
    let widths = widths();
    for (model, k_bound) in [("two", HANDOVER_K_TWO), ("single", HANDOVER_K_SINGLE)] {
        for a in [0.25, 1.0, 4.0] {
            let pts = ex22::points(model == "two", a, 0.3, &widths).unwrap();
            let f = fit_decay(&pts, 1.0, HANDOVER_RATE).unwrap();
            // the handover bound needs the decay at least as fast as the round trip's rate:
            // within three of the fit's own one-sigma uncertainties of it, or faster (the
            // survey's fits: 3.9–5.2, the second mode's 5.36 mixing in on two plates)
            assert!(
                f.alpha >= HANDOVER_RATE - 3.0 * f.alpha_sigma,
                "{model}, A/D {a}: α = {} ± {}",
                f.alpha,
                f.alpha_sigma
            );
            let k = ex22::prefactor(&pts);
            assert!(
                k <= k_bound,
                "{model}, A/D {a}: prefactor {k} over {k_bound}"
            );
        }
    }
}
