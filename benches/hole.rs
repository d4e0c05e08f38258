//! Time of the single plate with a hole by the Hankel route: R_o with N doubled until R_o's
//! error estimate is below 1e-6 R_o (or N = 64), for the easiest and the hardest of
//! Table 1's geometries, by the default route (slab traction on the hole as a Chebyshev profile
//! in z) and by the direct per-height route it replaced; then the pieces: the slab's traction
//! profile alone, and the hole fit alone at N = 16. Time against error for all twelve
//! geometries: `examples/14_hole_speed.rs`.
use boltzone::hankel::hole::plate::extended_load;
use boltzone::hankel::hole::TractionProfile;
use boltzone::hankel::hole::{single_plate_separation, HoleParams, HolePlate, SlabSampling};
use boltzone::hankel::{QuadParams, SeparationParams, Slab};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use criterion::{criterion_group, criterion_main, Criterion};

fn plate(a_over_d: f64, b_over_a: f64) -> SinglePlate {
    let a = 0.1;
    let load = FaceLoad::uniform(a, a * b_over_a, 1.0).unwrap();
    SinglePlate::new(
        a,
        OuterRadius::Infinite,
        a / a_over_d,
        Material::unit(0.3).unwrap(),
        load,
    )
    .unwrap()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("hole");
    g.sample_size(20);
    for (ad, ba) in [(1.0, 3.1), (0.5, 1.3)] {
        let p = plate(ad, ba);
        for (name, sampling) in [
            ("profile", SlabSampling::Profile),
            ("direct", SlabSampling::Direct),
        ] {
            let params = HoleParams {
                slab_sampling: sampling,
                ..HoleParams::default()
            };
            g.bench_function(
                format!("R_o to 1e-6, A/D = {ad}, B/A = {ba}, {name}"),
                |b| {
                    b.iter(|| {
                        single_plate_separation(&p, &SeparationParams::default(), &params).unwrap()
                    })
                },
            );
        }
        let slab = Slab::new(
            p.half_thickness(),
            p.material(),
            extended_load(p.load(), 0.1, p.half_thickness())
                .unwrap()
                .unwrap(),
        )
        .unwrap();
        let quad = QuadParams {
            rel_tol: 1e-10,
            ..QuadParams::default()
        };
        g.bench_function(
            format!("slab traction profile to 1e-8, A/D = {ad}, B/A = {ba}"),
            |b| b.iter(|| TractionProfile::new(&slab, 0.1, 1e-8, &quad)),
        );
    }
    let p = plate(1.0, 3.1);
    let fixed = HoleParams {
        terms: Some(16),
        ..HoleParams::default()
    };
    g.bench_function("fit N = 16, A/D = 1, B/A = 3.1", |b| {
        b.iter(|| HolePlate::new(&p, &fixed).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
