//! Time of the slab solver: R_o to 1e-10 relative, and the midplane curve (1000 radii, 1e-10).
use boltzone::hankel::{MidplaneCurve, SeparationParams, Slab};
use boltzone::{FaceLoad, Material};
use criterion::{criterion_group, criterion_main, Criterion};

fn bench(c: &mut Criterion) {
    let slab = Slab::new(
        0.1,
        Material::unit(0.3).unwrap(),
        FaceLoad::uniform(0.1, 0.31, 1.0).unwrap(),
    )
    .unwrap();
    c.bench_function("separation_radius 1e-10 (A=D=0.1, B=0.31)", |b| {
        b.iter(|| {
            slab.separation_radius(&SeparationParams::default())
                .unwrap()
        })
    });
    c.bench_function("midplane curve 1000 radii 1e-10", |b| {
        b.iter(|| {
            let curve = MidplaneCurve::new(&slab, 0.0, 1.0, 1e-10).unwrap();
            (0..1000)
                .map(|k| curve.eval(k as f64 / 999.0).value)
                .sum::<f64>()
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
