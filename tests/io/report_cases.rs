//! The report's own cases as 1970 decks (issue 12, item 4). Table 2's case 4 (the 1/4 in pair:
//! D = 0.253 in, A = 0.1285 in, B = 0.211 in, C = 2 in) as the 1970 program ran the two-plate
//! model: one plate on its frictionless interface, held (code 2) out to a trial contact radius,
//! free beyond. A trial zone is admissible when no free interface node moves into the other
//! plate (w ≥ 0 beyond it) and the interface stays compressive inside it (here: σ_z at the
//! centres of the bottom row of elements). The report's computed 2R_o = 0.700 in passes both
//! checks through the stored deck; zones 14 % smaller and larger each fail one of them.

use boltzone::fem::Spacing;
use boltzone::io::deck::{plate_on_plane_deck, read_decks, run, DeckSolution};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

/// (w of the first free interface node beyond `rc`, largest σ_z of the bottom-row elements
/// inside `rc`).
fn checks(sol: &DeckSolution, rc: f64, row_height: f64) -> (f64, f64) {
    let beyond = sol
        .nodes
        .iter()
        .filter(|n| n.z == 0.0 && n.r > rc * (1.0 + 1e-9));
    let first = beyond
        .min_by(|a, b| a.r.total_cmp(&b.r))
        .map_or(f64::NAN, |n| n.w);
    let inside = sol.elements.iter().filter(|e| e.z < row_height && e.r < rc);
    (
        first,
        inside.map(|e| e.sigma_z).fold(f64::NEG_INFINITY, f64::max),
    )
}

#[test]
fn report_contact_radius_of_the_quarter_inch_pair_is_admissible() {
    // written by: boltzone deck --emit tests/data/decks/table2_case4.deck --a 0.1285 --b 0.211
    //             --c 2.0 --d 0.253 --contact 0.35 --h 0.03
    let text = std::fs::read_to_string("tests/data/decks/table2_case4.deck").unwrap();
    let sol = run(&read_decks(&text).unwrap()[0]).unwrap();
    let (w, s) = checks(&sol, 0.35, 0.03);
    println!(
        "report's R_o = 0.350 in: first free node w = {w:.3e} in, bottom-row σ_z ≤ {s:.1} psi"
    );
    assert!(w > 0.0 && s < 0.0, "w {w}, σ_z {s}");
}

#[test]
fn trial_contact_zones_too_small_or_too_large_fail_the_checks() {
    let load = FaceLoad::uniform(0.1285, 0.211, 1000.0).unwrap();
    let m = Material::new(28.0e6, 0.3).unwrap();
    let plate = SinglePlate::new(0.1285, OuterRadius::Finite(2.0), 0.253, m, load).unwrap();
    let pts = |a: f64, b: f64, n| Spacing::uniform(a, b, n).unwrap().points().to_vec();
    let mut outcome = Vec::new();
    for rc in [0.30, 0.35, 0.40] {
        let mut r = pts(0.1285, 0.211, 6);
        for (a, b, n) in [(0.211, rc, 10), (rc, 0.8, 30), (0.8, 2.0, 24)] {
            r.extend_from_slice(&pts(a, b, n)[1..]);
        }
        let radial = Spacing::from_points(r).unwrap();
        let axial = Spacing::uniform(0.0, 0.253, 10).unwrap();
        let deck =
            plate_on_plane_deck(&plate, &radial, &axial, "TABLE 2 CASE 4", Some(rc)).unwrap();
        let (w, s) = checks(&run(&deck).unwrap(), rc, 0.0253);
        println!("trial R = {rc} in: first free node w = {w:.3e} in, bottom-row σ_z ≤ {s:.1} psi");
        outcome.push((w > 0.0, s < 0.0));
    }
    // measured: w = −1.3e-7 in at 0.30 (penetration); σ_z up to +60 psi at 0.40 (tension)
    assert_eq!(outcome, [(false, true), (true, true), (true, false)]);
}
