//! How a free rim r = C moves the two plates' R_o, measured: the law a two-plate rim bound or
//! correction for the tables (`docs/tables.md`) would rest on.
//!
//! **Physics.** Beyond R_o the infinite plates carry log bending, M_r ∝ 1/r²; freeing the rim
//! adds the uniform bending that cancels M_r(C) (`hankel::receding::rim`), so the shift
//! δ = R_o(∞) − R_o(C) falls like 1/C², not exponentially. To the first order in that bending,
//! with the moments' own 1/C² corrections, δ = κD³/(C² − μD²) with κ, μ functions of A/D,
//! (B − A)/D and ν alone.
//!
//! **Method.** For N random equal plates (log-uniform A/D in [0.25, 4] and w = (B − A)/D in
//! [0.15, 5] with B ≤ 8D, the holed rim route's reach; uniform ν in [0, 0.5)), R_o(∞) and
//! R_o(C) at C = R_o(∞) + u·D, u = 4, 6, 9, 14, 22, 40, by the holed route
//! ([`two_plate_hole_to`]) at TOL (default 1e-8), D = 1; κ and μ from the two widest rims; the
//! law's residual at the others, relative to δ and to R_o.
//!
//! Run (the quick run in CI takes two `check` points and one geometry of the study at 1e-6):
//! - `cargo run --release --example 31_two_plate_rim_law N SEED [TOL] [OUT.csv]`: the study,
//!   about 15 s per geometry on one core;
//! - `… build PANEL PART PARTS OUT.csv` solves the rim table's nodes of panel PANEL (0, 1) with
//!   index ≡ PART (mod PARTS) (appending, resuming), `… table 2 P0a.csv P0b.csv P1a.csv
//!   P1b.csv` writes `src/table/data/near_rim.json` from them (files per panel, then the files);
//! - `… check N SEED` holds the shipped tables' rimmed answers against N fresh rimmed solves.
//!
//! What it found: `docs/tables.md` (measured).

use boltzone::hankel::receding::holed::two_plate_hole_to;
use boltzone::numerics::random::SplitMix64;
use boltzone::table::near::{A_MAX, A_MIN, W_MAX, W_MIN};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
use std::io::Write;
use std::time::Instant;

/// The rims' distances beyond R_o(∞), in D (the last two fit the law).
const U: [f64; 6] = [4.0, 6.0, 9.0, 14.0, 22.0, 40.0];

/// R_o and its estimate of two equal plates D = 1 with hole `a`, uniform pressure to `b`, rim
/// `c`, by the holed route at `tol`.
fn r_o(
    a: f64,
    b: f64,
    nu: f64,
    c: OuterRadius,
    tol: f64,
) -> Result<(f64, f64), Box<dyn std::error::Error>> {
    let load = FaceLoad::uniform(a, b, 1.0)?;
    let p = SinglePlate::new(a, c, 1.0, Material::unit(nu)?, load)?;
    let (h, _) = two_plate_hole_to(&p, tol, &[])?;
    Ok((h.r_o, h.info.r_o_error))
}

/// κ and μ of δ = κ/(C² − μ) through (c1, δ1) and (c2, δ2).
fn law(c1: f64, d1: f64, c2: f64, d2: f64) -> (f64, f64) {
    // δ1 (c1² − μ) = δ2 (c2² − μ)
    let mu = (d1 * c1 * c1 - d2 * c2 * c2) / (d1 - d2);
    (d1 * (c1 * c1 - mu), mu)
}

/// The rim table's panels in w = (B − A)/D: (w_lo, w_hi, ln-mapped, points per axis
/// (ln A/D, w, ν)), A/D ∈ [0.25, 4], ν ∈ [0, 0.5], B ≤ 8D (the holed rim route's reach).
pub const PANELS: [(f64, f64, bool, [usize; 3]); 2] =
    [(0.15, 1.2, true, [7, 7, 4]), (1.2, 4.0, false, [7, 7, 4])];

fn nodes(panel: usize) -> Vec<[f64; 3]> {
    let (lo, hi, log_w, n) = PANELS[panel];
    boltzone::table::near::Panel::nodes(lo, hi, log_w, n)
}

/// κ, μ and their errors (from the solves' estimates, each shift moved by its own) at one
/// geometry; also R_o(∞) and the seconds taken.
fn sample(a: f64, w: f64, nu: f64, tol: f64) -> Result<[f64; 6], Box<dyn std::error::Error>> {
    let t = Instant::now();
    let (inf, e_inf) = r_o(a, a + w, nu, OuterRadius::Infinite, tol)?;
    let [u1, u2] = [U[U.len() - 2], U[U.len() - 1]];
    let (c1, c2) = (inf + u1, inf + u2);
    let (r1, e1) = r_o(a, a + w, nu, OuterRadius::Finite(c1), tol)?;
    let (r2, e2) = r_o(a, a + w, nu, OuterRadius::Finite(c2), tol)?;
    let (d1, d2) = (inf - r1, inf - r2);
    let (kappa, mu) = law(c1, d1, c2, d2);
    let (k1, m1) = law(c1, d1 + e1 + e_inf, c2, d2);
    let (k2, m2) = law(c1, d1, c2, d2 + e2 + e_inf);
    let e_kappa = (k1 - kappa).abs() + (k2 - kappa).abs();
    let e_mu = (m1 - mu).abs() + (m2 - mu).abs();
    Ok([inf, kappa, mu, e_kappa, e_mu, t.elapsed().as_secs_f64()])
}

/// Solves panel `panel`'s nodes k ≡ `part` (mod `parts`) into `path` (index, a, w, ν, R_o(∞), κ, μ,
/// their errors, seconds), appending and skipping those already there.
fn build(
    panel: usize,
    part: usize,
    parts: usize,
    path: &str,
    tol: f64,
) -> Result<(), Box<dyn std::error::Error>> {
    let done: Vec<usize> = std::fs::read_to_string(path)
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.split(',').next()?.parse().ok())
        .collect();
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?;
    let nodes = self::nodes(panel);
    for (k, p) in nodes.iter().enumerate() {
        if k % parts != part || done.contains(&k) {
            continue;
        }
        let [inf, kappa, mu, ek, em, secs] = sample(p[0], p[1], p[2], tol)?;
        writeln!(
            f,
            "{k},{:e},{:e},{:e},{inf:e},{kappa:e},{mu:e},{ek:e},{em:e},{secs:.2}",
            p[0], p[1], p[2]
        )?;
        f.flush()?;
        println!("{k}/{}: a {:.3} w {:.3} ν {:.3}: κ {kappa:.6} ± {ek:.1e}, μ {mu:.4} ± {em:.1e} ({secs:.1} s)", nodes.len(), p[0], p[1], p[2]);
    }
    Ok(())
}

/// Panel `panel` of κ and of μ from its build files.
fn panel_of(
    panel: usize,
    paths: &[String],
) -> Result<
    (
        boltzone::table::near::Panel,
        boltzone::table::near::Panel,
        f64,
    ),
    Box<dyn std::error::Error>,
> {
    let mut rows: Vec<Vec<f64>> = paths
        .iter()
        .flat_map(|p| {
            std::fs::read_to_string(p)
                .unwrap_or_default()
                .lines()
                .map(|l| {
                    l.split(',')
                        .map(|x| x.parse().unwrap_or(f64::NAN))
                        .collect::<Vec<f64>>()
                })
                .collect::<Vec<_>>()
        })
        .collect();
    rows.sort_by(|x, y| x[0].total_cmp(&y[0]));
    rows.dedup_by(|x, y| x[0] == y[0]);
    let (lo, hi, log_w, n) = PANELS[panel];
    let count: usize = n.iter().product();
    if rows.len() != count || rows.iter().enumerate().any(|(k, r)| r[0] != k as f64) {
        return Err(format!("panel {panel}: {} of {count} nodes solved", rows.len()).into());
    }
    let col = |i: usize| rows.iter().map(|r| r[i]).collect::<Vec<f64>>();
    let secs: f64 = col(9).iter().sum();
    let from = boltzone::table::near::Panel::from_samples;
    Ok((
        from(lo, hi, log_w, n, &col(5), &col(7)),
        from(lo, hi, log_w, n, &col(6), &col(8)),
        secs,
    ))
}

/// Writes `src/table/data/near_rim.json` from the build files, `files` per panel in order.
fn table(paths: &[String], files: usize) -> Result<(), Box<dyn std::error::Error>> {
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:e}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let json = |p: &boltzone::table::near::Panel| {
        format!(
            "{{ \"w_lo\": {:e}, \"w_hi\": {:e}, \"log_w\": {}, \"n\": [{}, {}, {}], \"errors\": [{}], \"coefficients\": [{}] }}",
            p.w_lo, p.w_hi, p.log_w, p.n[0], p.n[1], p.n[2], list(&p.errors), list(&p.coefficients)
        )
    };
    let (mut kappa, mut mu, mut secs) = (Vec::new(), Vec::new(), 0.0);
    for k in 0..PANELS.len() {
        let (pk, pm, s) = panel_of(k, &paths[k * files..(k + 1) * files])?;
        for (name, p) in [("kappa", &pk), ("mu", &pm)] {
            for axis in 0..3 {
                let m = p.axis_magnitudes(axis);
                println!(
                    "panel {k} {name} axis {axis}: {}",
                    m.iter()
                        .map(|x| format!("{x:.1e}"))
                        .collect::<Vec<_>>()
                        .join(" ")
                );
            }
            println!("panel {k} {name}: tails {:?}", p.tails());
        }
        kappa.push(json(&pk));
        mu.push(json(&pm));
        secs += s;
    }
    let nodes: usize = PANELS.iter().map(|p| p.3.iter().product::<usize>()).sum();
    let commit = std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .output()
        .map_or("unknown".into(), |o| {
            String::from_utf8_lossy(&o.stdout).trim().to_string()
        });
    let out = format!(
        "{{\n  \"provenance\": \"examples/31_two_plate_rim_law.rs: {nodes} nodes in {} panels, each R_o(inf) and R_o(C) at C = R_o(inf) + 22 D and + 40 D by boltzone::hankel::receding::holed::two_plate_hole_to at 1e-8, D = 1, kappa and mu of R_o(inf) - R_o(C) = kappa D^3/(C^2 - mu D^2) through the two; {secs:.0} s of solves; built at commit {commit}\",\n  \"kappa\": [{}],\n  \"mu\": [{}]\n}}\n",
        PANELS.len(),
        kappa.join(", "),
        mu.join(", ")
    );
    let path = std::path::Path::new("src/table/data/near_rim.json");
    boltzone::fsutil::write_atomic(path, out.as_bytes())?;
    println!("wrote {} ({} bytes)", path.display(), out.len());
    Ok(())
}

/// The shipped tables' rimmed R_o (the near or far table's R_o(∞) less the rim table's shift)
/// against the holed route with the rim at 1e-8 on `n` random plates (A/D, w ≤ 4, ν as the
/// study, C = R_o + u·D with u log-uniform in [4, 40]): the distribution of
/// |table − route| / (bar + the route's estimate), and where the bar met 1e-3 and 1e-5 of R_o.
fn check(n: usize, seed: u64) -> Result<(), Box<dyn std::error::Error>> {
    use boltzone::table::{lookup, rim, Model};
    let mut rng = SplitMix64::new(seed);
    let (mut ratios, mut met3, mut met5) = (Vec::new(), 0, 0);
    let t = Instant::now();
    for _ in 0..n {
        let a = rng.log_uniform(A_MIN, A_MAX);
        let w = rng.log_uniform(W_MIN, rim::W_MAX_TWO);
        let nu = 0.5 * rng.unit();
        let u = rng.log_uniform(rim::U_MIN, 40.0);
        let inf = lookup::separation_radius(Model::TwoPlates, a, a + w, 1.0, nu, 1.0)?;
        let c = inf.value + u;
        let shift = rim::two_plates_rim_shift(a, a + w, 1.0, nu, c, inf.value)?;
        let (value, bar) = (inf.value - shift.value, inf.error + shift.error);
        let (r, e) = r_o(a, a + w, nu, OuterRadius::Finite(c), 1e-8)?;
        let q = (value - r).abs() / (bar + e);
        println!(
            "A/D {a:.3} w {w:.3} ν {nu:.3} u {u:5.2}: table {value:.9} ± {bar:.1e} (shift {:.3e} ± {:.1e}), route {r:.9} ± {e:.1e}: ratio {q:.3}",
            shift.value, shift.error
        );
        met3 += usize::from(bar <= 1e-3 * value);
        met5 += usize::from(bar <= 1e-5 * value);
        ratios.push(q);
    }
    ratios.sort_by(f64::total_cmp);
    let at = |f: f64| ratios[((ratios.len() - 1) as f64 * f).round() as usize];
    println!(
        "{n} rimmed plates in {:.0} s: |table − route| / (bar + estimate) median {:.3}, 90 % {:.3}, max {:.3}; the bar met 1e-3 of R_o on {met3}, 1e-5 on {met5}",
        t.elapsed().as_secs_f64(),
        at(0.5),
        at(0.9),
        at(1.0)
    );
    if at(1.0) > 1.0 {
        return Err("a rimmed two-plate table answer is outside its bar".into());
    }
    Ok(())
}

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    let quick = std::env::var("BOLTZONE_QUICK").is_ok_and(|v| v == "1");
    let args: Vec<String> = std::env::args().collect();
    match args.get(1).map(String::as_str) {
        Some("build") if !quick => {
            let arg = |k: usize| args.get(k).ok_or("usage: build PANEL PART PARTS OUT.csv");
            return build(
                arg(2)?.parse()?,
                arg(3)?.parse()?,
                arg(4)?.parse()?,
                arg(5)?,
                1e-8,
            );
        }
        Some("check") if !quick => {
            let arg = |k: usize| args.get(k).ok_or("usage: check N SEED");
            return check(arg(2)?.parse()?, arg(3)?.parse()?);
        }
        Some("table") if !quick => {
            // FILES_PER_PANEL then the files, panel by panel
            let files: usize = args
                .get(2)
                .ok_or("usage: table FILES_PER_PANEL F…")?
                .parse()?;
            return table(&args[3..], files);
        }
        _ => {}
    }
    if quick {
        check(2, 31)?;
    }
    let (n, seed, tol, out) = match quick {
        true => (1, 31, 1e-6, None),
        false => (
            args.get(1)
                .ok_or("usage: 31_two_plate_rim_law N SEED [TOL] [OUT.csv]")?
                .parse()?,
            args.get(2).ok_or("SEED")?.parse()?,
            args.get(3).map_or(Ok(1e-8), |t| t.parse())?,
            args.get(4).cloned(),
        ),
    };
    let mut csv = match &out {
        Some(path) => {
            let mut f = std::fs::File::create(path)?;
            write!(f, "a,w,nu,r_o_inf,kappa,mu")?;
            for u in &U[..U.len() - 2] {
                write!(f, ",residual_u{u}")?;
            }
            writeln!(f)?;
            Some(f)
        }
        None => None,
    };
    let mut rng = SplitMix64::new(seed);
    let mut worst = vec![0.0f64; U.len() - 2];
    let t = Instant::now();
    println!(
        "A/D     w       ν      R_o(∞)/D     κ        μ/D²   residual/δ at u = {:?} (of R_o)",
        &U[..U.len() - 2]
    );
    for _ in 0..n {
        let a = rng.log_uniform(A_MIN, A_MAX);
        let w = rng.log_uniform(W_MIN, W_MAX.min(8.0 - a));
        let nu = 0.5 * rng.unit();
        let (inf, e_inf) = r_o(a, a + w, nu, OuterRadius::Infinite, tol)?;
        let mut shifts = Vec::new();
        for u in U {
            let c = inf + u;
            let (r, e) = r_o(a, a + w, nu, OuterRadius::Finite(c), tol)?;
            shifts.push((c, inf - r, e + e_inf));
        }
        let [.., (c1, d1, _), (c2, d2, _)] = shifts[..] else {
            unreachable!()
        };
        let (kappa, mu) = law(c1, d1, c2, d2);
        let mut line = format!("{a:.3}  {w:.3}  {nu:.3}  {inf:.8}  {kappa:.5}  {mu:+.3}  ");
        let mut row = format!("{a:e},{w:e},{nu:e},{inf:e},{kappa:e},{mu:e}");
        for (k, &(c, d, e)) in shifts[..U.len() - 2].iter().enumerate() {
            let residual = kappa / (c * c - mu) - d;
            // a residual within the solves' estimates is not resolved: report it as it is
            line += &format!(
                " {:+.1e} ({:.1e}{})",
                residual / d,
                residual.abs() / inf,
                if residual.abs() <= e { "~" } else { "" }
            );
            row += &format!(",{residual:e}");
            worst[k] = worst[k].max(residual.abs() / inf);
        }
        println!("{line}");
        // the law's claim: at u = 14 it holds to 1 % of the shift
        let (c, d, _) = shifts[3];
        if (kappa / (c * c - mu) - d).abs() > 1e-2 * d {
            return Err(format!(
                "A/D {a} w {w} ν {nu}: the 1/(C² − μ) law misses u = 14 by over 1 %"
            )
            .into());
        }
        if let Some(f) = csv.as_mut() {
            writeln!(f, "{row}")?;
        }
    }
    println!(
        "{n} geometries in {:.0} s; largest |residual|/R_o at u = {:?}: {}",
        t.elapsed().as_secs_f64(),
        &U[..U.len() - 2],
        worst
            .iter()
            .map(|w| format!("{w:.1e}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(())
}
