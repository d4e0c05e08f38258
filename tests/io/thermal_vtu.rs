//! Thermal stresses in the VTU (`[outputs] field` with `[temperature]`, issue 12 item 5): a
//! single-plate scene at a uniform temperature (α constant) and the same scene without one,
//! both written by `boltzone solve` and read back by Python's meshio. By superposition the
//! difference of the two files is the free body under a uniform ΔT: zero stress (σ = D(ε − ε_th)
//! must cancel the free expansion exactly) and u = α ΔT r, w = α ΔT z, on the whole grid
//! including the mirrored lower half; the file carries the nodal temperature. Without
//! `BOLTZONE_PYTHON` only the Rust-side checks (the same comparison on the library's grids) run.

use super::py::{run, temp_dir};
use boltzone::scene::Scene;
use std::process::Command;

const ALPHA: f64 = 13e-6;
const DT: f64 = 100.0;

fn scene(temperature: bool, field: &str) -> String {
    let t = if temperature {
        format!(
            "[temperature]\nreference = 70.0\nplates = [{}]\nalpha = [{ALPHA:e}]\n",
            70.0 + DT
        )
    } else {
        String::new()
    };
    format!(
        "model = \"single-plate\"\nmethod = \"fem\"\ntolerance = 1e-3\n[hole]\nradius = 0.1\n\
         [load]\nouter_radius = 0.31\npressure = 1000.0\n[[plates]]\nthickness = 0.1\n\
         material = {{ E = 1e7, nu = 0.3 }}\n[joint]\nouter_radius = 1.54\n[outputs]\n\
         field = \"{field}\"\n{t}"
    )
}

/// The free body's displacement difference and stress difference of two grids of the same mesh:
/// (max |Δu − α ΔT x|, max |Δσ| / max |σ|).
fn differences(
    points: &[[f64; 2]],
    cold: (&[[f64; 2]], &[Vec<f64>]),
    hot: (&[[f64; 2]], &[Vec<f64>]),
) -> (f64, f64) {
    let mut du = 0.0f64;
    for ((x, a), b) in points.iter().zip(cold.0).zip(hot.0) {
        for c in 0..2 {
            du = du.max((b[c] - a[c] - ALPHA * DT * x[c]).abs());
        }
    }
    let smax = cold.1.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let ds = cold
        .1
        .iter()
        .flatten()
        .zip(hot.1.iter().flatten())
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    (du, ds / smax)
}

/// Bounds: the displacement difference is round-off of two solves relative to the free
/// expansion α ΔT C = 2e-3 (tests/fem/single_thermal.rs: < 1e-10 of it on a level mesh); the
/// stress difference is the thermal solve's round-off, E α ΔT/(1 − ν) ≈ 19 000 against the
/// bolt-load stresses' largest ≈ 1 600: 1e-9 of the thermal scale is 1.2e-8 of max |σ|.
const DU: f64 = 1e-10 * ALPHA * DT * 1.54;
const DS: f64 = 1.2e-8;

const STRESSES: [&str; 4] = ["sigma_r", "sigma_z", "sigma_theta", "tau_rz"];

#[test]
fn uniform_temperature_adds_the_free_expansion_and_no_stress() {
    // the library's grids (scene units = in, psi)
    let grid = |t| {
        boltzone::solve(&Scene::parse(&scene(t, "f.vtu")).unwrap())
            .unwrap()
            .field
            .unwrap()
    };
    let (cold, hot) = (grid(false), grid(true));
    assert_eq!(cold.points.len(), hot.points.len());
    let stresses = |g: &boltzone::io::vtu::Grid| -> Vec<Vec<f64>> {
        STRESSES
            .iter()
            .map(|n| g.scalars.iter().find(|s| s.0 == *n).unwrap().1.clone())
            .collect()
    };
    let (du, ds) = differences(
        &hot.points,
        (&cold.displacement, &stresses(&cold)),
        (&hot.displacement, &stresses(&hot)),
    );
    println!("library grids: |Δu − α ΔT x| ≤ {du:e} in, |Δσ|/max|σ| ≤ {ds:e}");
    assert!(du < DU && ds < DS, "{du:e}, {ds:e}");
    let t = &hot.scalars.iter().find(|s| s.0 == "temperature").unwrap().1;
    assert!(t.iter().all(|&v| v == 70.0 + DT));

    // the files written by `boltzone solve`, read by meshio
    let dir = temp_dir("thermal_vtu");
    for (name, t) in [("cold", false), ("hot", true)] {
        let toml = dir.join(format!("{name}.toml"));
        std::fs::write(&toml, scene(t, &format!("{name}.vtu"))).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_boltzone"))
            .args(["solve", toml.to_str().unwrap()])
            .current_dir(&dir)
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let vtu = std::fs::read_to_string(dir.join("hot.vtu")).unwrap();
    assert!(
        vtu.contains("temperature in the degrees of [temperature]"),
        "unit note"
    );
    let script = format!(
        r#"
import sys, json, meshio, numpy as np
a, b = meshio.read(sys.argv[1]), meshio.read(sys.argv[2])
names = {STRESSES:?}
smax = max(np.abs(a.point_data[n]).max() for n in names)
ds = max(np.abs(b.point_data[n] - a.point_data[n]).max() for n in names) / smax
du = b.point_data["displacement"][:, :2] - a.point_data["displacement"][:, :2]
du = np.abs(du - {k:e} * b.points[:, :2]).max()
t = b.point_data["temperature"]
print(json.dumps({{"ds": ds, "du": du, "tmin": float(t.min()), "tmax": float(t.max()),
                  "dx": float(np.abs(a.points - b.points).max()), "n": len(b.points)}}))
"#,
        k = ALPHA * DT
    );
    let Some(v) = run(&script, &[&dir.join("cold.vtu"), &dir.join("hot.vtu")]) else {
        return;
    };
    let f = |k: &str| v[k].as_f64().unwrap();
    println!("meshio: {v}");
    // the two studies grade their meshes at their own R_o, equal to rounding (measured 3e-14 in)
    assert!(f("dx") < 1e-12 * 1.54, "{v}");
    assert!(f("du") < DU && f("ds") < DS, "{v}");
    assert_eq!((f("tmin"), f("tmax")), (70.0 + DT, 70.0 + DT));
}
