//! The 200-joint study of the orderings and the estimates (run by hand; its figures are
//! quoted in the report of the change).

#[test]
#[ignore = "200 random joints against 100× tighter runs: minutes on two cores"]
fn orderings_and_honest_estimates_on_200_random_joints() {
    let worst = crate::compliance::check_random_joints(2230, 200, 5e-4, true);
    println!("largest actual / estimated error over 200 joints: {worst:.3}");
}
