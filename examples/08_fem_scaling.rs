//! Cost of the FE pipeline against problem size: mesh, sparsity pattern, assembly, sparse
//! Cholesky (symbolic + numeric) and one solve, for Q4 and Q9 meshes of a square section
//! r ∈ [0.1, 1.1], z ∈ [0, 1] (roller at z = 0, face pressure on top), at about 10⁴, 10⁵ and
//! 10⁶ equations; peak resident memory (VmHWM) after each size, the fitted scaling exponent
//! of the total time, and the relative residual ‖K x − b‖/‖b‖ as a check of the solve.
//!
//! Run: `cargo run --release --example 08_fem_scaling [dofs…]` (default 1e4 1e5 1e6). For the
//! peak memory of one size alone, run that size by itself. Environment: FEM_ORDER=amd uses faer's
//! AMD instead of the mesh's nested dissection; FEM_THICKNESS=0.1 a plate-shaped section;
//! FEM_PARALLEL=1 faer's threads; FEM_ELEMENT=q4 or q9 only one element kind.
//! `BOLTZONE_QUICK=1` runs 2·10³ and 8·10³ equations (the test suite does).
//!
//! Self-check (exit code 1): every relative residual, computed with the assembled matrix
//! independently of the factorization, is below 1e-10.
//!
//! Builds on: example 02 (the pipeline it times).

use boltzone::fem::*;
use boltzone::{FaceLoad, Material};
use std::time::Instant;

fn vm_hwm_mib() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines().find(|l| l.starts_with("VmHWM")).and_then(|l| {
                l.split_whitespace()
                    .nth(1)
                    .and_then(|v| v.parse::<f64>().ok())
            })
        })
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

/// Builds and solves one problem with about `dofs` equations; returns (equations, seconds).
/// `thickness` is the z extent of the section (r always spans 0.1..1.1); elements are square.
pub fn run_size(
    kind: ElementKind,
    dofs: usize,
    thickness: f64,
    par: bool,
) -> anyhow::Result<(usize, f64)> {
    let t = Instant::now();
    let nz_nodes = ((dofs as f64 / 2.0 * thickness).sqrt()).round().max(2.0);
    let nr_nodes = (nz_nodes / thickness).round();
    let nz = ((nz_nodes as usize - 1) / kind.order()).max(1);
    let nr = ((nr_nodes as usize - 1) / kind.order()).max(1);
    let r = Spacing::uniform(0.1, 1.1, nr)?;
    let z = Spacing::uniform(0.0, thickness, nz)?;
    let mesh = Mesh::structured(kind, &r, &[PlateSpec { z, material: 0 }])?;
    let mut s = Supports::new(mesh.n_nodes());
    for node in mesh.bottom(0) {
        s.roller_z(node);
    }
    let mut loads = Loads::new(mesh.n_nodes());
    loads.add_face_pressure(&mesh, &mesh.top(0), 1.0, &FaceLoad::uniform(0.1, 0.5, 1.0)?)?;
    let dm = DofMap::new(&s);
    let t_mesh = t.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let pattern = Pattern::new(&mesh, &dm);
    let t_pattern = t1.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let k = assemble(&mesh, &[Material::unit(0.3)?], &dm, &pattern)?;
    let t_assemble = t1.elapsed().as_secs_f64();
    let nd = !std::env::var("FEM_ORDER").is_ok_and(|v| v == "amd");
    let order = nd.then(|| nested_dissection(&mesh, &dm));
    let f =
        Factorization::with_ordering(&k.matrix, order.as_deref(), &SolveParams { parallel: par })?;
    let b = dm.gather(loads.forces());
    let t1 = Instant::now();
    let x = f.solve(&b);
    let t_solve = t1.elapsed().as_secs_f64();
    let total = t.elapsed().as_secs_f64();
    // residual with the symmetric matrix stored as its lower triangle
    let mut kx = vec![0.0; x.len()];
    let m = k.matrix.as_ref();
    for j in 0..m.ncols() {
        for (i, v) in m.row_idx_of_col(j).zip(m.val_of_col(j)) {
            kx[i] += v * x[j];
            if i != j {
                kx[j] += v * x[i];
            }
        }
    }
    let res = kx
        .iter()
        .zip(&b)
        .map(|(a, c)| (a - c).powi(2))
        .sum::<f64>()
        .sqrt()
        / b.iter().map(|c| c * c).sum::<f64>().sqrt();
    if res.is_nan() || res >= 1e-10 {
        anyhow::bail!(
            "{kind:?}, {} equations: relative residual {res:e} > 1e-10",
            dm.n_equations()
        );
    }
    let [sym, num] = f.seconds();
    println!(
        "{:>6} {:>5} {:>9} {:>10} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>8.3} {:>9.1} {:>9.1e}",
        format!("{kind:?}"),
        thickness,
        dm.n_equations(),
        f.factor_entries(),
        t_mesh,
        t_pattern,
        t_assemble,
        sym,
        num,
        t_solve,
        total,
        vm_hwm_mib(),
        res
    );
    Ok((dm.n_equations(), total))
}

pub fn main() -> anyhow::Result<()> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    // env FEM_THICKNESS (default 1: a square section; 0.1: a plate 10 times wider than thick)
    // and FEM_PARALLEL=1 (faer on all threads)
    let thickness: f64 = std::env::var("FEM_THICKNESS")
        .ok()
        .map(|s| s.parse())
        .transpose()?
        .unwrap_or(1.0);
    let par = std::env::var("FEM_PARALLEL").is_ok_and(|v| v == "1");
    let sizes: Vec<usize> = {
        let a: Vec<usize> = if quick {
            vec![2_000, 8_000]
        } else {
            std::env::args()
                .skip(1)
                .map(|s| s.parse::<f64>().map(|v| v as usize))
                .collect::<Result<_, _>>()?
        };
        if a.is_empty() {
            vec![10_000, 100_000, 1_000_000]
        } else {
            a
        }
    };
    println!(
        "{:>6} {:>5} {:>9} {:>10} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>8} {:>9} {:>9}",
        "elem",
        "t",
        "dofs",
        "nnz(L)",
        "mesh",
        "pattern",
        "assem",
        "symb",
        "numeric",
        "solve",
        "total s",
        "peak MiB",
        "residual"
    );
    let only = std::env::var("FEM_ELEMENT").ok();
    for kind in [ElementKind::Q4, ElementKind::Q9] {
        if only
            .as_ref()
            .is_some_and(|k| !k.eq_ignore_ascii_case(&format!("{kind:?}")))
        {
            continue;
        }
        let runs: Vec<(usize, f64)> = sizes
            .iter()
            .map(|&d| run_size(kind, d, thickness, par))
            .collect::<Result<_, _>>()?;
        if runs.len() >= 2 {
            let (a, b) = (runs[0], runs[runs.len() - 1]);
            let p =
                boltzone::numerics::convergence::order_between(b.0 as f64, b.1, a.0 as f64, a.1);
            println!(
                "{kind:?}: total time ∝ dofs^{p:.2} between {} and {} dofs",
                a.0, b.0
            );
        }
    }
    Ok(())
}
