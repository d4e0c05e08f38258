//! One R_o from the far table (`boltzone::table::far::separation_radius`), both models; from
//! the near table (`boltzone::table::near`) and from both tables (`boltzone::table::two_plates`,
//! what `two --method table` calls).

use boltzone::table::far::separation_radius;
use boltzone::table::Model;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn far(c: &mut Criterion) {
    // parse the data once, outside the timing
    separation_radius(Model::TwoPlates, 0.1, 1.2, 0.1, 1e-8).unwrap();
    c.bench_function("far two plates R_o", |b| {
        b.iter(|| separation_radius(Model::TwoPlates, black_box(0.1), black_box(1.2), 0.1, 1e-8))
    });
    c.bench_function("far single plate R_o", |b| {
        b.iter(|| {
            separation_radius(
                Model::SinglePlate,
                black_box(0.1),
                black_box(1.2),
                0.1,
                1e-8,
            )
        })
    });
}

fn near(c: &mut Criterion) {
    boltzone::table::near::separation_radius(Model::TwoPlates, 0.1, 0.22, 0.1, 0.3, 1e-3).unwrap();
    c.bench_function("near two plates R_o", |b| {
        b.iter(|| {
            boltzone::table::near::separation_radius(
                Model::TwoPlates,
                black_box(0.1),
                black_box(0.22),
                0.1,
                0.3,
                1e-3,
            )
        })
    });
    c.bench_function("both tables two plates R_o", |b| {
        b.iter(|| {
            boltzone::table::lookup::separation_radius(
                Model::TwoPlates,
                black_box(0.1),
                black_box(0.22),
                0.1,
                0.3,
                1e-3,
            )
        })
    });
}

criterion_group!(benches, far, near);
criterion_main!(benches);
