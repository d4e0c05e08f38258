//! Benchmarks of the two-plate model (time against accuracy; see the report in the closing note).
//!
//! - one Table 1 geometry (A/D = 1, B/A = 3.1 and the costliest, B/A = 1.3, A/D = 0.5) to 0.05 %;
//! - all 24 values of Table 1 (single-plate by `fem::single`, two-plate by `contact`) with rayon
//!   across geometries and faer sequential inside;
//! - the share of the contact iterations against the linear solve, printed from the Info.

use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::fem::single::{single_plate_r_o, SingleParams};
use boltzone::reference::{table1, TABLE1_HOLE_RADIUS, TABLE1_OUTER_RADIUS, TABLE1_POISSON};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, SinglePlate};
use criterion::{criterion_group, criterion_main, Criterion};
use rayon::prelude::*;
use std::hint::black_box;

fn joint(b_over_a: f64, a_over_d: f64) -> Joint {
    let a = TABLE1_HOLE_RADIUS;
    Joint::symmetric(
        a,
        a * b_over_a,
        a / a_over_d,
        Material::unit(TABLE1_POISSON).unwrap(),
    )
    .unwrap()
    .with_outer_radius(OuterRadius::Finite(TABLE1_OUTER_RADIUS))
    .unwrap()
}

fn single(j: &Joint) -> f64 {
    let plate = SinglePlate::new(
        j.hole_radius(),
        j.outer_radius(),
        j.upper().thickness(),
        j.upper().material(),
        FaceLoad::uniform(j.hole_radius(), j.load().outer(), 1.0).unwrap(),
    )
    .unwrap();
    single_plate_r_o(&plate, &SingleParams::default())
        .unwrap()
        .0
}

fn bench(c: &mut Criterion) {
    let params = TwoPlateParams::default();
    for (b, ad) in [(3.1, 1.0), (1.3, 0.5)] {
        let j = joint(b, ad);
        let s = solve(&j, &params).unwrap();
        let lin: f64 = s.info.levels.iter().map(|l| l.time_linear).sum();
        let con: f64 = s.info.levels.iter().map(|l| l.time_contact).sum();
        eprintln!(
            "B/A={b} A/D={ad}: R_o/A = {:.5} ± {:.1e}, {} levels, finest {} nodes, contact/linear time = {:.2}",
            s.r_o / 0.1,
            s.r_o_error / 0.1,
            s.info.levels.len(),
            s.info.levels.last().unwrap().nodes,
            con / lin
        );
        c.bench_function(&format!("two_plate_table1_BA{b}_AD{ad}"), |bn| {
            bn.iter(|| solve(black_box(&j), &params).unwrap().r_o)
        });
    }
    let joints: Vec<Joint> = table1()
        .iter()
        .map(|r| joint(r.b_over_a, r.a_over_d))
        .collect();
    c.bench_function("table1_all_12_two_plate_rayon", |bn| {
        bn.iter(|| {
            joints
                .par_iter()
                .map(|j| solve(j, &params).unwrap().r_o)
                .sum::<f64>()
        })
    });
    c.bench_function("table1_all_24_values_rayon", |bn| {
        bn.iter(|| {
            joints
                .par_iter()
                .map(|j| solve(j, &params).unwrap().r_o + single(j))
                .sum::<f64>()
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(std::time::Duration::from_secs(5));
    targets = bench
}
criterion_main!(benches);
