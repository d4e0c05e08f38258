//! One R_o from the far table (`boltzone::table::far::separation_radius`), both models.

use boltzone::table::far::{separation_radius, FarModel};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn far(c: &mut Criterion) {
    // parse the data once, outside the timing
    separation_radius(FarModel::TwoPlates, 0.1, 1.2, 0.1, 1e-8).unwrap();
    c.bench_function("far two plates R_o", |b| {
        b.iter(|| {
            separation_radius(
                FarModel::TwoPlates,
                black_box(0.1),
                black_box(1.2),
                0.1,
                1e-8,
            )
        })
    });
    c.bench_function("far single plate R_o", |b| {
        b.iter(|| {
            separation_radius(
                FarModel::SinglePlate,
                black_box(0.1),
                black_box(1.2),
                0.1,
                1e-8,
            )
        })
    });
}

criterion_group!(benches, far);
criterion_main!(benches);
