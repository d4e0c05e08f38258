//! Example 28: the fitted edge's levels on fixed no-hole infinite plates against
//! the receding contact, per level: the force root's error and its Richardson value.
//! Arguments: `levels case…` with case `B:nu`.

use boltzone::contact::two_plate::{solve, TwoPlateParams};
use boltzone::hankel::receding::{Layer, RecedingParams};
use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
use std::time::Instant;

pub fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args
        .first()
        .ok_or_else(|| anyhow::anyhow!("usage: 28_fe_floor LEVELS B:nu…"))?
        .parse()?;
    for c in &args[1..] {
        let v: Vec<f64> = c.split(':').map(str::parse).collect::<Result<_, _>>()?;
        anyhow::ensure!(v.len() == 2, "a case is B:nu, got {c}");
        let (b, nu) = (v[0], v[1]);
        let m = Material::unit(nu)?;
        let load = FaceLoad::uniform(0.0, b, 1.0)?;
        let r = Layer::new(1.0, m, load.clone())?.receding_contact(&RecedingParams::default())?;
        let r2 = Layer::new(1.0, m, load.clone())?.receding_contact(&RecedingParams {
            nodes_per_thickness: 8.0,
            min_nodes: 32,
            rel_tol: 1e-14,
            ..Default::default()
        })?;
        let exact = r.r_o;
        let plate = Plate::new(1.0, m)?;
        let joint = Joint::new(0.0, OuterRadius::Infinite, plate, plate, load)?;
        let t = Instant::now();
        let s = solve(
            &joint,
            &TwoPlateParams {
                tolerance: 1e-13,
                min_levels: n,
                max_levels: n,
                fitted_edge: true,
                ..Default::default()
            },
        )?;
        println!(
            "B {b} nu {nu}: exact {exact:.13} (tighter differs {:+.1e}, claimed {:.1e}) cut {:?} {:.1} s",
            (r2.r_o - exact) / exact,
            r.info.r_o_error,
            s.info.cut,
            t.elapsed().as_secs_f64()
        );
        let mut prev: Option<f64> = None;
        for l in &s.info.levels {
            let f = l.r_o_fit_force.unwrap_or(f64::NAN);
            let e = (f - exact) / exact;
            let x = prev.map_or(f64::NAN, |p| (2.0 * f - p - exact) / exact);
            println!(
                "  h/D 1/{:<5.0} nodes {:7} raw {e:+.3e} rich {x:+.3e}",
                1.0 / l.h,
                l.nodes
            );
            prev = Some(f);
        }
    }
    Ok(())
}
