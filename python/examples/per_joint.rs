//! The library's own time per joint on one scene: `boltzone::solve` called N times (default
//! 200) after one warm-up call, the median and the minimum printed in microseconds. Its Python
//! twin is `python/examples/per_joint.py`: the same scene through `boltzone.solve`, so the two
//! medians give the binding's overhead per joint.
//!
//! `cargo run --release -p boltzone-python --example per_joint -- SCENE.toml [N]`

use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).ok_or("usage: per_joint SCENE.toml [N]")?;
    let n: usize = args.get(2).map_or(Ok(200), |s| s.parse())?;
    let scene = boltzone::scene::Scene::parse(&std::fs::read_to_string(path)?)?;
    let first = boltzone::solve(&scene)?;
    let mut times = Vec::with_capacity(n);
    for _ in 0..n {
        let t = Instant::now();
        let s = boltzone::solve(&scene)?;
        times.push(t.elapsed().as_secs_f64() * 1e6);
        assert_eq!(s.r_o, first.r_o, "the same scene gives the same R_o");
    }
    times.sort_by(f64::total_cmp);
    println!(
        "rust   {path}: median {:.1} us, min {:.1} us over {n} calls (R_o = {} {})",
        times[n / 2],
        times[0],
        first.r_o,
        first.length_unit
    );
    Ok(())
}
