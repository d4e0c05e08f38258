//! Criterion benchmarks of the FE pipeline: mesh + assembly + sparse Cholesky + one solve at
//! about 10⁴ and 10⁵ equations (the 10⁶ case takes ~10–25 s per run: time it with
//! `cargo run --release --example 08_fem_scaling`), and the single-plate R_o of Table 1's first
//! geometry to 0.05 %.
//!
//! Run: `cargo bench --bench fem`.

use boltzone::fem::single::{single_plate_r_o, SingleParams};
use boltzone::fem::ElementKind;
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use criterion::{criterion_group, criterion_main, Criterion};

#[allow(dead_code)]
#[path = "../examples/08_fem_scaling.rs"]
mod scaling;

fn pipeline(c: &mut Criterion) {
    let mut g = c.benchmark_group("assemble_factor_solve");
    g.sample_size(10);
    for kind in [ElementKind::Q4, ElementKind::Q9] {
        for dofs in [10_000, 100_000] {
            g.bench_function(format!("{kind:?}/{dofs}"), |b| {
                b.iter(|| scaling::run_size(kind, dofs, 0.1, false).unwrap())
            });
        }
    }
    g.finish();
}

fn single_plate(c: &mut Criterion) {
    let load = FaceLoad::uniform(0.1, 0.31, 1.0).unwrap();
    let plate = SinglePlate::new(
        0.1,
        OuterRadius::Finite(1.54),
        0.1,
        Material::unit(0.3).unwrap(),
        load,
    )
    .unwrap();
    let mut g = c.benchmark_group("single_plate_r_o");
    g.sample_size(10);
    for levels in [3, 4] {
        let params = SingleParams {
            levels,
            ..SingleParams::default()
        };
        g.bench_function(format!("Q9/levels{levels}"), |b| {
            b.iter(|| single_plate_r_o(&plate, &params).unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, pipeline, single_plate);
criterion_main!(benches);
