//! The holed route's rim on a wide load (B/D = 8, the rim's reach): the loose tiers' R_o against
//! the 1e-6 tier's. Before the rim's trials took the infinite route's Nyström points for wide
//! loads (`Setup::nodes_for`: more beyond B = 3.5D), the 1e-3 tier put R_o 2.4e-3 R_o off on
//! (A/D, B/D) = (0.5, 8) and 1.3e-3 on (2, 8), outside the tolerance and not converged, where the
//! infinite plate's own R_o met it with room to spare.

use boltzone::hankel::receding::holed::{two_plate_hole, HoledParams};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

#[test]
fn a_wide_load_with_a_rim_meets_the_loose_tolerance_and_its_estimate() {
    // D = 1, B = 8, C = 20 (12D beyond the load), ν = 0.3
    let load = FaceLoad::uniform(2.0, 8.0, 1.0).unwrap();
    let plate = SinglePlate::new(
        2.0,
        OuterRadius::Finite(20.0),
        1.0,
        Material::unit(0.3).unwrap(),
        load,
    )
    .unwrap();
    let fine = two_plate_hole(&plate, &HoledParams::for_tolerance(1e-6)).unwrap();
    assert!(fine.info.r_o_error < 1e-6 * fine.r_o, "{:?}", fine.info);
    let rim = fine.info.rim.as_ref().unwrap();
    // the rim moves R_o by ~4e-4 R_o here: far above the 1e-6 tier's estimate
    assert!((fine.r_o - rim.r_o_infinite).abs() > 1e2 * fine.info.r_o_error);
    let loose = two_plate_hole(&plate, &HoledParams::for_tolerance(1e-3)).unwrap();
    let error = (loose.r_o - fine.r_o).abs();
    println!(
        "R_o = {:.9} ± {:.1e} (1e-6 tier), {:.9} ± {:.1e} (1e-3 tier), difference {error:.1e}",
        fine.r_o, fine.info.r_o_error, loose.r_o, loose.info.r_o_error
    );
    assert!(loose.info.r_o_error < 1e-3 * loose.r_o, "{:?}", loose.info);
    assert!(error <= loose.info.r_o_error + fine.info.r_o_error);
}
